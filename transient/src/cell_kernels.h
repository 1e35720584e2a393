#pragma once
// Small vector kernels of the 3D transient (internal to the transient library), each with an AVX2
// path chosen at run time and a portable one that gives the same bits.

#include <vector>

namespace modaltyre::transient::detail {

/// The 3D observer's belt displacement of one section (patch_ode_3d.cc), radial and tangential,
/// each a modal sum over the state and a residual sum over the patch's forces:
/// out[0] = sum_k a[k] x[k] + c[k] y[k] and out[1] = sum_k b[k] x[k] + d[k] y[k], k < n (y, c
/// and d may be null: the x terms only). Eight partial sums per output (rows k mod 8), added
/// lane-wise as (k mod 4) + (k mod 4 + 4), then (s0 + s1) + (s2 + s3), then the last n % 8 rows
/// in order, every product fused with its addition: the same bits on the AVX2 + FMA path (chosen
/// at run time) and the portable one (std::fma).
void pair_dots(int n, const double* a, const double* b, const double* x, const double* c,
               const double* d, const double* y, double out[2]);

/// One row of CellNewton::factor()'s back substitution along a class's band, and its term of R:
///   y_j = ((a t_j - s1 y1_j) - s2 y2_j) d   (with_t; otherwise ((0 - s1 y1_j) - s2 y2_j) d),
///   r_j += w (t_j - gamma y_j)              (r not null),
/// j < n, in exactly these operations (no fused multiply-add): the AVX path is the scalar
/// expression four entries at a time, so a flat crown's one class keeps the 2D solver's bits.
void band_row(int n, bool with_t, double a, const double* t, const double* y1, const double* y2,
              double s1, double s2, double d, double* y, double* r, double w, double gamma);

/// CellNewton::solve_ee()'s lockstep of eight classes' back substitutions along their bands:
/// for t = t0 .. t1 - 1, for each lane l < 8, y_l[-t] = ((y_l[-t] - s1 y_l[1 - t]) - s2 y_l[2 - t])
/// d_l[-t] (t0 >= 2 or the entries at 1 - t0 and 2 - t0 readable), exactly these operations (no
/// fused multiply-add): the AVX2 path runs the lanes as two vectors with y_l[1 - t], y_l[2 - t]
/// carried in registers, the same bits.
void band_lockstep8(int t0, int t1, double* const* y, const double* const* d, double s1, double s2);

/// LU with partial pivoting of the column-major n x n matrix a into the row-major lu (unit L
/// below the diagonal, U on and above it; CellNewton's and ContactNewton's capacitance matrices,
/// row_lu_factor()): the steps on a's row-major copy are, at step k, the first row i >= k with
/// the largest |a_ik| swapped into row k (rows[k] <-> rows[i]: rows[pos] = the original row at
/// pos), and each row below updated as l = a_ik / a_kk, a_ij = fma(-l, a_kj, a_ij) for j > k.
/// False at a zero or non-finite pivot (lu and rows then partly written). One function per
/// instruction set: the AVX2 path takes each entry's fused multiply-adds in the same order in
/// Crout's arrangement (column k of L and row k of U from the final factors, in registers, and a
/// read through the permutation instead of copied and swapped), the same bits.
bool lu_factor(int n, const double* a, double* lu, int* rows);

/// The Cholesky factor L (lower, column-major, n x n; entries above the diagonal not written) of
/// the symmetric positive definite column-major a (its lower triangle read): column j at rows
/// i >= j is a_ij swept as c = fma(-L_ip, L_jp, c) for p = 0 .. j - 1 in order, then L_jj =
/// sqrt(c_jj) and L_ij = c_ij / L_jj; the same bits on the AVX2 + FMA path (16 rows of a column
/// in registers) and the portable one (std::fma). False at a pivot that is not positive and
/// finite (CellNewton's capacitance matrix at rest, cell_newton_rest.cc).
bool cholesky_factor(int n, const double* a, double* l);
/// For cholesky_factor()'s L, the same bits on both paths (serial chains along the rows):
/// x <- L^-1 x by columns: x_p = x_p / L_pp, then x_i = fma(-L_ip, x_p, x_i) for i > p;
/// x <- L^-T x by rows from the last: x_i = (x_i - d) / L_ii, d = sum_{p > i} L_pi x_p as four
/// partial sums (p - i - 1 mod 4) of fused multiply-adds, added (s0 + s1) + (s2 + s3), then the
/// last terms in order;
void lower_solve(int n, const double* l, double* x);
void lower_transpose_solve(int n, const double* l, double* x);
/// y = A x for the column-major n x n a as y_i = fma(-A_ip, -x_p, y_i) from y_i = 0 over every
/// p < n in order (zeros of a triangular a included), the same bits on both paths (16 rows in
/// registers across the sum on AVX2).
void square_product(int n, const double* a, const double* x, double* y);

/// Appends to `out` every k < n where (a[k] > 0) != (b[k] > 0), in increasing order (the cells
/// whose side of the contact kink differs between the iterate's forces a and the matrix's
/// stiffness b: CellNewton::update_active_set()).
void sign_mismatches(int n, const double* a, const double* b, std::vector<int>& out);

/// C (=, or += with accumulate) A B for small column-major matrices (A: m x k, lda; B: k x n,
/// ldb; C: m x n, ldc): each entry fma(A_i,k-1, B_k-1,j, ... fma(A_i0, B_0j, 0)) over the inner
/// index in order (+ C_ij), as column_product() per column of B (the same bits), register-blocked
/// on the AVX2 + FMA path (12 rows x 4 columns), std::fma on the portable path.
void small_gemm(int m, int n, int k, const double* A, int lda, const double* B, int ldb, double* C,
                int ldc, bool accumulate = false);

/// The first k < n with a[k] > 0 (n if none) and the last (-1 if none): a class's contact ends
/// (the 3D observer).
int first_positive(const double* a, int n);
int last_positive(const double* a, int n);
/// How many a[k] > 0, k < n.
int count_positive(const double* a, int n);
/// lo[k] = min(lo[k], v_lo) and hi[k] = max(hi[k], v_hi), k < n (the 3D observer's outermost
/// columns in contact per section).
void min_max_fill(int* lo, int* hi, int n, int v_lo, int v_hi);

}  // namespace modaltyre::transient::detail

#pragma once
// The 3D transient's passes over a class's slots (one cell per section; cell_system.h) that run
// at every right-hand side, accepted step and output sample (internal to the transient library).
// Each is plain element-wise arithmetic without fused multiply-adds or reordered sums, compiled
// twice: for AVX2 (four doubles a vector, chosen at run time as the other kernels:
// solvers/instruction_set.h) and for the baseline (SSE2, two). Every element takes the same IEEE
// operations in both, so both give the same bits; the rest of the library is compiled for SSE2
// only, where these loops had run at two elements an instruction.

namespace modaltyre::transient::detail {

/// A class's tip penetration and its rigid-road forces (CellSystem::slots()), k < n:
///   g_k = ((P_k - drop) + h_k) - e_k   (h null: no road term; e null: no tread state),
/// and when f is given f_k = kc_k max(0, g_k) (the select before the product) and
/// F_k += mu f_k.
void slot_pass(int n, const double* P, double drop, const double* h, const double* e,
               const double* kc, double mu, double* g, double* f, double* F);

/// The cells whose side of the kink (g_k > 0) differs from in[k] (0 or 1); in[k] takes the new
/// side. Returns the count.
int contact_flips(int n, const double* g, char* in);

/// A class's tread rates c' De/Dt + k' e = f along its sections (CellSystem::rhs(), rolling):
///   d_k = (((f_k ic_k - e_k kk_k) + a0 e_k) + a1 e_k+1) + a2 e_k+2,
/// the upwind terms beyond n left out; at rest (a0 = a1 = a2 = 0 and `at_rest`)
/// d_k = f_k ic_k - e_k kk_k.
void tread_rates(int n, const double* f, const double* ic, const double* kk, const double* e,
                 double a0, double a1, double a2, bool at_rest, double* d);

/// CellNewton::solve()'s gather of the tread rows onto their sections, k < n:
///   s_k += w_k (b_k d_k)   (d given: M_EE diagonal, at rest), else s_k += w_k b_k.
void slot_gather(int n, const double* w, const double* b, const double* d, double* s);

/// CellNewton::solve()'s tread rows from the sections' values, k < n:
///   x_k = (x_k + g_k s_k) d_k   (d given, at rest), else x_k += g_k s_k;
/// and x_k *= d_k alone (slot_scale) for the slots outside the active sections at rest.
void slot_scatter(int n, const double* g, const double* s, const double* d, double* x);
void slot_scale(int n, const double* d, double* x);

}  // namespace modaltyre::transient::detail

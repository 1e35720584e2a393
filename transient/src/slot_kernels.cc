#include "slot_kernels.h"

#include "modaltyre/solvers/instruction_set.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define MODALTYRE_SLOT_KERNELS_AVX2 1
#endif

namespace modaltyre::transient::detail {
namespace {

// The bodies, inlined into the baseline function and into its AVX2 twin, where the compiler
// vectorises the same element-wise operations four doubles at a time (target "avx2" without
// "fma": no multiply-add can be contracted, so the bits stay those of the baseline).

template <bool kRoad, bool kTread, bool kForces>
[[gnu::always_inline]] inline void slot_pass_body(int n, const double* __restrict P, double drop,
                                                  const double* __restrict h,
                                                  const double* __restrict e,
                                                  const double* __restrict kc, double mu,
                                                  double* __restrict g, double* __restrict f,
                                                  double* __restrict F) {
  for (int k = 0; k < n; ++k) {
    double gk = P[k] - drop;
    if constexpr (kRoad) gk = gk + h[k];
    if constexpr (kTread) gk = gk - e[k];
    g[k] = gk;
    if constexpr (kForces) {
      const double fk = kc[k] * (gk > 0 ? gk : 0.0);
      f[k] = fk;
      F[k] += mu * fk;
    }
  }
}

template <bool kForces>
[[gnu::always_inline]] inline void slot_pass_forces(int n, const double* P, double drop,
                                                    const double* h, const double* e,
                                                    const double* kc, double mu, double* g,
                                                    double* f, double* F) {
  if (h && e)
    slot_pass_body<true, true, kForces>(n, P, drop, h, e, kc, mu, g, f, F);
  else if (h)
    slot_pass_body<true, false, kForces>(n, P, drop, h, e, kc, mu, g, f, F);
  else if (e)
    slot_pass_body<false, true, kForces>(n, P, drop, h, e, kc, mu, g, f, F);
  else
    slot_pass_body<false, false, kForces>(n, P, drop, h, e, kc, mu, g, f, F);
}

[[gnu::always_inline]] inline void slot_pass_any(int n, const double* P, double drop,
                                                 const double* h, const double* e, const double* kc,
                                                 double mu, double* g, double* f, double* F) {
  if (f)
    slot_pass_forces<true>(n, P, drop, h, e, kc, mu, g, f, F);
  else
    slot_pass_forces<false>(n, P, drop, h, e, kc, mu, g, f, F);
}

[[gnu::always_inline]] inline int contact_flips_body(int n, const double* __restrict g,
                                                     char* __restrict in) {
  int flips = 0;
  for (int k = 0; k < n; ++k) {
    const int now = g[k] > 0 ? 1 : 0;
    flips += now ^ in[k];
    in[k] = static_cast<char>(now);
  }
  return flips;
}

[[gnu::always_inline]] inline void tread_rates_body(int n, const double* __restrict f,
                                                    const double* __restrict ic,
                                                    const double* __restrict kk,
                                                    const double* __restrict e, double a0,
                                                    double a1, double a2, bool at_rest,
                                                    double* __restrict d) {
  if (at_rest) {
    for (int k = 0; k < n; ++k) d[k] = f[k] * ic[k] - e[k] * kk[k];
    return;
  }
  int k = 0;
  for (; k + 2 < n; ++k)
    d[k] = (((f[k] * ic[k] - e[k] * kk[k]) + a0 * e[k]) + a1 * e[k + 1]) + a2 * e[k + 2];
  for (; k + 1 < n; ++k) d[k] = ((f[k] * ic[k] - e[k] * kk[k]) + a0 * e[k]) + a1 * e[k + 1];
  for (; k < n; ++k) d[k] = (f[k] * ic[k] - e[k] * kk[k]) + a0 * e[k];
}

[[gnu::always_inline]] inline void slot_gather_body(int n, const double* __restrict w,
                                                    const double* __restrict b,
                                                    const double* __restrict d,
                                                    double* __restrict s) {
  if (d) {
    for (int k = 0; k < n; ++k) s[k] += w[k] * (b[k] * d[k]);
  } else {
    for (int k = 0; k < n; ++k) s[k] += w[k] * b[k];
  }
}

[[gnu::always_inline]] inline void slot_scatter_body(int n, const double* __restrict g,
                                                     const double* __restrict s,
                                                     const double* __restrict d,
                                                     double* __restrict x) {
  if (d) {
    for (int k = 0; k < n; ++k) x[k] = (x[k] + g[k] * s[k]) * d[k];
  } else {
    for (int k = 0; k < n; ++k) x[k] += g[k] * s[k];
  }
}

[[gnu::always_inline]] inline void slot_scale_body(int n, const double* __restrict d,
                                                   double* __restrict x) {
  for (int k = 0; k < n; ++k) x[k] *= d[k];
}

#ifdef MODALTYRE_SLOT_KERNELS_AVX2
/// Whether the AVX2 paths run (solvers/instruction_set.h; decided once).
bool avx2() {
  static const bool yes = solvers::instruction_set() == solvers::InstructionSet::avx2_fma;
  return yes;
}

__attribute__((target("avx2"))) void slot_pass_avx2(int n, const double* P, double drop,
                                                    const double* h, const double* e,
                                                    const double* kc, double mu, double* g,
                                                    double* f, double* F) {
  slot_pass_any(n, P, drop, h, e, kc, mu, g, f, F);
}

__attribute__((target("avx2"))) int contact_flips_avx2(int n, const double* g, char* in) {
  return contact_flips_body(n, g, in);
}

__attribute__((target("avx2"))) void tread_rates_avx2(int n, const double* f, const double* ic,
                                                      const double* kk, const double* e, double a0,
                                                      double a1, double a2, bool at_rest,
                                                      double* d) {
  tread_rates_body(n, f, ic, kk, e, a0, a1, a2, at_rest, d);
}

__attribute__((target("avx2"))) void slot_gather_avx2(int n, const double* w, const double* b,
                                                      const double* d, double* s) {
  slot_gather_body(n, w, b, d, s);
}

__attribute__((target("avx2"))) void slot_scatter_avx2(int n, const double* g, const double* s,
                                                       const double* d, double* x) {
  slot_scatter_body(n, g, s, d, x);
}

__attribute__((target("avx2"))) void slot_scale_avx2(int n, const double* d, double* x) {
  slot_scale_body(n, d, x);
}
#endif

}  // namespace

void slot_pass(int n, const double* P, double drop, const double* h, const double* e,
               const double* kc, double mu, double* g, double* f, double* F) {
#ifdef MODALTYRE_SLOT_KERNELS_AVX2
  if (avx2()) return slot_pass_avx2(n, P, drop, h, e, kc, mu, g, f, F);
#endif
  slot_pass_any(n, P, drop, h, e, kc, mu, g, f, F);
}

int contact_flips(int n, const double* g, char* in) {
#ifdef MODALTYRE_SLOT_KERNELS_AVX2
  if (avx2()) return contact_flips_avx2(n, g, in);
#endif
  return contact_flips_body(n, g, in);
}

void tread_rates(int n, const double* f, const double* ic, const double* kk, const double* e,
                 double a0, double a1, double a2, bool at_rest, double* d) {
#ifdef MODALTYRE_SLOT_KERNELS_AVX2
  if (avx2()) return tread_rates_avx2(n, f, ic, kk, e, a0, a1, a2, at_rest, d);
#endif
  tread_rates_body(n, f, ic, kk, e, a0, a1, a2, at_rest, d);
}

void slot_gather(int n, const double* w, const double* b, const double* d, double* s) {
#ifdef MODALTYRE_SLOT_KERNELS_AVX2
  if (avx2()) return slot_gather_avx2(n, w, b, d, s);
#endif
  slot_gather_body(n, w, b, d, s);
}

void slot_scatter(int n, const double* g, const double* s, const double* d, double* x) {
#ifdef MODALTYRE_SLOT_KERNELS_AVX2
  if (avx2()) return slot_scatter_avx2(n, g, s, d, x);
#endif
  slot_scatter_body(n, g, s, d, x);
}

void slot_scale(int n, const double* d, double* x) {
#ifdef MODALTYRE_SLOT_KERNELS_AVX2
  if (avx2()) return slot_scale_avx2(n, d, x);
#endif
  slot_scale_body(n, d, x);
}

}  // namespace modaltyre::transient::detail

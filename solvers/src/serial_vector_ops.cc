#include "serial_vector_ops.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/solvers/instruction_set.h"

namespace modaltyre::solvers {
namespace {

using Index = sunindextype;

// Each loop is an always-inlined body compiled twice (MODALTYRE_VECTOR_CLONES below): an AVX2
// clone and the baseline's (SSE2), picked once by instruction_set() (MODALTYRE_ISA). AVX2 without
// FMA: every element sees the same operations in the same order (no contraction; the norms' four
// partial sums are the four lanes), so both clones give the same bits, on 4 doubles per
// instruction instead of SSE2's 2 (callgrind: linear_sum ~1 570 instructions for 343 entries,
// CVODE's vector operations ~16 % of a free vibration).
#define MODALTYRE_BODY [[gnu::always_inline]] inline

inline double* data(N_Vector v) { return NV_DATA_S(v); }
inline Index length(N_Vector v) { return NV_LENGTH_S(v); }

MODALTYRE_BODY void linear_sum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  const double *xp = data(x), *yp = data(y);
  double* zp = data(z);
  const Index n = length(z);
  // Many of CVODE's sums (the predictor's q(q+1)/2 passes, Newton's corrections) have
  // a = 1 and b = +-1: 1 x = x and -1 y = -y exactly, so x + y and x - y are the general
  // loop's bits without its two multiplications per element.
  if (a == 1.0 && b == 1.0) {
    for (Index i = 0; i < n; ++i) zp[i] = xp[i] + yp[i];
  } else if (a == 1.0 && b == -1.0) {
    for (Index i = 0; i < n; ++i) zp[i] = xp[i] - yp[i];
  } else {
    for (Index i = 0; i < n; ++i) zp[i] = a * xp[i] + b * yp[i];
  }
}

MODALTYRE_BODY void constant(realtype c, N_Vector z) { std::fill_n(data(z), length(z), c); }

MODALTYRE_BODY void prod(N_Vector x, N_Vector y, N_Vector z) {
  const double *xp = data(x), *yp = data(y);
  double* zp = data(z);
  for (Index i = 0, n = length(z); i < n; ++i) zp[i] = xp[i] * yp[i];
}

MODALTYRE_BODY void divide(N_Vector x, N_Vector y, N_Vector z) {
  const double *xp = data(x), *yp = data(y);
  double* zp = data(z);
  for (Index i = 0, n = length(z); i < n; ++i) zp[i] = xp[i] / yp[i];
}

MODALTYRE_BODY void scale(realtype c, N_Vector x, N_Vector z) {
  const double* xp = data(x);
  double* zp = data(z);
  if (c == 1.0 && xp == zp) return;  // an array onto itself (cvode_klu.cc's solve in place)
  for (Index i = 0, n = length(z); i < n; ++i) zp[i] = c * xp[i];
}

MODALTYRE_BODY void absolute(N_Vector x, N_Vector z) {
  const double* xp = data(x);
  double* zp = data(z);
  for (Index i = 0, n = length(z); i < n; ++i) zp[i] = std::abs(xp[i]);
}

MODALTYRE_BODY void inverse(N_Vector x, N_Vector z) {
  const double* xp = data(x);
  double* zp = data(z);
  for (Index i = 0, n = length(z); i < n; ++i) zp[i] = 1.0 / xp[i];
}

MODALTYRE_BODY void add_constant(N_Vector x, realtype b, N_Vector z) {
  const double* xp = data(x);
  double* zp = data(z);
  for (Index i = 0, n = length(z); i < n; ++i) zp[i] = xp[i] + b;
}

MODALTYRE_BODY realtype weighted_square_sum(N_Vector x, N_Vector w) {
  const double *xp = data(x), *wp = data(w);
  const Index n = length(x);
  double s[4] = {0, 0, 0, 0};
  Index i = 0;
  for (; i + 4 <= n; i += 4)
    for (int k = 0; k < 4; ++k) {
      const double v = xp[i + k] * wp[i + k];
      s[k] += v * v;
    }
  for (; i < n; ++i) s[0] += (xp[i] * wp[i]) * (xp[i] * wp[i]);
  return (s[0] + s[1]) + (s[2] + s[3]);
}

MODALTYRE_BODY realtype wrms_norm(N_Vector x, N_Vector w) {
  return std::sqrt(weighted_square_sum(x, w) / static_cast<double>(length(x)));
}

MODALTYRE_BODY realtype max_norm(N_Vector x) {
  const double* xp = data(x);
  double m = 0;
  for (Index i = 0, n = length(x); i < n; ++i) m = std::max(m, std::abs(xp[i]));
  return m;
}

MODALTYRE_BODY int linear_combination(int nv, realtype* c, N_Vector* X, N_Vector z) {
  double* zp = data(z);
  const Index n = length(z);
  // z may be X[0] (z = c0 z + sum c_k X_k): accumulate in place from the first term.
  const double* x0 = data(X[0]);
  for (Index i = 0; i < n; ++i) zp[i] = c[0] * x0[i];
  for (int k = 1; k < nv; ++k) {
    const double* xk = data(X[k]);
    const double ck = c[k];
    for (Index i = 0; i < n; ++i) zp[i] += ck * xk[i];
  }
  return 0;
}

MODALTYRE_BODY int scale_add_multi(int nv, realtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  const double* xp = data(x);
  const Index n = length(x);
  for (int k = 0; k < nv; ++k) {
    const double* yp = data(Y[k]);
    double* zp = data(Z[k]);
    const double ak = a[k];
    for (Index i = 0; i < n; ++i) zp[i] = ak * xp[i] + yp[i];
  }
  return 0;
}

// Per loop an AVX2 clone and a portable one, `name##_avx2` and `name##_portable`, whose
// arguments are forwarded to the body.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define MODALTYRE_AVX2_CLONE(ret, name, params, args) \
  __attribute__((target("avx2"))) ret name##_avx2 params { return name args; }
#else
#define MODALTYRE_AVX2_CLONE(ret, name, params, args) \
  ret name##_avx2 params { return name args; }
#endif
#define MODALTYRE_VECTOR_CLONES(ret, name, params, args) \
  MODALTYRE_AVX2_CLONE(ret, name, params, args)          \
  ret name##_portable params { return name args; }

MODALTYRE_VECTOR_CLONES(void, linear_sum,
                        (realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z),
                        (a, x, b, y, z))
MODALTYRE_VECTOR_CLONES(void, constant, (realtype c, N_Vector z), (c, z))
MODALTYRE_VECTOR_CLONES(void, prod, (N_Vector x, N_Vector y, N_Vector z), (x, y, z))
MODALTYRE_VECTOR_CLONES(void, divide, (N_Vector x, N_Vector y, N_Vector z), (x, y, z))
MODALTYRE_VECTOR_CLONES(void, scale, (realtype c, N_Vector x, N_Vector z), (c, x, z))
MODALTYRE_VECTOR_CLONES(void, absolute, (N_Vector x, N_Vector z), (x, z))
MODALTYRE_VECTOR_CLONES(void, inverse, (N_Vector x, N_Vector z), (x, z))
MODALTYRE_VECTOR_CLONES(void, add_constant, (N_Vector x, realtype b, N_Vector z), (x, b, z))
MODALTYRE_VECTOR_CLONES(realtype, weighted_square_sum, (N_Vector x, N_Vector w), (x, w))
MODALTYRE_VECTOR_CLONES(realtype, wrms_norm, (N_Vector x, N_Vector w), (x, w))
MODALTYRE_VECTOR_CLONES(realtype, max_norm, (N_Vector x), (x))
MODALTYRE_VECTOR_CLONES(int, linear_combination, (int nv, realtype* c, N_Vector* X, N_Vector z),
                        (nv, c, X, z))
MODALTYRE_VECTOR_CLONES(int, scale_add_multi,
                        (int nv, realtype* a, N_Vector x, N_Vector* Y, N_Vector* Z),
                        (nv, a, x, Y, Z))

}  // namespace

void install_serial_vector_ops(N_Vector v) {
  N_Vector_Ops ops = v->ops;
#define MODALTYRE_PICK(name) \
  (instruction_set() == InstructionSet::avx2_fma ? name##_avx2 : name##_portable)
  ops->nvlinearsum = MODALTYRE_PICK(linear_sum);
  ops->nvconst = MODALTYRE_PICK(constant);
  ops->nvprod = MODALTYRE_PICK(prod);
  ops->nvdiv = MODALTYRE_PICK(divide);
  ops->nvscale = MODALTYRE_PICK(scale);
  ops->nvabs = MODALTYRE_PICK(absolute);
  ops->nvinv = MODALTYRE_PICK(inverse);
  ops->nvaddconst = MODALTYRE_PICK(add_constant);
  ops->nvwrmsnorm = MODALTYRE_PICK(wrms_norm);
  ops->nvwsqrsumlocal = MODALTYRE_PICK(weighted_square_sum);
  ops->nvmaxnorm = MODALTYRE_PICK(max_norm);
  ops->nvmaxnormlocal = MODALTYRE_PICK(max_norm);
  ops->nvlinearcombination = MODALTYRE_PICK(linear_combination);
  ops->nvscaleaddmulti = MODALTYRE_PICK(scale_add_multi);
#undef MODALTYRE_PICK
}

}  // namespace modaltyre::solvers

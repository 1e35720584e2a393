// CVODE's serial vector kernels (solvers/src/serial_vector_ops.h) on each path (run again with
// MODALTYRE_ISA=portable, tests/CMakeLists.txt): the sums with a = 1, b = +-1 give the bits of
// the general a x + b y, and the scaling those of c x, on lengths around the vector width, in
// place too.
#include "../../solvers/src/serial_vector_ops.h"

#include <gtest/gtest.h>
#include <sundials/sundials_context.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace {

using modaltyre::solvers::install_serial_vector_ops;

class SerialVectorOps : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(SUNContext_Create(nullptr, &ctx_), 0); }
  void TearDown() override {
    for (N_Vector v : vectors_) N_VDestroy(v);
    SUNContext_Free(&ctx_);
  }
  /// A serial vector with the kernels, entries spread over magnitudes and signs (and -0).
  N_Vector make(int n, double seed) {
    N_Vector v = N_VNew_Serial(n, ctx_);
    install_serial_vector_ops(v);
    vectors_.push_back(v);
    double* d = N_VGetArrayPointer(v);
    for (int i = 0; i < n; ++i)
      d[i] = i % 11 == 5 ? -0.0 : std::sin(seed * (i + 1)) * std::pow(10.0, (i % 7) - 3);
    return v;
  }
  SUNContext ctx_ = nullptr;
  std::vector<N_Vector> vectors_;
};

void expect_bits(const double* got, const std::vector<double>& want, const char* what, int n) {
  for (int i = 0; i < n; ++i)
    ASSERT_EQ(std::memcmp(&got[i], &want[i], sizeof(double)), 0)
        << what << ", n " << n << ", entry " << i << ": " << got[i] << " vs " << want[i];
}

TEST_F(SerialVectorOps, SumsAndScalingGiveTheGeneralLoopsBits) {
  for (int n : {1, 3, 4, 5, 8, 17, 2023}) {
    for (const auto& [a, b] : std::vector<std::pair<double, double>>{
             {1.0, 1.0}, {1.0, -1.0}, {-1.0, 1.0}, {0.37, -2.1}, {1.0, 0.5}}) {
      N_Vector x = make(n, 0.3), y = make(n, 0.7), z = make(n, 1.1);
      const double *xp = N_VGetArrayPointer(x), *yp = N_VGetArrayPointer(y);
      std::vector<double> want(n);
      for (int i = 0; i < n; ++i) want[i] = a * xp[i] + b * yp[i];
      N_VLinearSum(a, x, b, y, z);
      expect_bits(N_VGetArrayPointer(z), want, "z = a x + b y", n);
      N_VLinearSum(a, x, b, y, x);  // in place, as CVODE's predictor
      expect_bits(N_VGetArrayPointer(x), want, "x = a x + b y", n);
    }
    for (double c : {1.0, -1.0, 0.25}) {
      N_Vector x = make(n, 0.9), z = make(n, 1.3);
      const double* xp = N_VGetArrayPointer(x);
      std::vector<double> want(n);
      for (int i = 0; i < n; ++i) want[i] = c * xp[i];
      N_VScale(c, x, z);
      expect_bits(N_VGetArrayPointer(z), want, "z = c x", n);
      N_VScale(c, x, x);
      expect_bits(N_VGetArrayPointer(x), want, "x = c x", n);
    }
  }
}

}  // namespace

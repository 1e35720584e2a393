#pragma once
// Slope factors B1 (seed 000 eq. 6) and B2 (eq. 10) by least squares over
// 0 <= h_Z/r0 <= 0.117:
//   (1 - cos phi1)^(4/3) ~ B1 (sin phi1 - phi1 cos phi1)                         eq. (6)
//   (1 - cos phi1)^(4/3) ~ B2 cos phi1 (phi1 - cos phi1 * atanh(sin phi1))        eq. (10)
// The seed reports B1 = 1.5526, B2 = 1.6669, R = 0.995 without saying how it sampled the
// range; the defaults (6 points equally spaced in h_Z/r0, line through the origin) are the
// sampling that reproduces B1 closest (docs/rheology.md lists the alternatives).
#include <vector>

#include "modaltyre/rheology/report.h"

namespace modaltyre::rheology {

enum class SlopeSampling { uniform_deflection, uniform_angle };

/// Bounds `--samples` (2147483647 filled the memory); from 10^3 to 10^5 samples B1 and B2
/// change in the fourth digit only.
constexpr int kMaxSlopeSamples = 100000;
/// Smallest upper end of the h_Z/r0 range: below it the fit's design columns underflow.
constexpr double kMinRelativeDeflection = 1e-4;

struct SlopeFactorOptions {
  double max_relative_deflection = 0.117;  ///< upper end of h_Z/r0, in [1e-4, 1)
  int samples = 6;                         ///< points including h = 0, 3..kMaxSlopeSamples
  SlopeSampling sampling = SlopeSampling::uniform_deflection;
  bool through_origin = true;  ///< fit y = B x (true) or y = B x + c (false)
};

struct SlopeFactorResult {
  double B1 = 0, B1_se = 0, R1 = 0;
  double B2 = 0, B2_se = 0, R2 = 0;
  std::vector<double> phi1;               ///< sampled half contact angles [rad]
  std::vector<double> y;                  ///< (1 - cos phi1)^(4/3)
  std::vector<double> x1;                 ///< sin phi1 - phi1 cos phi1
  std::vector<double> x2;                 ///< cos phi1 (phi1 - cos phi1 atanh(sin phi1))
  double intercept1 = 0, intercept2 = 0;  ///< 0 when through_origin
  FitReport report;
};

/// InputError for samples outside [3, kMaxSlopeSamples] or a range outside [1e-4, 1).
SlopeFactorResult compute_slope_factors(const SlopeFactorOptions& options = {});

}  // namespace modaltyre::rheology

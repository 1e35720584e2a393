#include "modaltyre/rheology/slope_factors.h"

#include <cmath>
#include <string>

#include "modaltyre/core/errors.h"
#include "modaltyre/rheology/contact_geometry.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/solvers/correlation.h"
#include "modaltyre/solvers/linear_least_squares.h"

namespace modaltyre::rheology {

SlopeFactorResult compute_slope_factors(const SlopeFactorOptions& o) {
  if (o.samples < 3 || o.samples > kMaxSlopeSamples) {
    throw InputError({"--samples", 0, "samples"}, "need 3 to " + std::to_string(kMaxSlopeSamples) +
                                                      " samples, got " + std::to_string(o.samples));
  }
  // Below 1e-4 (0.03 mm on a 300 mm tyre) the samples' powers of phi underflow towards zero and
  // the fit's design loses its columns: an input error, not a failed computation.
  if (!(o.max_relative_deflection >= kMinRelativeDeflection && o.max_relative_deflection < 1))
    throw InputError({"--max-h-r0", 0, "max_relative_deflection"},
                     "the range of h_Z/r0 must be in [1e-4, 1)");
  SlopeFactorResult res;
  const double phi_max = std::acos(1.0 - o.max_relative_deflection);
  for (int i = 0; i < o.samples; ++i) {
    const double u = static_cast<double>(i) / (o.samples - 1);
    const double phi = o.sampling == SlopeSampling::uniform_deflection
                           ? std::acos(1.0 - u * o.max_relative_deflection)
                           : u * phi_max;
    res.phi1.push_back(phi);
    res.y.push_back(deflection_power(phi));
    res.x1.push_back(kelvin_voigt_load_function(phi));  // seed 000 eq. (6)
    res.x2.push_back(arc_stress_load_function(phi));    // seed 000 eq. (10)
  }
  const int n = o.samples;
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(res.y.data(), n);
  auto fit = [&](const std::vector<double>& xs, double& B, double& se, double& R, double& c) {
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(xs.data(), n);
    Eigen::MatrixXd A(n, o.through_origin ? 1 : 2);
    A.col(0) = x;
    if (!o.through_origin) A.col(1).setOnes();
    const solvers::LinearFit f = solvers::solve_linear_least_squares(A, y);
    B = f.coef(0);
    se = f.std_error(0);
    c = o.through_origin ? 0.0 : f.coef(1);
    R = solvers::pearson_correlation(xs, res.y);
    return f.residual_rms;
  };
  const double rms1 = fit(res.x1, res.B1, res.B1_se, res.R1, res.intercept1);
  const double rms2 = fit(res.x2, res.B2, res.B2_se, res.R2, res.intercept2);

  auto& rep = res.report;
  rep.method = "b-factors";
  rep.rows = n;
  rep.residual_rms = std::max(rms1, rms2);
  rep.residual_unit = "-";
  rep.parameters = {{"B1", res.B1, "-", res.B1_se},
                    {"B2", res.B2, "-", res.B2_se},
                    {"R1", res.R1, "-", 0.0},
                    {"R2", res.R2, "-", 0.0},
                    {"B1_vs_seed_percent", 100.0 * (res.B1 / kSeedB1 - 1.0), "%", 0.0},
                    {"B2_vs_seed_percent", 100.0 * (res.B2 / kSeedB2 - 1.0), "%", 0.0}};
  rep.notes.push_back(std::string("sampling: ") + std::to_string(n) + " points uniform in " +
                      (o.sampling == SlopeSampling::uniform_deflection ? "h_Z/r0" : "phi1") +
                      " over 0 <= h_Z/r0 <= " + std::to_string(o.max_relative_deflection) +
                      (o.through_origin ? ", line through the origin" : ", line with intercept"));
  return res;
}

}  // namespace modaltyre::rheology

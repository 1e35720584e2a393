#include "modaltyre/studies/stiffness_calibration.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/bracketed_root.h"

namespace modaltyre::studies {

using namespace contact;
namespace {

constexpr double kMinScale = 1e-3, kMaxScale = 1e3;  // tyre_config.cc's range of the key

std::string mm(double v) {
  char b[48];
  std::snprintf(b, sizeof b, "%.4g mm", v);
  return b;
}

}  // namespace

ScaleCalibration calibrate_compliance_scale(const TyreModel& model,
                                            const TyreParameters& parameters,
                                            const OperatingConditions& at, double target_sinking_mm,
                                            double relative_tolerance) {
  ScaleCalibration out;
  out.target_mm = target_sinking_mm;
  if (!(target_sinking_mm > 0) || !std::isfinite(target_sinking_mm)) {
    throw InputError({"", 0, "modal.compliance_scale"},
                     "target deflection must be a positive number, got " + mm(target_sinking_mm));
  }
  TyreParameters trial = parameters;
  // f(log scale) = sinking - target; throws nothing, reports a failed solve.
  auto residual = [&](double log_scale, double& sinking_mm) {
    trial.compliance_scale = std::exp(log_scale);
    const Prediction p = predict(model, trial, at);
    ++out.evaluations;
    if (!p.ok()) {
      out.message = "footprint at compliance_scale " + std::to_string(trial.compliance_scale) +
                    " did not converge: " + p.message;
      return false;
    }
    sinking_mm = p.sinking_mm;
    return true;
  };

  // Bracket outwards from the config's own scale in factors of 4: the far ends of the key's
  // range may not even be solvable (a very soft carcass outgrows the candidate window).
  const double step = std::log(4.0);
  double a = std::log(parameters.compliance_scale), sa = 0;
  if (!residual(a, sa)) return out;
  double b = a, sb = sa;
  if (sa < target_sinking_mm) {
    while (sb < target_sinking_mm) {
      a = b, sa = sb;
      if (b >= std::log(kMaxScale)) {
        throw InputError({"", 0, "modal.compliance_scale"},
                         "the measured deflection " + mm(target_sinking_mm) +
                             " exceeds the model's at the softest carcass allowed (" + mm(sb) +
                             " at compliance_scale 1e3)");
      }
      b = std::min(b + step, std::log(kMaxScale));
      if (!residual(b, sb)) return out;
    }
  } else {
    while (sa > target_sinking_mm) {
      b = a, sb = sa;
      if (a <= std::log(kMinScale)) {
        throw InputError({"", 0, "modal.compliance_scale"},
                         "the measured deflection " + mm(target_sinking_mm) +
                             " is below the model's at the stiffest carcass allowed (" + mm(sa) +
                             " at compliance_scale 1e-3, mostly the tread's): the tested tyre "
                             "is stiffer than this config's tread and road allow");
      }
      a = std::max(a - step, std::log(kMinScale));
      if (!residual(a, sa)) return out;
    }
  }
  if (sa == target_sinking_mm || sb == target_sinking_mm) {
    out.status = SolveStatus::converged;
    out.compliance_scale = std::exp(sa == target_sinking_mm ? a : b);
    out.sinking_mm = target_sinking_mm;
    return out;
  }
  // Illinois regula falsi in log(scale): superlinear, and never leaves the bracket.
  auto f = [&](double log_scale) -> std::optional<double> {
    double sc = 0;
    if (!residual(log_scale, sc)) return std::nullopt;
    out.compliance_scale = std::exp(log_scale);
    out.sinking_mm = sc;
    return sc - target_sinking_mm;
  };
  solvers::IllinoisOptions io;
  io.tolerance = relative_tolerance * target_sinking_mm;
  io.max_iterations = 100;
  const solvers::RootResult root =
      solvers::illinois_root(f, a, sa - target_sinking_mm, b, sb - target_sinking_mm, io);
  if (root.status == SolveStatus::aborted) return out;
  if (root.ok()) {
    out.status = SolveStatus::converged;
    return out;
  }
  out.status = SolveStatus::max_iterations;
  out.message = "compliance_scale did not settle in 100 footprints (last sinking " +
                mm(out.sinking_mm) + ", target " + mm(target_sinking_mm) + ")";
  return out;
}

}  // namespace modaltyre::studies

#pragma once
// A root of a scalar function inside a sign-changing bracket by the Illinois variant of regula
// falsi (Dowell & Jarratt 1971): superlinear, and every iterate stays inside the bracket, which
// matters when f is expensive and undefined outside it (a footprint per evaluation).
#include <functional>
#include <optional>

#include "modaltyre/core/solve_status.h"

namespace modaltyre::solvers {

struct IllinoisOptions {
  double tolerance = 0;      ///< converged when |f(x)| <= tolerance (in f's unit), >= 0
  int max_iterations = 100;  ///< evaluations of f at most, >= 1
};

struct RootResult {
  SolveStatus status = SolveStatus::max_iterations;  ///< or converged, aborted
  double x = 0;        ///< the last iterate f was evaluated at successfully
  double fx = 0;       ///< f(x)
  int iterations = 0;  ///< evaluations of f, the aborted one included
  bool ok() const { return modaltyre::ok(status); }
};

/// Finds x in [a, b] with |f(x)| <= tolerance, given fa = f(a) and fb = f(b) of opposite
/// signs (both nonzero; ComputationError otherwise). f returns nullopt to stop the search
/// (status aborted; the reason is the caller's to keep). With no iteration yet, x and fx are 0.
RootResult illinois_root(const std::function<std::optional<double>(double)>& f, double a, double fa,
                         double b, double fb, const IllinoisOptions& options = {});

}  // namespace modaltyre::solvers

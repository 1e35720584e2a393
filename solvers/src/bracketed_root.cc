#include "modaltyre/solvers/bracketed_root.h"

#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::solvers {

RootResult illinois_root(const std::function<std::optional<double>(double)>& f, double a, double fa,
                         double b, double fb, const IllinoisOptions& options) {
  MODALTYRE_CHECK((fa < 0 && fb > 0) || (fa > 0 && fb < 0),
                  "illinois_root: the bracket's ends must have f of opposite signs");
  MODALTYRE_CHECK(options.tolerance >= 0 && options.max_iterations >= 1,
                  "illinois_root: bad options");
  RootResult r;
  int side = 0;  // which end moved last: -1 b, +1 a
  for (int it = 0; it < options.max_iterations; ++it) {
    const double c = (a * fb - b * fa) / (fb - fa);  // the secant through both ends
    ++r.iterations;
    const std::optional<double> fc = f(c);
    if (!fc) {
      r.status = SolveStatus::aborted;
      return r;
    }
    r.x = c;
    r.fx = *fc;
    if (std::abs(*fc) <= options.tolerance) {
      r.status = SolveStatus::converged;
      return r;
    }
    // Replace the end of c's sign; when the same end moves twice running, halve the other
    // end's value (the Illinois step), so that end moves too and the order stays superlinear.
    if ((*fc > 0) == (fb > 0)) {
      b = c, fb = *fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = c, fa = *fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
  }
  r.status = SolveStatus::max_iterations;
  return r;
}

}  // namespace modaltyre::solvers

#pragma once
// The points of a drawbar-pull curve a soil-bin engineer reads off (docs/soil.md section 5.1):
// the towed point (zero driving torque: its slip and drawbar pull, negative on a soil: the
// motion resistance a towed wheel needs) and the self-propelled point (zero drawbar pull: its
// slip and torque). Each is interpolated linearly between the two converged slips of the curve
// (one load, one pass, slips in increasing order) where the quantity changes sign; absent when it
// does not change sign over the slips given.
#include <optional>
#include <vector>

#include "modaltyre/contact/traction.h"

namespace modaltyre::contact {

struct CurvePoint {
  double slip = 0;
  double value = 0;  ///< drawbar pull [N] at the towed point, torque [N m] at the self-propelled
};

struct TractionCurve {
  double load_N = 0;
  int pass = 1;
  std::vector<const TractionResult*> rows;  ///< the curve's rows, in the order given
  std::optional<CurvePoint> towed, self_propelled;
};

/// The curves of steady_traction's results (one per load and pass, in order of appearance). The
/// pointers refer into `results`.
std::vector<TractionCurve> traction_curves(const std::vector<TractionResult>& results);

}  // namespace modaltyre::contact

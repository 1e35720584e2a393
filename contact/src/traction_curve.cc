#include "modaltyre/contact/traction_curve.h"

#include <algorithm>

namespace modaltyre::contact {
namespace {

// Where y(slip) crosses zero between consecutive converged rows (sorted by slip): the slip and
// the other quantity there, both interpolated linearly.
std::optional<CurvePoint> zero_crossing(std::vector<const TractionResult*> rows,
                                        double (*y)(const TractionResult&),
                                        double (*other)(const TractionResult&)) {
  std::erase_if(rows, [](const TractionResult* r) { return !r->ok(); });
  std::sort(rows.begin(), rows.end(),
            [](const TractionResult* a, const TractionResult* b) { return a->slip < b->slip; });
  for (std::size_t k = 0; k + 1 < rows.size(); ++k) {
    const double y0 = y(*rows[k]), y1 = y(*rows[k + 1]);
    if (y0 == 0) return CurvePoint{rows[k]->slip, other(*rows[k])};
    if ((y0 < 0) == (y1 < 0) || y1 == y0) continue;
    const double t = y0 / (y0 - y1);
    return CurvePoint{rows[k]->slip + t * (rows[k + 1]->slip - rows[k]->slip),
                      other(*rows[k]) + t * (other(*rows[k + 1]) - other(*rows[k]))};
  }
  if (!rows.empty() && y(*rows.back()) == 0)
    return CurvePoint{rows.back()->slip, other(*rows.back())};
  return std::nullopt;
}

double torque(const TractionResult& r) { return r.torque_Nm; }
double pull(const TractionResult& r) { return r.drawbar_pull_N; }

}  // namespace

std::vector<TractionCurve> traction_curves(const std::vector<TractionResult>& results) {
  std::vector<TractionCurve> curves;
  for (const TractionResult& r : results) {
    auto it = std::find_if(curves.begin(), curves.end(), [&](const TractionCurve& c) {
      return c.load_N == r.load_N && c.pass == r.pass;
    });
    if (it == curves.end()) {
      curves.push_back({r.load_N, r.pass, {}, std::nullopt, std::nullopt});
      it = curves.end() - 1;
    }
    it->rows.push_back(&r);
  }
  for (TractionCurve& c : curves) {
    c.towed = zero_crossing(c.rows, torque, pull);
    c.self_propelled = zero_crossing(c.rows, pull, torque);
  }
  return curves;
}

}  // namespace modaltyre::contact

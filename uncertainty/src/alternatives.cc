#include "alternatives.h"

#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/uncertainty/order_mixture.h"

namespace modaltyre::uncertainty {
namespace {

/// One kind of discrete alternative: its members' probabilities (summing to 1) and their
/// outputs' shifts from the nominal, [member][case][output].
struct Group {
  std::vector<double> weight;
  std::vector<Outputs> shift;
};

Outputs minus(const Outputs& a, const Outputs& b) {
  Outputs d = a;
  for (std::size_t c = 0; c < d.size(); ++c)
    for (std::size_t q = 0; q < d[c].size(); ++q) d[c][q] -= b[c][q];
  return d;
}

// modal.order_alternatives: the config's orders (the rest of the probability, no shift) and each
// alternative assignment.
Group order_group(PropagationResult& r, const contact::TyreConfig& config,
                  const modal::ModeIdentification& modes, const Evaluator& evaluate,
                  const Outputs& nominal, std::ostringstream& words) {
  Group g;
  const contact::CarcassSettings& s = config.carcass;
  const std::size_t na = s.order_alternatives.size();
  if (na == 0) return g;
  double rest = 1;
  for (double p : s.order_alternative_probabilities) rest -= p;
  g.weight.push_back(rest);
  g.shift.push_back(minus(nominal, nominal));
  r.order_alternatives.push_back({s.orders, rest});
  for (std::size_t a = 0; a < na; ++a) {
    contact::TyreConfig c = config;
    c.carcass.orders = s.order_alternatives[a];
    modal::ModeIdentification m = modes;
    // config_modes: the list's modes first, in the list's order.
    for (std::size_t i = 0; i < c.carcass.orders.size() && i < m.modes.size(); ++i) {
      m.modes[i].apparent_order = c.carcass.orders[i];
    }
    const std::string what = "order alternative " + std::to_string(a + 1);
    const Outputs out = evaluate(c, m, what);
    check_shape(out, nominal.size(), nominal.front().size(), what);
    g.weight.push_back(s.order_alternative_probabilities[a]);
    g.shift.push_back(minus(out, nominal));
    r.order_alternatives.push_back({s.order_alternatives[a], s.order_alternative_probabilities[a]});
  }
  words << "; mixed with " << na << " alternative order assignment" << (na > 1 ? "s" : "")
        << " of the frequency list (modal.order_alternatives, probabilities";
  for (double p : s.order_alternative_probabilities) words << " " << p;
  words << "; modal.orders " << rest << ")";
  return g;
}

// footprint_3d.crown.round_limit_radius_mm: crowns from flat to the limit's circle, uniform in
// the curvature, at kCrownPoints midpoints.
Group crown_group(const contact::TyreConfig& config, const modal::ModeIdentification& modes,
                  const Evaluator& evaluate, const Outputs& nominal, std::ostringstream& words) {
  Group g;
  if (!config.footprint_3d) return g;
  const contact::CrownProfile& crown = config.footprint_3d->crown;
  const double limit_m = crown.round_limit_radius_m;
  if (crown.shape != contact::CrownShape::flat || !(limit_m > 0)) return g;
  if (!(limit_m > 0.5 * config.footprint_3d->tread_width_m)) {
    throw InputError({config.source, 0, "footprint_3d.crown.round_limit_radius_mm"},
                     "must exceed half the tread width (a circle of this radius turns vertical "
                     "inside the tread)");
  }
  g.weight.push_back(0.5 / (kCrownPoints - 1));  // flat: the nominal itself
  g.shift.push_back(minus(nominal, nominal));
  for (int i = 1; i < kCrownPoints; ++i) {
    const double u = static_cast<double>(i) / (kCrownPoints - 1);
    contact::TyreConfig c = config;
    c.footprint_3d->crown.shape = contact::CrownShape::circular;
    c.footprint_3d->crown.radius_m = limit_m / u;
    const std::string what = "crown alternative " + std::to_string(i) + " (radius " +
                             std::to_string(std::lround(limit_m / u * 1e3)) + " mm)";
    const Outputs out = evaluate(c, modes, what);
    check_shape(out, nominal.size(), nominal.front().size(), what);
    g.weight.push_back((i + 1 == kCrownPoints ? 0.5 : 1.0) / (kCrownPoints - 1));
    g.shift.push_back(minus(out, nominal));
  }
  words << "; mixed with the crown's shape from flat to a circle of radius "
        << std::lround(limit_m * 1e3)
        << " mm (footprint_3d.crown.round_limit_radius_mm, uniform in curvature, " << kCrownPoints
        << " points)";
  return g;
}

}  // namespace

void mix_alternatives(PropagationResult& r, const contact::TyreConfig& config,
                      const modal::ModeIdentification& modes, const Evaluator& evaluate,
                      const Outputs& nominal, const std::vector<Outputs>& samples) {
  std::ostringstream words;
  words.precision(3);
  std::vector<Group> groups;
  for (Group g : {order_group(r, config, modes, evaluate, nominal, words),
                  crown_group(config, modes, evaluate, nominal, words)}) {
    if (!g.weight.empty()) groups.push_back(std::move(g));
  }
  if (groups.empty()) return;
  // Each group's first member is the nominal itself (not evaluated).
  for (const Group& g : groups) r.evaluations += static_cast<int>(g.weight.size()) - 1;
  if (r.inputs.empty())
    r.check = "no continuous uncertain input (noise-free shapes, nothing stated)";
  r.check += words.str();
  for (std::size_t c = 0; c < nominal.size(); ++c) {
    for (std::size_t q = 0; q < nominal[c].size(); ++q) {
      // Every combination of one member per group: weights multiply, shifts add.
      std::vector<MixtureComponent> comps = {{1.0, 0.0}};
      for (const Group& g : groups) {
        std::vector<MixtureComponent> next;
        for (const auto& base : comps) {
          for (std::size_t k = 0; k < g.weight.size(); ++k) {
            next.push_back({base.weight * g.weight[k], base.shift + g.shift[k][c][q]});
          }
        }
        comps = std::move(next);
      }
      std::vector<double> column;
      for (const auto& sample : samples) column.push_back(sample[c][q]);
      r.cases[c].bands[q] =
          mix_band(r.cases[c].bands[q], samples.empty() ? nullptr : &column, comps);
    }
  }
}

}  // namespace modaltyre::uncertainty

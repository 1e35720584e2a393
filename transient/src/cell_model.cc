#include "modaltyre/transient/cell_model.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "modaltyre/core/errors.h"

namespace modaltyre::transient {

CellClasses column_classes(const contact::Patch3dSettings& s, double cleat_width_m, bool merge) {
  CellClasses c;
  // The 3D patch's columns (patch3d.cc): round(width / cell) of equal width.
  const int n = std::max(1, static_cast<int>(std::round(s.tread_width_m / s.lateral_cell_m)));
  c.columns = n;
  c.tread_width_m = s.tread_width_m;
  c.dy_m = s.tread_width_m / n;
  const double half = 0.5 * s.tread_width_m;
  const double cleat_half = cleat_width_m > 0 ? 0.5 * cleat_width_m : half;
  // Classes keyed by (drop, covered): the drop evaluated at |y| of the column nearer the left
  // edge of its mirror pair, so that mirror columns get bit-identical keys.
  std::map<std::pair<double, int>, int> key_class;
  for (int j = 0; j < n; ++j) {
    const int mirror = std::min(j, n - 1 - j);
    const double ay = std::abs(-half + (mirror + 0.5) * c.dy_m);
    c.column_y_m.push_back(-half + (j + 0.5) * c.dy_m);
    const double drop = s.crown.drop_m(ay);
    c.column_drop_m.push_back(drop);
    const int covered = ay < cleat_half ? 1 : 0;
    const std::pair<double, int> key{drop, merge ? covered : j};
    auto it = key_class.find(key);
    if (!merge || it == key_class.end()) {
      const int k = c.size();
      key_class[merge ? key : std::pair<double, int>{drop, j}] = k;
      c.drop_m.push_back(drop);
      c.abs_y_m.push_back(ay);
      c.multiplicity.push_back(1);
      c.on_cleat.push_back(static_cast<char>(covered));
      c.column_class.push_back(k);
    } else {
      ++c.multiplicity[it->second];
      c.abs_y_m[it->second] = std::min(c.abs_y_m[it->second], ay);
      c.column_class.push_back(it->second);
    }
  }
  return c;
}

CellModel build_cell_model(const TransientModel& M, double cleat_width_m, bool merge) {
  const auto& cfg = M.tyre.config;
  if (!cfg.footprint_3d) {
    throw InputError(InputLocation{cfg.source, 0, "footprint_3d"},
                     "the 3D transient needs a footprint_3d: section");
  }
  CellModel cm;
  cm.carcass = &M;
  cm.patch = *cfg.footprint_3d;
  if (cm.patch.lateral_belt.enabled || cm.patch.sidewall.enabled) {
    throw InputError(InputLocation{cfg.source, 0,
                                   cm.patch.lateral_belt.enabled ? "footprint_3d.lateral_belt"
                                                                 : "footprint_3d.sidewall"},
                     "the transient on the 3D patch takes the laterally rigid belt with the "
                     "modes' linear sidewalls only (docs/transient.md section 7)");
  }
  if (cleat_width_m > cm.patch.tread_width_m) {
    throw InputError(InputLocation{cfg.source, 0, "transient.cleat.width_mm"},
                     "cleat wider than footprint_3d.tread_width_mm");
  }
  cm.classes = column_classes(cm.patch, cleat_width_m, merge);
  const contact::Patch3d patch(M.tyre, cm.patch);
  const int m = M.m, ny = cm.classes.columns;
  const contact::TreadSprings ks =
      contact::tread_springs(cfg.tread, cm.classes.dy_m, M.tyre.unit_length_m);
  cm.k_radial_cell_N_m = ks.radial_N_m;
  cm.k_tangential_cell_N_m = ks.tangential_N_m;
  const double ratio = M.settings.instantaneous_stiffness_ratio;
  cm.k_relaxed.resize(m);
  cm.k_contact.resize(m);
  cm.k_kv.resize(m);
  cm.c_kv.resize(m);
  for (int i = 0; i < m; ++i) {
    const double k = 1.0 / patch.cell_tread_compliance(i);
    const double d = ny * M.residual_lumped(i);  // the section's lumped residual, per cell
    cm.k_relaxed(i) = k;
    if (M.settings.relaxation) {
      cm.k_contact(i) = 1.0 / (1.0 / (ratio * k) + d);
      cm.k_kv(i) = k * ratio / (ratio - 1);
      cm.c_kv(i) = cm.k_kv(i) * M.tread_time_constant_s;
    } else {
      cm.k_contact(i) = 1.0 / (1.0 / k + d);
      cm.k_kv(i) = 0;
      cm.c_kv(i) = 0;
    }
  }
  return cm;
}

contact::Patch3d static_patch(const CellModel& cm) {
  return contact::Patch3d(cm.M().tyre, cm.patch);
}

}  // namespace modaltyre::transient

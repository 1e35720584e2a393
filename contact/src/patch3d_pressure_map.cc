// The 3D patch's pressure over its loaded sections and columns (plus a margin), in kPa: what
// `footprint --map-csv` writes and the footprint plot draws.
#include "modaltyre/contact/patch3d.h"

namespace modaltyre::contact {

PressureMap pressure_map(const Patch3dResult& r, int margin) {
  PressureMap map;
  int first = -1, last = -1;
  for (int i = 0; i < r.sections; ++i) {
    if (r.section_force_N[i] > 0) {
      if (first < 0) first = i;
      last = i;
    }
  }
  if (first < 0) return map;
  first = std::max(0, first - margin);
  last = std::min(r.sections - 1, last + margin);
  map.first_section = first;
  for (int i = first; i <= last; ++i) map.x_mm.push_back(r.x_m[i] * 1e3);
  for (int j = 0; j < r.columns; ++j) {
    map.y_mm.push_back(r.y_m[j] * 1e3);
    std::vector<double> row;
    for (int i = first; i <= last; ++i) row.push_back(r.pressure_Pa(i, j) * 1e-3);
    map.pressure_kPa.push_back(std::move(row));
  }
  return map;
}

}  // namespace modaltyre::contact

#include "modaltyre/contact/footprint_measures.h"

#include <algorithm>

#include "modaltyre/contact/pneumatic_share.h"

namespace modaltyre::contact {

double cell_area_in_contact_m2(const Patch3dResult& r) {
  double area = 0;
  for (int i = 0; i < r.sections; ++i)
    for (int j = 0; j < r.columns; ++j)
      if (r.cell_force(i, j) > 0) area += r.dx_m[i] * r.dy_m;
  return area;
}

// Off the centre line with a lateral belt, the 3D map's peak exceeds the units' one.
double peak_pressure_Pa(const Prediction& p) {
  double peak = 0;
  for (const auto& u : p.footprint.units) peak = std::max(peak, u.pressure_Pa);
  if (p.patch3d) {
    const auto& m = *p.patch3d;
    for (int i = 0; i < m.sections; ++i)
      for (int j = 0; j < m.columns; ++j) peak = std::max(peak, m.pressure_Pa(i, j));
  }
  return peak;
}

double mean_pressure_Pa(const Prediction& p) {
  const auto& r = p.footprint;
  const double area =
      p.patch3d ? cell_area_in_contact_m2(*p.patch3d) : r.contact_length_m * p.width_mm * 1e-3;
  return area > 0 ? r.load.load_N / area : 0.0;
}

}  // namespace modaltyre::contact

namespace modaltyre::contact {

double smooth_mean_pressure_Pa(const Prediction& p) {
  if (!p.patch3d) return mean_pressure_Pa(p);
  const double area = contact_area_m2(*p.patch3d);
  return area > 0 ? p.footprint.load.load_N / area : 0.0;
}

}  // namespace modaltyre::contact

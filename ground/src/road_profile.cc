#include "modaltyre/ground/road_profile.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::ground {

namespace {
// The segment [x_k, x_k+1] holding x; k in [0, points - 2].
std::size_t segment(const std::vector<double>& x, double at) {
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const std::size_t k = static_cast<std::size_t>(it - x.begin());
  return std::clamp<std::size_t>(k, 1, x.size() - 1) - 1;
}
}  // namespace

double RoadProfile::height_at(double at) const {
  if (x_m.empty()) return 0.0;
  if (at <= x_m.front()) return height_m.front();
  if (at >= x_m.back()) return height_m.back();
  const std::size_t k = segment(x_m, at);
  const double t = (at - x_m[k]) / (x_m[k + 1] - x_m[k]);
  return height_m[k] + t * (height_m[k + 1] - height_m[k]);
}

double RoadProfile::slope_at(double at) const {
  if (x_m.size() < 2 || at < x_m.front() || at >= x_m.back()) return 0.0;
  const std::size_t k = segment(x_m, at);
  return (height_m[k + 1] - height_m[k]) / (x_m[k + 1] - x_m[k]);
}

RoadProfile read_road_profile_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"x_m", "height_m"};
  schema.max_rows = kMaxProfilePoints;
  const CsvTable t = read_csv(path, schema);
  RoadProfile p;
  p.path = path;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double x = t.number(r, "x_m"), h = t.number(r, "height_m");
    if (!(std::abs(x) <= kMaxProfileLength_m))
      throw InputError({path, t.line(r), "x_m"}, "must be within +-1e6 m");
    if (!(std::abs(h) <= kMaxProfileHeight_m))
      throw InputError({path, t.line(r), "height_m"}, "must be within +-100 m");
    if (!p.x_m.empty() && !(x > p.x_m.back()))
      throw InputError({path, t.line(r), "x_m"}, "must increase strictly from row to row");
    p.x_m.push_back(x);
    p.height_m.push_back(h);
  }
  if (p.x_m.size() < 2)
    throw InputError({path, t.rows() ? t.line(0) : 0, "x_m"},
                     "a road profile needs at least two points");
  return p;
}

}  // namespace modaltyre::ground

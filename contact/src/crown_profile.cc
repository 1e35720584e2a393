#include "modaltyre/contact/crown_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace modaltyre::contact {
namespace {

/// The shoulder arc, tangent to the crown arc at y1: its centre (cy, cz) lies on the crown
/// arc's normal through (y1, z1), R2 from the point.
struct ShoulderArc {
  double y1, z1, cy, cz, r2;
};

ShoulderArc shoulder_arc(const CrownProfile& c) {
  const double r1 = c.radius_m, y1 = c.shoulder_start_m, r2 = c.shoulder_radius_m;
  const double z1 = r1 - std::sqrt(r1 * r1 - y1 * y1);
  const double s = y1 / r1, co = std::sqrt(1 - s * s);  // normal (s, -co) from the centre
  return {y1, z1, y1 - r2 * s, z1 + r2 * co, r2};
}

/// Steep continuation past a shoulder arc's vertical tangent (never reached
/// inside a valid tread width, see patch3d.h).
constexpr double kWallSlope = 1e3;

/// v(u) linear between the points of a table with u and v both strictly increasing (the contour
/// and its inverse), the last segment's slope past the end; u >= us[0].
double table_lookup(const std::vector<double>& us, const std::vector<double>& vs, double u) {
  const std::size_t n = us.size();
  std::size_t k = std::upper_bound(us.begin(), us.end(), u) - us.begin();
  k = std::min(k, n - 1);  // past the end: extend the last segment
  const double t = (u - us[k - 1]) / (us[k] - us[k - 1]);
  return vs[k - 1] + t * (vs[k] - vs[k - 1]);
}

}  // namespace

double CrownProfile::drop_m(double y) const {
  const double a = std::abs(y);
  switch (shape) {
    case CrownShape::flat:
      return 0.0;
    case CrownShape::circular: {
      if (shoulder_radius_m <= 0 || a <= shoulder_start_m) {
        return radius_m - std::sqrt(std::max(radius_m * radius_m - a * a, 0.0));
      }
      const ShoulderArc s = shoulder_arc(*this);
      const double u = a - s.cy;
      if (u >= s.r2) return s.cz + kWallSlope * (u - s.r2);
      return s.cz - std::sqrt(s.r2 * s.r2 - u * u);
    }
    case CrownShape::power: {
      const double yr = reference_half_width_m;
      return yr * yr / (2 * radius_m) * std::pow(a / yr, exponent);
    }
    case CrownShape::contour:
      return table_lookup(contour_y_m, contour_drop_m, a);
  }
  return 0.0;
}

double CrownProfile::half_width_m(double d) const {
  if (d <= 0) return 0.0;
  switch (shape) {
    case CrownShape::flat:
      return INFINITY;
    case CrownShape::circular: {
      const ShoulderArc s = shoulder_radius_m > 0 ? shoulder_arc(*this) : ShoulderArc{};
      if (shoulder_radius_m <= 0 || d <= s.z1) {
        const double r = radius_m;
        return std::sqrt(std::max(2 * r * d - d * d, 0.0));
      }
      if (d >= s.cz) return s.cy + s.r2 + (d - s.cz) / kWallSlope;
      return s.cy + std::sqrt(s.r2 * s.r2 - (s.cz - d) * (s.cz - d));
    }
    case CrownShape::power: {
      const double yr = reference_half_width_m;
      return yr * std::pow(2 * radius_m * d / (yr * yr), 1 / exponent);
    }
    case CrownShape::contour:
      return table_lookup(contour_drop_m, contour_y_m, d);
  }
  return 0.0;
}

double CrownProfile::reach_m() const {
  if (shape != CrownShape::circular) return INFINITY;
  if (shoulder_radius_m <= 0) return radius_m;
  const ShoulderArc s = shoulder_arc(*this);
  return s.cy + s.r2;
}

void CrownProfile::validate() const {
  if (shape == CrownShape::circular || shape == CrownShape::power) {
    if (!(radius_m > 0)) throw std::invalid_argument("crown radius must be > 0");
  }
  if (shape == CrownShape::power) {
    // n > 1: the crown has no ridge (zero slope) on the centre line.
    if (!(exponent > 1)) throw std::invalid_argument("power crown exponent must be > 1");
    if (!(reference_half_width_m > 0)) {
      throw std::invalid_argument("power crown reference half-width must be > 0");
    }
  }
  if (shape == CrownShape::circular) {
    if (shoulder_radius_m > 0) {
      if (!(shoulder_radius_m < radius_m)) {
        throw std::invalid_argument("shoulder radius must be smaller than the crown radius");
      }
      if (!(shoulder_start_m > 0 && shoulder_start_m < radius_m)) {
        throw std::invalid_argument("shoulder start must lie between 0 and the crown radius");
      }
    }
  }
  if (shape == CrownShape::contour) {
    const auto& ys = contour_y_m;
    const auto& zs = contour_drop_m;
    if (ys.size() != zs.size() || ys.size() < 2) {
      throw std::invalid_argument("contour needs as many drops as positions, at least two");
    }
    if (ys[0] != 0 || zs[0] != 0) {
      throw std::invalid_argument("contour must start at y = 0 with drop 0");
    }
    for (std::size_t k = 1; k < ys.size(); ++k) {
      if (!(ys[k] > ys[k - 1]) || !(zs[k] > zs[k - 1])) {
        throw std::invalid_argument("contour positions and drops must both increase strictly");
      }
    }
  }
}

CrownProfile read_crown_profile(const ConfigSection& s) {
  CrownProfile c;
  const std::string shape = s.choice("shape", "circular", {"flat", "circular", "power", "contour"});
  c.shape = shape == "flat"      ? CrownShape::flat
            : shape == "power"   ? CrownShape::power
            : shape == "contour" ? CrownShape::contour
                                 : CrownShape::circular;
  c.radius_m = s.positive("radius_mm", c.radius_m * 1e3, 1e6) * 1e-3;
  c.shoulder_radius_m = s.number("shoulder_radius_mm", 0, 0, 1e6) * 1e-3;
  c.shoulder_start_m = s.number("shoulder_start_mm", 0, 0, 1e6) * 1e-3;
  if (c.shape == CrownShape::flat) {  // elsewhere an unknown key
    c.round_limit_radius_m = s.number("round_limit_radius_mm", 0, 0, 1e6) * 1e-3;
  }
  if (c.shape == CrownShape::power) {  // elsewhere the two keys are unknown keys
    c.exponent = s.number("exponent", c.exponent, 1, 20);
    c.reference_half_width_m = s.number("reference_half_width_mm", 0, 0, 1e4) * 1e-3;
  }
  for (double v : s.numbers("contour_y_mm", {}, 0, 1e4)) c.contour_y_m.push_back(v * 1e-3);
  for (double v : s.numbers("contour_drop_mm", {}, 0, 1e4)) c.contour_drop_m.push_back(v * 1e-3);
  if (c.shape == CrownShape::circular && c.shoulder_radius_m > 0 && !s.has("shoulder_start_mm")) {
    s.fail("shoulder_start_mm", "required with shoulder_radius_mm");
  }
  if (c.shape == CrownShape::power && !s.has("reference_half_width_mm")) {
    s.fail("reference_half_width_mm", "required with shape: power");
  }
  try {
    c.validate();
  } catch (const std::invalid_argument& e) {
    const char* key = c.shape == CrownShape::contour                      ? "contour_drop_mm"
                      : c.shape == CrownShape::power && !(c.exponent > 1) ? "exponent"
                      : c.shape == CrownShape::power && !(c.reference_half_width_m > 0)
                          ? "reference_half_width_mm"
                      : c.shoulder_radius_m > 0 ? "shoulder_radius_mm"
                                                : "radius_mm";
    s.fail(key, e.what());
  }
  return c;
}

}  // namespace modaltyre::contact

#pragma once
// A rigid road's height profile along the track (today's cleat generalised): points
// (x_m, height_m) with x strictly increasing, height above the reference plane, linear between
// points and level (the end heights) beyond them. CSV: x_m,height_m ('#' comments).
#include <string>
#include <vector>

namespace modaltyre::ground {

struct RoadProfile {
  std::string path = "<profile>";
  std::vector<double> x_m, height_m;
  /// Height at x [m].
  double height_at(double x_m) const;
  /// Slope dh/dx at x (0 beyond the ends; the right slope at a point).
  double slope_at(double x_m) const;
};

/// Limits of a profile file: points, |x| and |height|.
constexpr std::size_t kMaxProfilePoints = 1000000;
constexpr double kMaxProfileLength_m = 1e6;
constexpr double kMaxProfileHeight_m = 100;

/// Reads a profile CSV; every problem is an InputError naming file, line and column (fewer
/// than two points, x not strictly increasing, values out of range).
RoadProfile read_road_profile_csv(const std::string& path);

}  // namespace modaltyre::ground

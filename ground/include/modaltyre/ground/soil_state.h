#pragma once
// The soil's memory: the deepest sinkage z_max each ground point has been pressed to (the rut).
// A point is whatever the caller's grid makes it: a patch unit of a standing tyre in a load
// cycle, a lateral strip of the track in repeated passes. 0 is virgin soil.
#include <cstddef>
#include <vector>

#include "modaltyre/ground/pressure_sinkage.h"

namespace modaltyre::ground {

class SoilState {
 public:
  SoilState() = default;
  explicit SoilState(std::size_t points) : z_max_m_(points, 0.0) {}
  std::size_t points() const { return z_max_m_.size(); }
  double z_max_m(std::size_t i) const { return z_max_m_.at(i); }
  /// Records that point i was pressed to z (z_max only grows).
  void record(std::size_t i, double z_m);
  /// The surface depth of point i with no load on it: the rut.
  double rut_depth_m(const PressureSinkage& law, std::size_t i) const;
  /// The deepest z_max and the deepest rut over all points.
  double deepest_m() const;
  double deepest_rut_m(const PressureSinkage& law) const;
  const std::vector<double>& z_max() const { return z_max_m_; }

 private:
  std::vector<double> z_max_m_;
};

}  // namespace modaltyre::ground

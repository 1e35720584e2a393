#pragma once
// The 3D transient's cells on a deformable soil (docs/soil.md section 8.3): every cell of the 3D
// patch (cell_model.h) is its contact spring k (k_g with relaxation, else k_i, with the lumped
// residual in series) in series with the soil under its road area A_i = dy ds cos theta_i, as a
// 2D unit is (soil_contact.h) and as the 3D static footprint's cell is (contact/src/
// patch3d_soil.cc: t_i f + Z(f / A_i) = e). At the tip penetration g into the undisturbed
// surface a cell carries f = phi(g), the root of f / k + Z(f / A; z_max) = g, with Newton's
// stiffness d phi / d g = 1 / (1 / k + Z'(p) / A).
//
// One memory z_max per (column class, section) slot: the columns of a class share their
// trajectory (cell_model.h), so they press the same rut. Each class's row of sections is one
// SoilContact (the 2D unit row's memory, moved with the ground along the sections while rolling,
// recorded at every accepted step). Bekker's b is the 3D static footprint's at the scenario's
// largest load, b = min(width, length) iterated with it (contact/predictor.cc), fixed for the
// run.
#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <vector>

#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/transient/cell_model.h"
#include "modaltyre/transient/cell_system.h"
#include "modaltyre/transient/scenario.h"
#include "modaltyre/transient/soil_contact.h"

namespace modaltyre::transient {

class CellSoil {
 public:
  /// The soil of `ground` (a soil) under the cells of `cm`, Bekker's b fixed at
  /// `bekker_width_m`; `distance` the distance rolled D(t) [m] (empty: at rest).
  CellSoil(const CellModel& cm, const ground::GroundSettings& ground, double bekker_width_m,
           std::function<double(double)> distance = {});

  double bekker_width_m() const { return bekker_width_m_; }
  int classes() const { return static_cast<int>(rows_.size()); }
  /// The row of sections of class c (its memory, its last forces()).
  const SoilContact& row(int c) const { return *rows_[c]; }
  SoilContact& row(int c) { return *rows_[c]; }

  /// The memory from a static contact's soil depths (m x classes) at time t.
  void set_memory(const Eigen::MatrixXd& depth_m, double t = 0);

  /// The cell forces phi(g) in place of the penetrations g of the slots of `ranges` (class c's
  /// sections ranges[c] at slots offsets[c] ...), d phi / d g per slot into kd.
  void forces(double t, const std::vector<UnitRange>& ranges, const std::vector<int>& offsets,
              double* g, double* kd) const;
  /// An accepted step: moves the memory with the ground and records the depths of the last
  /// forces() (which must be at the accepted state).
  void accept(double t, const std::vector<UnitRange>& ranges);

  /// The soil surface's depth under slot (class c, section i) at the last forces() [m].
  double depth(int c, int i) const { return rows_[c]->depth(i); }
  /// The surface's depth unloaded (the rut) at time t [m].
  double rut_m(int c, int i, double t) const { return rows_[c]->rut_m(i, t); }
  /// The deepest depth under the loaded slots (forces f per slot) [m].
  double deepest_loaded_m(const std::vector<UnitRange>& ranges, const std::vector<int>& offsets,
                          const Eigen::VectorXd& f) const;
  /// sum over cells of f tan(alpha), tan(alpha) = -dZ/dx by central differences of the depths
  /// along each class's sections, every class times its multiplicity (soil_contact.h's R_c).
  double compaction_resistance_N(const std::vector<UnitRange>& ranges,
                                 const std::vector<int>& offsets, const Eigen::VectorXd& f) const;

 private:
  const CellModel& cm_;
  std::vector<std::unique_ptr<SoilContact>> rows_;
  double bekker_width_m_ = 0;
};

/// The 3D static footprint on the config's soil (contact::Patch3d with the soil under every
/// cell, virgin soil) under load_N: section and cell forces, approaches, sinking and the soil
/// depth per (section, class). Bekker's b fixed at bekker_width_m, or (0) iterated with the
/// footprint as `footprint` does; the b used into *bekker_used. ComputationError if it fails.
StaticCells static_soil_cells(const CellModel& cm, double load_N, double bekker_width_m = 0,
                              double* bekker_used = nullptr);

/// The soil of a 3D run under `plan`: Bekker's b of the static footprint at the scenario's
/// largest load, the ground moving with the distance rolled; the initial contact on it into
/// `initial` (the memory set from its depths), and the bounding contact (tread_window.h's
/// 2 F_max - F0) into `bound` (false when that footprint fails: every section then).
std::unique_ptr<CellSoil> cell_soil_for_plan(const CellModel& cm, const ScenarioPlan& plan,
                                             StaticCells& initial, StaticCells& bound,
                                             bool& bounded);

}  // namespace modaltyre::transient

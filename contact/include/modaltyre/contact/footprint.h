#pragma once
// Static footprint under load control (seed 001 sections 3.2-3.3): given the vertical load F_z
// (and optionally a horizontal force F_x at the axle), find the sinking, the contact length, the
// force and pressure on every patch unit and the deformed contour, with unilateral contact
// against a rigid flat road (no tension, no penetration).
//
// Horizontal force: with F_x != 0 every unit in contact carries f_x,i = (F_x / F_z) f_z,i
// (uniform use of adhesion along the patch); positive F_x points forward (+x). With F_x = 0 the
// contact is frictionless and the solution is symmetric about the contact centre.
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_model.h"

namespace modaltyre::contact {

struct LoadCase {
  double load_N = 0;              ///< F_z > 0
  double horizontal_force_N = 0;  ///< F_x
};

struct PatchUnit {
  double x_m = 0;         ///< deformed position along the road from the contact centre
  double dx_m = 0;        ///< road length the unit covers
  double fz_N = 0;        ///< vertical force on the unit
  double fx_N = 0;        ///< horizontal force on the unit
  double pressure_Pa = 0; ///< fz / (dx * contact width)
};

struct FootprintResult {
  LoadCase load;
  bool converged = false;
  std::string message;
  int iterations = 0;
  double sinking_m = 0;           ///< approach of axle and road
  double contact_length_m = 0;     ///< front_edge_x_m - rear_edge_x_m
  double rear_edge_x_m = 0;        ///< patch edges, interpolated between units
  double front_edge_x_m = 0;
  double equilibrium_residual = 0;      ///< |sum fz - F_z| / F_z
  double complementarity_residual = 0;  ///< max |f g| / (F_z sinking)
  std::vector<PatchUnit> units;         ///< units in contact, front to back ordered by x
  std::vector<double> contour_x_m;      ///< deformed tread surface of all candidate units
  std::vector<double> contour_height_m; ///< height above the road (0 in contact)
  std::vector<char> active;             ///< contact flags of the candidate units (warm start)

  double vertical_stiffness_N_m() const { return load.load_N / sinking_m; }
};

FootprintResult solve_footprint(const TyreModel& model, const LoadCase& load,
                                const std::vector<char>* warm_active = nullptr);

/// Solves the loads in order, each warm-started from the previous contact set.
std::vector<FootprintResult> solve_footprints(const TyreModel& model,
                                              const std::vector<LoadCase>& loads);

}  // namespace modaltyre::contact

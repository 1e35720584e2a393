#pragma once
// Static footprint under load control (seed 001 sections 3.2-3.3): given the vertical load F_z
// (and optionally a horizontal force F_x at the axle), find the sinking, the contact length, the
// force and pressure on every patch unit and the deformed contour, with unilateral contact
// against a rigid flat road (no tension, no penetration).
//
// Horizontal force: with F_x != 0 every unit in contact carries f_x,i = (F_x / F_z) f_z,i
// (uniform use of adhesion along the patch); positive F_x points forward (+x). With F_x = 0 the
// contact is frictionless and the solution is symmetric about the contact centre.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/solve_status.h"

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
  double soil_depth_m = 0; ///< on a soil: the ground's surface under the unit below the undisturbed surface
};

struct FootprintResult {
  LoadCase load;
  /// The contact solver's status, or failed when the patch reached the candidate window's edge.
  SolveStatus status = SolveStatus::failed;
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
  bool window_exceeded = false;  ///< failed: the contact reached the candidate window's edge
  /// On a soil (ground_patch.h): the deepest point of the ground below its undisturbed surface,
  /// the tyre's own deflection (sinking_m - soil_sinkage_m), Bekker's b used, and the ground's
  /// surface depth under every candidate unit (the rut where the unit is free). Zero / empty on
  /// a rigid road.
  bool on_soil = false;
  double soil_sinkage_m = 0, tyre_deflection_m = 0, bekker_width_m = 0;
  std::vector<double> soil_depth_m;

  bool ok() const { return modaltyre::ok(status); }
  double vertical_stiffness_N_m() const { return load.load_N / sinking_m; }
};

/// The largest candidate window the config reader accepts (half the circumference, at most 20000
/// units) [m], and the window a contact that reached the window's edge should try next: 1.5
/// times the current, at most that [mm, rounded up to 10 mm].
double max_window_m(const TyreConfig& config);
double suggested_window_mm(const TyreConfig& config);

/// The linear operator of one load case on the model's candidate units: the carcass kernels
/// (static or rolling) with a scale, the tread's compliance and the assembled vertical
/// compliance the contact problem sees. solve_footprint() uses the model's own; the effects of
/// predictor.h assemble others.
struct PatchOperator {
  const modal::LagKernels* kernels = nullptr;  ///< carcass transfer functions per lag
  double carcass_scale = 1;                     ///< multiplies every carcass kernel
  /// Tread radial compliance between units l apart, l = 0, 1, ... (one entry: independent
  /// springs, seed 001 eq. 6) [m/N].
  std::vector<double> tread_radial_lag;
  double tread_tangential_compliance = 0;  ///< per unit [m/N]
  double width_m = 0;                      ///< patch width for the pressure
  double horizontal_ratio = 0;             ///< F_x / F_z
  Eigen::MatrixXd compliance;              ///< vertical compliance of the candidates [m/N]
  /// The same compliance matrix-free; when set it is used and `compliance` may stay empty.
  /// Per solve (the operator caches FFT plans and is not thread-safe).
  std::shared_ptr<const solvers::ComplianceOperator> compliance_operator;
  bool symmetric = true;
};

/// The model's own operator for a load case (static kernels, tread springs of the config), with
/// the assembled compliance.
PatchOperator static_operator(const TyreModel& model, double horizontal_ratio);

/// The same without a horizontal force, matrix-free (vertical_compliance_operator): what
/// solve_footprint() uses. Nothing of size m x m is copied or built.
PatchOperator static_matrix_free_operator(const TyreModel& model);

/// Solves one load case with a given operator (F_x = load.horizontal_force_N must match the
/// operator's horizontal_ratio). `warm_active`: a previous result's `active` to start the
/// contact set from (empty: cold start).
FootprintResult solve_patch(const TyreModel& model, PatchOperator op, const LoadCase& load,
                            std::span<const char> warm_active = {});

FootprintResult solve_footprint(const TyreModel& model, const LoadCase& load,
                                std::span<const char> warm_active = {});

/// Solves the loads in order, each warm-started from the previous contact set.
std::vector<FootprintResult> solve_footprints(const TyreModel& model,
                                              const std::vector<LoadCase>& loads);

}  // namespace modaltyre::contact

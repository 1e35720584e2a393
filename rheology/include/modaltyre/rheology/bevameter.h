#pragma once
// Soil parameters from plate-sinkage (bevameter) tests (docs/soil.md section 6):
//   loading (Bekker):        p = (k_c / b + k_phi) z^n,            b the plate width
//   unloading (Wong):        p = p_max - k_u (z_max - z),  k_u = k_0 + A_u z_max
// (Wong, Theory of Ground Vehicles, 4th ed., 2008, eq. 2.45 and section 2.4.2; units as
// Wong's Table 2.3: p in kPa, z in m, k_c kN/m^(n+1), k_phi kN/m^(n+2), k_0 kN/m^3, A_u kN/m^4).
//
// File: plate_width_mm|plate_radius_mm,sinkage_mm,pressure_kPa[,cycle]. The plate's size says
// its shape, and Bekker's b is then the width of a rectangular plate or the radius of a circular
// one (Wong, Theory of Ground Vehicles, 4th ed., section 2.4: b is the smaller dimension of the
// contact, the width of a rectangle, the radius of a circle); a file with both columns, or with a
// plate_diameter_mm, is refused. Rows with cycle 0 (or no cycle column) are virgin loading; rows
// with cycle k >= 1 lie on the k-th unloading-reloading branch, which left the virgin curve at
// the largest sinkage of its rows (z_max). At least two plate sizes separate k_c from k_phi, and
// every plate needs two sinkages at least (else n cannot be told from k).
//
// Fit: n by a one-dimensional search (golden section on the residual), k_c and k_phi by linear
// least squares at each n (variable projection), on relative residuals (p_model - p) / p (a
// gauge's error is relative); standard errors from s^2 (J^T J)^-1 with the full Jacobian in
// (n, k_c, k_phi). Each cycle's k_u is the slope of its rows (linear least squares), then
// k_u = k_0 + A_u z_max over the cycles (two or more z_max for A_u; one: k_0 = k_u, A_u = 0).
#include <string>
#include <vector>

#include "modaltyre/rheology/report.h"

namespace modaltyre::rheology {

struct PlateRow {
  double bekker_b_m = 0;  ///< Bekker's b: the plate's width (rectangular) or radius (circular)
  double sinkage_m = 0, pressure_Pa = 0;
  int cycle = 0;
  int line = 0;
};

enum class PlateShape { rectangular, circular };

struct PlateData {
  std::string path = "<data>";
  PlateShape shape = PlateShape::rectangular;
  std::vector<PlateRow> rows;
};

/// "rectangular: b = the plate's width" or "circular: b = the plate's radius" (the output says
/// how b was taken).
std::string bekker_b_convention(PlateShape shape);

/// InputError naming file, line and column for a bad cell (non-positive width, negative
/// sinkage or pressure, a cycle that is not a whole number in [0, 1000]).
PlateData read_plate_sinkage_csv(const std::string& path);

struct BevameterResult {
  double n = 0, n_se = 0;
  double k_c = 0, k_c_se = 0;      ///< kN/m^(n+1)
  double k_phi = 0, k_phi_se = 0;  ///< kN/m^(n+2)
  bool has_unloading = false;
  double k0 = 0, k0_se = 0;  ///< kN/m^3
  double Au = 0, Au_se = 0;  ///< kN/m^4
  /// k_u = Au z_max through the origin (k0 = 0), the physical fit when k0 < 0 [kN/m^4].
  double Au_through_origin = 0;
  /// What the data cannot make physical (k0 < 0, n outside 0-2, k_c < 0), each with the data's
  /// reason; also in report.notes as "warning: ...".
  std::vector<std::string> warnings;
  FitReport report;
};

/// InputError: fewer than two plate sizes or four loading rows, a plate with one sinkage only,
/// data whose Jacobian cannot separate n, k_c and k_phi, or cycles without rows.
BevameterResult identify_bevameter(const PlateData& data);

struct ShearRow {
  double normal_stress_Pa = 0, displacement_m = 0, shear_stress_Pa = 0;
  int line = 0;
};

struct ShearData {
  std::string path = "<data>";
  std::vector<ShearRow> rows;
};

/// File: normal_stress_kPa,shear_displacement_mm,shear_stress_kPa.
ShearData read_shear_csv(const std::string& path);

struct ShearResult {
  double cohesion_kPa = 0, cohesion_se = 0;
  double friction_angle_deg = 0, friction_angle_se = 0;
  double K_mm = 0, K_se = 0;
  FitReport report;
};

/// Janosi-Hanamoto tau = (c + sigma tan phi)(1 - exp(-j / K)) fitted to all rows: K by a
/// one-dimensional search, c and tan phi by linear least squares at each K, on residuals
/// relative to each normal stress's largest shear stress; standard errors from the full
/// Jacobian. InputError: fewer than two normal stresses or five rows.
ShearResult identify_shear(const ShearData& data);

}  // namespace modaltyre::rheology

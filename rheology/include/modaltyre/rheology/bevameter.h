#pragma once
// Soil parameters from plate-sinkage (bevameter) tests (docs/soil.md section 6):
//   loading (Bekker):        p = (k_c / b + k_phi) z^n,            b the plate width
//   unloading (Wong):        p = p_max - k_u (z_max - z),  k_u = k_0 + A_u z_max
// (Wong, Theory of Ground Vehicles, 4th ed., 2008, eq. 2.45 and section 2.4.2; units as
// Wong's Table 2.3: p in kPa, z in m, k_c kN/m^(n+1), k_phi kN/m^(n+2), k_0 kN/m^3, A_u kN/m^4).
//
// File: plate_width_mm,sinkage_mm,pressure_kPa[,cycle]. Rows with cycle 0 (or no cycle column)
// are virgin loading; rows with cycle k >= 1 lie on the k-th unloading-reloading branch, which
// left the virgin curve at the largest sinkage of its rows (z_max). At least two plate widths
// separate k_c from k_phi.
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
  double plate_width_m = 0, sinkage_m = 0, pressure_Pa = 0;
  int cycle = 0;
  int line = 0;
};

struct PlateData {
  std::string path = "<data>";
  std::vector<PlateRow> rows;
};

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
  FitReport report;
};

/// InputError: fewer than two plate widths or three loading rows, or cycles without rows.
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

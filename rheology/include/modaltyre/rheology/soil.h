#pragma once
// Kelvin-Voigt deformable soil under a rigid wheel rolling in the driven mode
// (seed 000 eq. 23-28). Soil law sigma2 = E2 eps2 + eta2 deps2/dt (eq. 23); k_E = h_E / h_G the
// elastic share of the sinking (eq. 24). With a layer of thickness A, wheel radius r0, tread
// width B_tr, speed V, front contact angle alpha1 (loading zone nO) and rear angle alpha2
// (unloading zone Om), strains along the radius (docs/rheology.md derives them):
//   eps21 = r0 (cos phi - cos alpha1) / A,     deps21/dt =  V tan phi / A
//   eps22 = r0 (cos phi - cos alpha2) / A_c,   deps22/dt = -V tan phi / A_c,  A_c = A - (h_G - h_E)
// and stresses sigma21 = k_E (E2 eps21 + eta2 deps21/dt) (only the elastic share of the
// loading strain is carried by the Kelvin-Voigt element), sigma22 = E2 eps22 + eta2 deps22/dt.
// Equilibrium (eq. 25, 26):
//   P_Z = B_tr r0 [int_0^a1 sigma21 cos phi dphi + int_0^a2 sigma22 cos phi dphi]
//   P_X = B_tr r0 [int_0^a1 sigma21 sin phi dphi - int_0^a2 sigma22 sin phi dphi]
// is linear in (E2, eta2) (eq. 27, 28); all rows are solved together by least squares on
// relative residuals.
//
// File format:
// load_N,longitudinal_force_N,alpha1_deg,alpha2_deg,total_sinking_mm,elastic_sinking_mm,layer_mm,speed_m_s
#include <string>
#include <vector>

#include "modaltyre/rheology/report.h"

namespace modaltyre::rheology {

struct SoilRow {
  double load_N = 0.0;                ///< P_Z > 0
  double longitudinal_force_N = 0.0;  ///< P_X, rolling resistance of the towed wheel
  double alpha1_rad = 0.0;            ///< front contact angle, (0, pi/2)
  double alpha2_rad = 0.0;            ///< rear contact angle, (0, alpha1]
  double total_sinking_m = 0.0;       ///< h_G > 0
  double elastic_sinking_m = 0.0;     ///< h_E in (0, h_G]
  double layer_m = 0.0;               ///< A > h_G
  double speed_m_s = 0.0;             ///< V > 0
  int line = 0;
};

struct SoilData {
  std::string path = "<data>";
  std::vector<SoilRow> rows;
};

SoilData read_soil_rolling_csv(const std::string& path);

struct SoilOptions {
  double r0_m = 0.0;           ///< radius of the rigid test wheel, required
  double tread_width_m = 0.0;  ///< its width B_tr, required
};

/// Coefficients (a, b) with force = B_tr r0 (a E2 + b eta2) for the vertical (P_Z) and the
/// longitudinal (P_X) equilibrium of one row.
struct SoilCoefficients {
  double z_E = 0, z_eta = 0, x_E = 0, x_eta = 0;
};
SoilCoefficients soil_coefficients(const SoilRow& row, const SoilOptions& o);

/// Forces predicted by the model for a row (fills load_N and longitudinal_force_N).
SoilRow soil_forces(SoilRow row, double E2_Pa, double eta2_Pa_s, const SoilOptions& o);

struct SoilResult {
  double E2_Pa = 0.0, E2_se = 0.0, eta2_Pa_s = 0.0, eta2_se = 0.0;
  double k_E = 0.0, k_E_se = 0.0;
  std::vector<double> predicted_load_N, predicted_longitudinal_N;
  FitReport report;
};

/// InputError: fewer than two rows, inconsistent rows (named by line and column), missing
/// geometry, or rows that cannot separate E2 from eta2.
SoilResult identify_soil(const SoilData& data, const SoilOptions& o);

}  // namespace modaltyre::rheology

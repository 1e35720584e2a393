#pragma once
// Radial stiffness from the normal stress distribution in the contact patch
// (seed 000 eq. 8-12). The deformation law is sigma = K1 Delta_P with
// Delta_P = r0 - sqrt(x^2 + (r0 - h_Z)^2) at road abscissa x (eq. 1 geometry), so one stress
// profile gives K1 [Pa/m] and the deflection h_Z. Then
//   P_Z = 2 K1 B_tr r0^2 cos phi1 (phi1 - cos phi1 atanh(sin phi1))   eq. (8)
//   C_P = B3 K1,  B3 = B1 B_tr r0 / B2                                 eq. (12)
//
// File format: x_mm,stress_kPa with x measured along the road from the patch centre (below
// the axle); rows outside the patch (stress 0) are welcome and help to locate its ends.
#include <string>
#include <vector>

#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/report.h"

namespace modaltyre::rheology {

struct StressRow {
  double x_m = 0.0;
  double stress_Pa = 0.0;  ///< >= 0
  int line = 0;
};

struct StressData {
  std::string path = "<data>";
  std::vector<StressRow> rows;
};

StressData read_contact_stress_csv(const std::string& path);

struct ContactStressOptions {
  double r0_m = 0.0;             ///< free radius, required
  double tread_width_m = 0.0;    ///< B_tr, required (eq. 8 and 12)
  double contact_length_m = 0.0; ///< if > 0, fixes h_Z; else h_Z is fitted
  double B1 = kSeedB1;
  double B2 = kSeedB2;
};

/// Stress sigma = K1 Delta_P at abscissa x for the given deflection.
double contact_stress_law(double K1_Pa_per_m, double x_m, double deflection_m, double r0_m);
/// K1 from K_Z by eq. (11): K1 = B2 ((1 + p_W)/K_Z)^(4/3) / (2 B_tr r0^(2/3)).
double k1_eq11(double K_Z_m, double r0_m, double tread_width_m, double pressure_Pa,
               double B2 = kSeedB2);
/// C_P = B1 B_tr r0 K1 / B2, eq. (12).
double c_p_eq12(double K1_Pa_per_m, double r0_m, double tread_width_m, double B1 = kSeedB1,
                double B2 = kSeedB2);

struct ContactStressResult {
  double K1_Pa_per_m = 0.0, K1_se = 0.0;
  double deflection_m = 0.0, deflection_se_m = 0.0;
  double C_P = 0.0, C_P_se = 0.0;
  double load_N = 0.0;  ///< implied by eq. (8)
  FitReport report;
};

/// InputError: fewer than three rows, no positive stress, negative stress, missing geometry.
ContactStressResult identify_contact_stress(const StressData& data,
                                            const ContactStressOptions& options);

}  // namespace modaltyre::rheology

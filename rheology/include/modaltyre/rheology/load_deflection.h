#pragma once
// Kelvin-Voigt radial stiffness from a static load-deflection test (seed 000 eq. 2-7).
//
//   h_Z = K_Z P_Z^(3/4) / (1 + p_W)          eq. (3), p_W gauge pressure in bar
//   C_P = r0^(1/3) ((1+p_W)/K_Z)^(4/3) (1-cos phi1)^(4/3) / (2 (sin phi1 - phi1 cos phi1))  eq. (5)
//   C_P = B1 r0^(1/3) ((1+p_W)/K_Z)^(4/3) / 2                                            eq. (7)
//
// File format: load_N,pressure_kPa,deflection_mm (pressure gauge; '#' comment lines allowed).
// K_Z is carried in SI (m N^-3/4) and reported in mm N^-3/4 as the seed writes it.
#include <string>
#include <vector>

#include "modaltyre/rheology/report.h"

namespace modaltyre::rheology {

/// The seed's slope factors of eq. (6) and (10) (values published in seed 000).
inline constexpr double kSeedB1 = 1.5526;
inline constexpr double kSeedB2 = 1.6669;

struct LoadDeflectionRow {
  double load_N = 0.0;        ///< P_Z > 0
  double pressure_Pa = 0.0;   ///< gauge inflation pressure p_W >= 0
  double deflection_m = 0.0;  ///< h_Z > 0
  int line = 0;               ///< line in the file (0 for synthetic rows)
};

struct LoadDeflectionData {
  std::string path = "<data>";
  std::vector<LoadDeflectionRow> rows;
};

/// Reads load_N,pressure_kPa,deflection_mm; InputError for non-positive load or deflection,
/// negative pressure, naming file, line and column.
LoadDeflectionData read_load_deflection_csv(const std::string& path);

struct LoadDeflectionOptions {
  double r0_m = 0.0;                   ///< free radius r0, required (> 0) for C_P
  double reference_pressure_Pa = -1.0; ///< pressure at which C_P is given; < 0: median of data
  double B1 = kSeedB1;                 ///< slope factor of eq. (6)
};

/// h_Z from eq. (3) with K_Z in m N^-3/4.
double law_deflection(double K_Z_m, double load_N, double pressure_Pa);
/// K_Z from two loads at one pressure (seed 000, first formula after eq. 3).
double k_z_two_loads(double load1_N, double defl1_m, double load2_N, double defl2_m,
                     double pressure_Pa);
/// K_Z from two pressures at one load (seed 000, second formula after eq. 3); p1 > p2.
double k_z_two_pressures(double pressure1_Pa, double defl1_m, double pressure2_Pa,
                         double defl2_m, double load_N);
/// C_P from eq. (5) at a load (its deflection taken from eq. 3 at that pressure) [N/(m rad)].
double c_p_eq5(double K_Z_m, double r0_m, double pressure_Pa, double load_N);
/// C_P from the closed form eq. (7) [N/(m rad)].
double c_p_eq7(double K_Z_m, double r0_m, double pressure_Pa, double B1 = kSeedB1);

struct LoadDeflectionResult {
  double K_Z_m = 0.0, K_Z_se_m = 0.0;  ///< least squares over all rows [m N^-3/4]
  double C_P_eq5 = 0.0, C_P_eq5_se = 0.0;  ///< mean of eq. (5) over the loads [N/(m rad)]
  double C_P_eq7 = 0.0, C_P_eq7_se = 0.0;  ///< eq. (7) [N/(m rad)]
  double reference_pressure_Pa = 0.0;
  FitReport report;
};

/// K_Z by least squares h = K_Z x, x = P^(3/4)/(1+p), plus the two-load and two-pressure
/// formulas where the data allow them, and C_P by eq. (5) and (7). InputError for fewer than
/// two rows or rows that do not differ in load or pressure.
LoadDeflectionResult identify_load_deflection(const LoadDeflectionData& data,
                                              const LoadDeflectionOptions& options);

}  // namespace modaltyre::rheology

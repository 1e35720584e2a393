#pragma once
// What a Magic Formula .tir file says about a standing tyre: its size, its vertical law and its
// contact-patch law, in SI (the file's [UNITS] converted). A file that is not a Magic Formula
// property file is refused here with a sentence saying what it is (an FTire file shares the
// .tir extension).
//
// Which vertical law: MF-Tyre/MF-Swift 6.x (FITTYP >= 61) use (A3.3) with VERTICAL_STIFFNESS,
// Q_FZ2 and PFZ1 (mf_formulas.h). Older files (MF-Tyre 5.x, PAC2002) use their
// [DEFLECTION_LOAD_CURVE] table when they carry one (as MSC Adams does), else (A3.3) with
// VERTICAL_STIFFNESS or, without it, an explicit Q_FZ1. The contact patch: Q_RA1/Q_RA2 (A3.7)
// and Q_RB1/Q_RB2 (A3.8); a quantity the file does not carry is absent with its reason.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/tir/mf_formulas.h"
#include "modaltyre/tir/mf_longitudinal.h"
#include "modaltyre/tir/tir_file.h"
#include "modaltyre/tir/tir_units.h"

namespace modaltyre::tir {

struct MfTyre {
  std::string path;
  int fittyp = 0;                  ///< [MODEL] FITTYP, 0 when the file has none
  std::vector<std::string> notes;  ///< the reader's notes (TirFile::notes)
  std::string model_name;          ///< e.g. "MF-Tyre 6.2 (FITTYP 62)", "PAC2002"
  TirUnits units;
  double unloaded_radius_m = 0;   ///< UNLOADED_RADIUS
  std::optional<double> width_m;  ///< WIDTH, nominal section width
  std::optional<double> rim_radius_m, aspect_ratio;
  double inflation_pressure_Pa = 0;  ///< INFLPRES (0: not given; the law is then at NOMPRES)

  MfVerticalLaw vertical;  ///< (A3.3); fnomin_N is always set
  bool table_law = false;  ///< the vertical law is the [DEFLECTION_LOAD_CURVE] table
  std::vector<double> table_deflection_m, table_load_N;
  std::string vertical_source;  ///< which keys or table make the vertical law

  std::optional<double> q_ra1, q_ra2, q_rb1, q_rb2;
  std::string length_reason;  ///< why the file gives no length law (empty when it does)
  std::string width_reason;

  // The rolling wheel's laws (mf_longitudinal.h), each absent with its reason when the file
  // lacks it: the longitudinal force needs PCX1, PDX1 and PKX1, the rolling moment QSY1, the
  // effective radius Q_RE0 (other coefficients are 0 when not stated, as MF evaluators take
  // them). Files before MF 6.1 (FITTYP < 61) state M_y = -R0 F_z (...) without QSY7/QSY8: read
  // as QSY7 = 1, QSY8 = 0, the same law.
  double longvl_m_s = 0;  ///< [MODEL] LONGVL (0: not given; the speed terms of M_y then vanish)
  MfScaling scaling;      ///< [SCALING_COEFFICIENTS] (1 when not stated; LMUV 0)
  std::optional<MfLongitudinal> longitudinal;
  std::optional<MfRolling> rolling;
  std::optional<MfEffectiveRadius> effective_radius;
  std::string longitudinal_reason, rolling_reason, radius_reason;
  /// R0, FNOMIN, LONGVL, NOMPRES, INFLPRES and C_z at INFLPRES, for those laws.
  MfBasis mf_basis() const;

  /// Vertical load at a deflection, at the file's INFLPRES; nullopt outside the law (beyond a
  /// table's last point or a falling (A3.3)).
  std::optional<double> load_N(double deflection_m) const;
  /// Vertical stiffness C_z at INFLPRES (A3.5); for a table law the secant at FNOMIN.
  double vertical_stiffness_N_m() const;
  /// Contact length 2a and width 2b at a load (A3.7-A3.8, rho_z = F_z / C_z).
  std::optional<double> length_m(double load_N) const;
  std::optional<double> width_at_m(double load_N) const;
};

/// Interprets a parsed file; InputError (file, line, SECTION.KEY) for a file that is not a Magic
/// Formula file, lacks UNLOADED_RADIUS, FNOMIN or a vertical law, or has values out of range.
/// RIM_RADIUS and ASPECT_RATIO, which no law uses, are left out with a note instead.
MfTyre interpret_tir(const TirFile& file);

/// read_tir + interpret_tir.
MfTyre read_mf_tyre(const std::string& path);

}  // namespace modaltyre::tir

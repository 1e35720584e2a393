// Interpretation of a parsed .tir file as a Magic Formula tyre (mf_tyre.h).
#include "modaltyre/tir/mf_tyre.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::tir {
namespace {

std::string uppercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// Whether the file names FTire anywhere: sections, keys, values or header comments.
bool mentions_ftire(const TirFile& f) {
  const auto has = [](const std::string& s) {
    return uppercase(s).find("FTIRE") != std::string::npos;
  };
  if (std::any_of(f.comments.begin(), f.comments.end(), has)) return true;
  for (const auto& s : f.sections) {
    if (has(s.name)) return true;
    for (const auto& [key, value] : s.entries) {
      if (has(key) || has(value.text)) return true;
    }
  }
  return false;
}

class Reader {
 public:
  explicit Reader(const TirFile& f) : f_(f), units_(read_units(f)) {}

  const TirUnits& units() const { return units_; }

  [[noreturn]] void fail(const std::string& section, const std::string& key,
                         const std::string& message) const {
    const TirValue* v = f_.value(section, key);
    throw InputError({f_.path, v ? v->line : 0, section + "." + key}, message);
  }

  /// The SI value of SECTION.KEY, checked against [min, max] (SI); nullopt when absent.
  std::optional<double> number(const std::string& section, const std::string& key, Dimension d,
                               double min, double max, const char* unit) const {
    const TirValue* v = f_.value(section, key);
    if (!v) return std::nullopt;
    if (const auto why = problem(*v, d, min, max, unit)) fail(section, key, *why);
    return *v->number * units_.to_si(d);
  }

  /// SECTION.KEY for a key no law uses (stated for the record, e.g. ASPECT_RATIO): a value that
  /// is not a number or is out of range is left out with a note, not a refusal of the file
  /// (issue 20: keys the model does not use are kept, not rejected).
  std::optional<double> informative(const std::string& section, const std::string& key, Dimension d,
                                    double min, double max, const char* unit,
                                    std::vector<std::string>& notes) const {
    const TirValue* v = f_.value(section, key);
    if (!v) return std::nullopt;
    if (const auto why = problem(*v, d, min, max, unit)) {
      notes.push_back(format_location({f_.path, v->line, section + "." + key},
                                      *why + "; no law uses it: left out"));
      return std::nullopt;
    }
    return *v->number * units_.to_si(d);
  }

  /// Why a value is unusable: not a number, or outside [min, max] after [UNITS]; else nullopt.
  std::optional<std::string> problem(const TirValue& v, Dimension d, double min, double max,
                                     const char* unit) const {
    if (!v.number) return "'" + printable(v.text) + "' is not a number";
    const double si = *v.number * units_.to_si(d);
    if ((si >= min && si <= max) && std::isfinite(si)) return std::nullopt;
    std::string shown = num(*v.number);
    if (units_.to_si(d) != 1) shown += " (" + num(si) + " " + unit + ")";
    return shown + " is outside " + num(min) + " .. " + num(max) + (*unit ? " " : "") + unit +
           (d == Dimension::none ? "" : " (after [UNITS])");
  }

  double required(const std::string& section, const std::string& key, Dimension d, double min,
                  double max, const char* unit, const std::string& why) const {
    if (auto v = number(section, key, d, min, max, unit)) return *v;
    throw InputError({f_.path, 0, section + "." + key}, "missing: " + why);
  }

 private:
  const TirFile& f_;
  TirUnits units_;
};

// The model a file holds: refuses what is not a Magic Formula property file.
void identify_model(const TirFile& f, MfTyre& t) {
  const TirValue* fittyp = f.value("MODEL", "FITTYP");
  const TirValue* format = f.value("MODEL", "PROPERTY_FILE_FORMAT");
  const std::string fmt = format ? uppercase(format->text) : "";
  if (fittyp) {
    if (!fittyp->number || *fittyp->number != std::floor(*fittyp->number) || *fittyp->number < 1 ||
        *fittyp->number > 999) {
      throw InputError({f.path, fittyp->line, "MODEL.FITTYP"},
                       "'" + printable(fittyp->text) + "' is not a Magic Formula version number");
    }
    t.fittyp = static_cast<int>(*fittyp->number);
    // The Magic Formula versions writers state (MSC Adams' and MF-Tool's manuals, mfeval):
    // 5 PAC2002, 6 and 21 MF-Tyre 5.x, 61 MF-Tyre 6.1, 62 MF-Tyre/MF-Swift 6.2. Any other number
    // is another model or a typing error, whose laws this reader would only guess.
    constexpr int kKnownFittyp[] = {5, 6, 21, 61, 62};
    if (std::find(std::begin(kKnownFittyp), std::end(kKnownFittyp), t.fittyp) ==
        std::end(kKnownFittyp)) {
      throw InputError({f.path, fittyp->line, "MODEL.FITTYP"},
                       std::to_string(t.fittyp) +
                           " is not a Magic Formula version this reader knows: 5 (PAC2002), "
                           "6 or 21 (MF-Tyre 5.x), 61 (MF-Tyre 6.1), 62 (MF-Tyre/MF-Swift 6.2)");
    }
    t.model_name = t.fittyp == 61   ? "MF-Tyre 6.1 (FITTYP 61)"
                   : t.fittyp == 62 ? "MF-Tyre/MF-Swift 6.2 (FITTYP 62)"
                                    : "Magic Formula, FITTYP " + std::to_string(t.fittyp);
    if (!fmt.empty()) t.model_name += ", " + printable(format->text);
    return;
  }
  if (fmt.rfind("PAC", 0) == 0 || fmt.rfind("MF", 0) == 0) {
    t.model_name = printable(format->text);
    return;
  }
  if (mentions_ftire(f)) {
    throw InputError({f.path, 0, ""},
                     "is an FTire tyre model file (cosin's FTire uses the .tir extension too), "
                     "not a Magic Formula file; modaltyre tir reads MF-Tyre 5.x/6.x and "
                     "MF-Swift property files, which state [MODEL] FITTYP");
  }
  if (format) {
    throw InputError({f.path, format->line, "MODEL.PROPERTY_FILE_FORMAT"},
                     "is a property file of the '" + printable(format->text) +
                         "' tyre model, not a Magic Formula (MF-Tyre/MF-Swift) file");
  }
  throw InputError({f.path, 0, "MODEL.FITTYP"},
                   "no [MODEL] FITTYP or PROPERTY_FILE_FORMAT: not an MF-Tyre/MF-Swift "
                   "property file");
}

// [DEFLECTION_LOAD_CURVE]: two columns (deflection, load), deflection strictly increasing.
void read_table(const TirFile& f, const Reader& r, MfTyre& t) {
  const TirSection* s = f.section("DEFLECTION_LOAD_CURVE");
  if (!s || s->table.rows.empty()) return;
  const TirTable& tab = s->table;
  if (tab.rows.front().size() != 2) {
    throw InputError(
        {f.path, tab.row_lines.front(), "DEFLECTION_LOAD_CURVE"},
        "needs two columns (deflection, load); has " + std::to_string(tab.rows.front().size()));
  }
  const double to_m = r.units().to_si(Dimension::length);
  const double to_N = r.units().to_si(Dimension::force);
  for (std::size_t i = 0; i < tab.rows.size(); ++i) {
    const double d = tab.rows[i][0] * to_m, load = tab.rows[i][1] * to_N;
    if (d < 0 || load < 0 || (i > 0 && !(d > t.table_deflection_m.back()))) {
      throw InputError({f.path, tab.row_lines[i], "DEFLECTION_LOAD_CURVE"},
                       "deflections must be >= 0 and strictly increasing, loads >= 0");
    }
    t.table_deflection_m.push_back(d);
    t.table_load_N.push_back(load);
  }
  if (t.table_deflection_m.size() < 2) {
    throw InputError({f.path, tab.row_lines.front(), "DEFLECTION_LOAD_CURVE"},
                     "a deflection-load table needs at least two rows");
  }
}

void read_vertical(const TirFile& f, const Reader& r, MfTyre& t) {
  MfVerticalLaw& v = t.vertical;
  v.unloaded_radius_m = t.unloaded_radius_m;
  v.fnomin_N = r.required("VERTICAL", "FNOMIN", Dimension::force, 1, 1e7, "N",
                          "the nominal load FNOMIN is needed for the vertical law");
  v.q_fz2 = r.number("VERTICAL", "Q_FZ2", Dimension::none, -1e6, 1e6, "").value_or(0);
  v.pfz1 = r.number("VERTICAL", "PFZ1", Dimension::none, -100, 100, "").value_or(0);
  v.nominal_pressure_Pa =
      r.number("OPERATING_CONDITIONS", "NOMPRES", Dimension::pressure, 1e3, 1e9, "Pa").value_or(0);
  const auto stiffness =
      r.number("VERTICAL", "VERTICAL_STIFFNESS", Dimension::stiffness, 1e3, 1e10, "N/m");
  const auto q_fz1 = r.number("VERTICAL", "Q_FZ1", Dimension::none, 1e-6, 1e6, "");
  read_table(f, r, t);
  const bool mf6 = t.fittyp >= 61;
  if (!t.table_deflection_m.empty() && (!mf6 || (!stiffness && !q_fz1))) {
    t.table_law = true;
    t.vertical_source = "[DEFLECTION_LOAD_CURVE] table (" +
                        std::to_string(t.table_deflection_m.size()) + " points)";
  }
  if (stiffness) {
    const auto q1 = q_fz1_from_stiffness(*stiffness, v.unloaded_radius_m, v.fnomin_N, v.q_fz2);
    if (!q1) {
      r.fail("VERTICAL", "Q_FZ2",
             "Q_FZ2 = " + num(v.q_fz2) +
                 " leaves no real Q_FZ1 = sqrt((C_z R0/F_z0)^2 - 4 Q_FZ2) "
                 "(Pacejka 2012 eq. A3.4) with VERTICAL_STIFFNESS = " +
                 num(*stiffness) + " N/m");
    }
    v.vertical_stiffness_N_m = *stiffness;
    v.q_fz1 = *q1;
    if (!t.table_law) {
      // Name only the keys the file gives: without Q_FZ2 the law is linear.
      t.vertical_source = std::string("VERTICAL_STIFFNESS") +
                          (f.value("VERTICAL", "Q_FZ2") ? ", Q_FZ2" : " (linear: no Q_FZ2)") +
                          (f.value("VERTICAL", "PFZ1") ? ", PFZ1" : "") +
                          " (Pacejka 2012 A3.3-A3.5)";
    }
  } else if (q_fz1) {
    const auto cz = stiffness_from_q_fz(*q_fz1, v.q_fz2, v.unloaded_radius_m, v.fnomin_N);
    if (!cz) r.fail("VERTICAL", "Q_FZ2", "Q_FZ1 and Q_FZ2 give no positive stiffness at FNOMIN");
    v.q_fz1 = *q_fz1;
    v.vertical_stiffness_N_m = *cz;
    if (!t.table_law) t.vertical_source = "Q_FZ1, Q_FZ2, PFZ1 (Pacejka 2012 A3.3)";
  } else if (!t.table_law) {
    throw InputError({f.path, 0, "VERTICAL.VERTICAL_STIFFNESS"},
                     "missing, and the file has neither Q_FZ1 nor a [DEFLECTION_LOAD_CURVE] "
                     "table: it states no vertical law");
  }
}

void read_patch(const Reader& r, MfTyre& t) {
  // A3.7 and A3.8 start with Q_RA1 sqrt(x) and Q_RB1 x^(1/3): a lightly loaded tyre's length and
  // width grow with them, so they are positive (a negative one gives negative lengths). The
  // second coefficients may be negative (the laws then bend over; MfTyre::length_m gives no
  // value where a law has fallen to zero).
  constexpr double kTiny = 1e-9;
  t.q_ra1 = r.number("CONTACT_PATCH", "Q_RA1", Dimension::none, kTiny, 1e3, "");
  t.q_ra2 = r.number("CONTACT_PATCH", "Q_RA2", Dimension::none, -1e3, 1e3, "");
  t.q_rb1 = r.number("CONTACT_PATCH", "Q_RB1", Dimension::none, kTiny, 1e3, "");
  t.q_rb2 = r.number("CONTACT_PATCH", "Q_RB2", Dimension::none, -1e3, 1e3, "");
  // Which of a pair is missing: "no Q_RA1 and Q_RA2", or "Q_RB1 but no Q_RB2".
  const auto missing = [](const std::optional<double>& a, const std::optional<double>& b,
                          const std::string& na, const std::string& nb) {
    if (!a && !b) return "the file has no [CONTACT_PATCH] " + na + " and " + nb;
    return "the file has [CONTACT_PATCH] " + (a ? na : nb) + " but no " + (a ? nb : na);
  };
  if (!t.q_ra1 || !t.q_ra2) {
    t.length_reason = missing(t.q_ra1, t.q_ra2, "Q_RA1", "Q_RA2") + " (the MF 6.x length law)";
    t.q_ra1.reset();
    t.q_ra2.reset();
  }
  if (!t.q_rb1 || !t.q_rb2) {
    t.width_reason = missing(t.q_rb1, t.q_rb2, "Q_RB1", "Q_RB2") + " (the MF 6.x width law)";
    t.q_rb1.reset();
    t.q_rb2.reset();
  } else if (!t.width_m) {
    t.width_reason = "the file has Q_RB1 and Q_RB2 but no [DIMENSION] WIDTH, which (A3.8) scales";
    t.q_rb1.reset();
    t.q_rb2.reset();
  }
}

// [LONGITUDINAL_COEFFICIENTS], [ROLLING_COEFFICIENTS], the effective radius' keys of
// [VERTICAL], [SCALING_COEFFICIENTS] and LONGVL. Coefficients are dimensionless numbers; the
// bounds only refuse what no tyre states (a typing error, a value in the wrong unit).
void read_rolling_wheel(const TirFile& f, const Reader& r, MfTyre& t) {
  constexpr double kBig = 1e6;
  const auto coef = [&](const char* section, const char* key, double fallback) {
    return r.number(section, key, Dimension::none, -kBig, kBig, "").value_or(fallback);
  };
  t.longvl_m_s = r.number("MODEL", "LONGVL", Dimension::speed, 0, 1e3, "m/s").value_or(0);
  const char* sc = "SCALING_COEFFICIENTS";
  t.scaling = MfScaling{coef(sc, "LFZO", 1), coef(sc, "LCX", 1),  coef(sc, "LMUX", 1),
                        coef(sc, "LEX", 1),  coef(sc, "LKX", 1),  coef(sc, "LHX", 1),
                        coef(sc, "LVX", 1),  coef(sc, "LMUV", 0), coef(sc, "LMY", 1)};
  const char* lo = "LONGITUDINAL_COEFFICIENTS";
  if (f.value(lo, "PCX1") && f.value(lo, "PDX1") && f.value(lo, "PKX1")) {
    MfLongitudinal c;
    double* slots[] = {&c.pcx1, &c.pdx1, &c.pdx2, &c.pdx3, &c.pex1, &c.pex2, &c.pex3,
                       &c.pex4, &c.pkx1, &c.pkx2, &c.pkx3, &c.phx1, &c.phx2, &c.pvx1,
                       &c.pvx2, &c.ppx1, &c.ppx2, &c.ppx3, &c.ppx4};
    const char* keys[] = {"PCX1", "PDX1", "PDX2", "PDX3", "PEX1", "PEX2", "PEX3",
                          "PEX4", "PKX1", "PKX2", "PKX3", "PHX1", "PHX2", "PVX1",
                          "PVX2", "PPX1", "PPX2", "PPX3", "PPX4"};
    for (std::size_t i = 0; i < std::size(keys); ++i) *slots[i] = coef(lo, keys[i], 0);
    t.longitudinal = c;
  } else {
    t.longitudinal_reason =
        "the file has no [LONGITUDINAL_COEFFICIENTS] PCX1, PDX1 and PKX1 (the pure-slip force)";
  }
  const char* ro = "ROLLING_COEFFICIENTS";
  if (f.value(ro, "QSY1")) {
    MfRolling q;
    q.qsy1 = coef(ro, "QSY1", 0), q.qsy2 = coef(ro, "QSY2", 0), q.qsy3 = coef(ro, "QSY3", 0);
    q.qsy4 = coef(ro, "QSY4", 0), q.qsy5 = coef(ro, "QSY5", 0), q.qsy6 = coef(ro, "QSY6", 0);
    // Before MF 6.1 the law is -R0 F_z (...) (Pacejka 2012 4.E70 with no load exponent).
    const bool mf6 = t.fittyp >= 61;
    q.qsy7 = mf6 ? coef(ro, "QSY7", 0) : 1;
    q.qsy8 = mf6 ? coef(ro, "QSY8", 0) : 0;
    t.rolling = q;
  } else {
    t.rolling_reason = "the file has no [ROLLING_COEFFICIENTS] QSY1 (the rolling resistance)";
  }
  if (f.value("VERTICAL", "Q_RE0")) {
    const char* ve = "VERTICAL";
    t.effective_radius =
        MfEffectiveRadius{coef(ve, "Q_RE0", 1), coef(ve, "Q_V1", 0), coef(ve, "BREFF", 0),
                          coef(ve, "DREFF", 0), coef(ve, "FREFF", 0)};
  } else {
    t.radius_reason = "the file has no [VERTICAL] Q_RE0 (the effective rolling radius, A3.6)";
  }
}

}  // namespace

MfBasis MfTyre::mf_basis() const {
  MfBasis b;
  b.unloaded_radius_m = unloaded_radius_m;
  b.fnomin_N = vertical.fnomin_N;
  b.longvl_m_s = longvl_m_s;
  b.nominal_pressure_Pa = vertical.nominal_pressure_Pa;
  b.pressure_Pa = inflation_pressure_Pa;
  b.vertical_stiffness_N_m = vertical_stiffness_N_m();
  return b;
}

std::optional<double> MfTyre::load_N(double deflection_m) const {
  if (deflection_m < 0) return std::nullopt;
  if (!table_law) {
    const MfVerticalLaw& v = vertical;
    // Past the maximum of a falling (A3.3) the law no longer describes a tyre.
    if (v.q_fz2 < 0 && deflection_m / v.unloaded_radius_m > -v.q_fz1 / (2 * v.q_fz2)) {
      return std::nullopt;
    }
    return mf_load_N(v, deflection_m, inflation_pressure_Pa);
  }
  const auto& d = table_deflection_m;
  if (deflection_m < d.front() || deflection_m > d.back()) return std::nullopt;
  const auto it = std::upper_bound(d.begin(), d.end(), deflection_m);
  const std::size_t i =
      std::min<std::size_t>(std::max<std::ptrdiff_t>(it - d.begin(), 1), d.size() - 1);
  const double w = (deflection_m - d[i - 1]) / (d[i] - d[i - 1]);
  return table_load_N[i - 1] + w * (table_load_N[i] - table_load_N[i - 1]);
}

double MfTyre::vertical_stiffness_N_m() const {
  if (vertical.vertical_stiffness_N_m > 0)
    return mf_vertical_stiffness(vertical, inflation_pressure_Pa);
  // Table law without VERTICAL_STIFFNESS: the secant through the table's point nearest FNOMIN.
  std::size_t best = 1;
  for (std::size_t i = 1; i < table_load_N.size(); ++i) {
    if (std::abs(table_load_N[i] - vertical.fnomin_N) <
        std::abs(table_load_N[best] - vertical.fnomin_N)) {
      best = i;
    }
  }
  return table_load_N[best] / table_deflection_m[best];
}

std::optional<double> MfTyre::length_m(double load) const {
  if (!q_ra1 || !q_ra2) return std::nullopt;
  const double a =
      mf_half_length_m(unloaded_radius_m, *q_ra1, *q_ra2, load / vertical_stiffness_N_m());
  if (!(a > 0)) return std::nullopt;  // past where a negative Q_RA2 brings the law to zero
  return 2 * a;
}

std::optional<double> MfTyre::width_at_m(double load) const {
  if (!q_rb1 || !q_rb2 || !width_m) return std::nullopt;
  const double b =
      mf_half_width_m(unloaded_radius_m, *width_m, *q_rb1, *q_rb2, load / vertical_stiffness_N_m());
  if (!(b > 0)) return std::nullopt;  // past where a negative Q_RB2 brings the law to zero
  return 2 * b;
}

MfTyre interpret_tir(const TirFile& file) {
  MfTyre t;
  t.path = file.path;
  t.notes = file.notes;
  identify_model(file, t);
  const Reader r(file);
  t.units = r.units();
  t.unloaded_radius_m = r.required("DIMENSION", "UNLOADED_RADIUS", Dimension::length, 0.02, 10, "m",
                                   "the unloaded radius R0 scales every law");
  t.width_m = r.number("DIMENSION", "WIDTH", Dimension::length, 0.005, 10, "m");
  t.rim_radius_m =
      r.informative("DIMENSION", "RIM_RADIUS", Dimension::length, 0.005, 10, "m", t.notes);
  t.aspect_ratio =
      r.informative("DIMENSION", "ASPECT_RATIO", Dimension::none, 0.01, 5, "", t.notes);
  t.inflation_pressure_Pa =
      r.number("OPERATING_CONDITIONS", "INFLPRES", Dimension::pressure, 1e3, 1e9, "Pa").value_or(0);
  read_vertical(file, r, t);
  if (!(t.vertical_stiffness_N_m() > 0) || !std::isfinite(t.vertical_stiffness_N_m())) {
    throw InputError({file.path, 0, "VERTICAL"},
                     "the vertical law gives no positive stiffness at INFLPRES (PFZ1 too "
                     "negative?)");
  }
  read_patch(r, t);
  read_rolling_wheel(file, r, t);
  return t;
}

MfTyre read_mf_tyre(const std::string& path) { return interpret_tir(read_tir(path)); }

}  // namespace modaltyre::tir

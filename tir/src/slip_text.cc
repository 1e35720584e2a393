// The .tir text of the longitudinal laws (slip_text.h).
#include "modaltyre/tir/slip_text.h"

#include <cstdio>
#include <sstream>
#include <string>

#include "tir_text.h"

namespace modaltyre::tir {
namespace {

using detail::comment_line;
using detail::key_line;
using detail::number_text;

std::string fixed(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string percent(const Residual& r) {
  return "RMS " + fixed(100 * r.rms, 2) + " %, max " + fixed(100 * r.max, 2) + " %";
}

/// The MF 6.2 scaling factors: all 1 (the fit is the model's own tyre, unscaled).
constexpr const char* kScaling[][2] = {
    {"LFZO", "Scale factor of nominal (rated) load"},
    {"LCX", "Scale factor of Fx shape factor"},
    {"LMUX", "Scale factor of Fx peak friction coefficient"},
    {"LEX", "Scale factor of Fx curvature factor"},
    {"LKX", "Scale factor of Fx slip stiffness"},
    {"LHX", "Scale factor of Fx horizontal shift"},
    {"LVX", "Scale factor of Fx vertical shift"},
    {"LCY", "Scale factor of Fy shape factor"},
    {"LMUY", "Scale factor of Fy peak friction coefficient"},
    {"LEY", "Scale factor of Fy curvature factor"},
    {"LKY", "Scale factor of Fy cornering stiffness"},
    {"LKYC", "Scale factor of Fy camber stiffness"},
    {"LKZC", "Scale factor of Mz camber stiffness"},
    {"LHY", "Scale factor of Fy horizontal shift"},
    {"LVY", "Scale factor of Fy vertical shift"},
    {"LTR", "Scale factor of peak of pneumatic trail"},
    {"LRES", "Scale factor for offset of Mz residual torque"},
    {"LXAL", "Scale factor of alpha influence on Fx"},
    {"LYKA", "Scale factor of kappa influence on Fy"},
    {"LVYKA", "Scale factor of kappa induced Fy"},
    {"LS", "Scale factor of moment arm of Fx"},
    {"LMX", "Scale factor of Mx overturning moment"},
    {"LVMX", "Scale factor of Mx vertical shift"},
    {"LMY", "Scale factor of rolling resistance torque"},
    {"LMP", "Scale factor of Mz parking torque"},
};

void section(std::ostream& s, const char* dashes_name, const char* name) {
  s << "$" << dashes_name << "\n[" << name << "]\n";
}

}  // namespace

void write_slip_comments(std::ostream& s, const TirSlipFit& f) {
  std::ostringstream runs;
  runs << "longitudinal force (pure slip), rolling resistance and effective rolling radius "
          "fitted to the model's steady rolling on a prescribed wheel (as its FMU runs it: hub "
          "held at the static sinking of "
       << f.curves.size() << " loads, F_z " << fixed(f.fz_min_N, 0) << " to "
       << fixed(f.fz_max_N, 0) << " N rolling, constant speed and spin) at LONGVL "
       << fixed(f.basis.longvl_m_s * 3.6, 1) << " km/h, kappa " << number_text(f.kappa_min)
       << " to " << number_text(f.kappa_max) << " from R_e of free rolling, road mu "
       << number_text(f.mu);
  comment_line(s, runs.str());
  if (!f.free_runs.empty()) {
    std::ostringstream speeds;
    speeds << "free rolling also at";
    for (const auto& c : f.free_runs) speeds << " " << fixed(c.speed_m_s * 3.6, 1);
    speeds << " km/h (FNOMIN's sinking) for the speed terms of M_y";
    comment_line(s, speeds.str());
  }
  comment_line(s, "residuals: F_x0 (Pacejka 2012 4.E9) " + percent(f.fx_over_fz) +
                      " of F_z; M_y (QSY) " + percent(f.rolling_rel) + " at free rolling, " +
                      percent(f.rolling_slip_rel) + " at slip; R_e (A3.6) max " +
                      fixed(f.radius_m.max * 1e3, 3) + " mm at LONGVL");
  comment_line(s,
               "left out, the model being in-plane (no slip angle, no camber): lateral force, "
               "aligning and overturning moments, combined slip, turn slip ([LATERAL_, "
               "ALIGNING_, OVERTURNING_, TURNSLIP_COEFFICIENTS], RBX1-3, RCX1, REX1-2, RHX1); "
               "camber terms 0 (PDX3, QSY5, QSY6)");
  comment_line(s,
               "not fitted, 0: pressure effects on the force and moment (PPX1-4, QSY8: the file "
               "holds at INFLPRES = NOMPRES), the radius' growth with speed (Q_V1)");
  comment_line(s,
               "for a tool that needs every section: keep these sections and take the others "
               "from a full MF 6.2 file of a similar tyre (docs/tir.md, 'Merging')");
}

void write_slip_model_keys(std::ostream& s, const TirSlipFit& f) {
  key_line(s, "TYRESIDE", "'LEFT'", "Position of tyre during measurements (in-plane: either)");
  key_line(s, "LONGVL", number_text(f.basis.longvl_m_s), "Reference speed: the slip runs'");
  key_line(s, "VXLOW", "1", "Lower boundary of slip calculation (MF-Tool's usual 1 m/s)");
}

void write_slip_vertical_keys(std::ostream& s, const TirSlipFit& f) {
  key_line(s, "Q_RE0", number_text(f.radius.q_re0),
           "Ratio of free tyre radius with nominal tyre radius");
  key_line(s, "Q_V1", "0", "Tyre radius increase with speed (not fitted)");
  key_line(s, "BREFF", number_text(f.radius.breff),
           "Low load stiffness of effective rolling radius");
  key_line(s, "DREFF", number_text(f.radius.dreff), "Peak value of effective rolling radius");
  key_line(s, "FREFF", number_text(f.radius.freff),
           "High load stiffness of effective rolling radius");
}

void write_slip_sections(std::ostream& s, const TirSlipFit& f) {
  const auto key = [&s](const char* k, double v, const std::string& note) {
    key_line(s, k, number_text(v), note);
  };
  section(s, "-------------------------------------------------vertical_force_range",
          "VERTICAL_FORCE_RANGE");
  key("FZMIN", f.fz_min_N, "Minimum allowed wheel load (the slip runs' lowest)");
  key("FZMAX", f.fz_max_N, "Maximum allowed wheel load (the slip runs' highest)");
  section(s, "------------------------------------------------------long_slip_range",
          "LONG_SLIP_RANGE");
  key("KPUMIN", f.kappa_min, "Minimum valid wheel slip (the slip runs')");
  key("KPUMAX", f.kappa_max, "Maximum valid wheel slip (the slip runs')");
  section(s, "--------------------------------------------------------------scaling",
          "SCALING_COEFFICIENTS");
  for (const auto& [k, note] : kScaling) key(k, 1, note);
  section(s, "---------------------------------------------------------longitudinal",
          "LONGITUDINAL_COEFFICIENTS");
  const MfLongitudinal& c = f.longitudinal;
  key("PCX1", c.pcx1, "Shape factor Cfx for longitudinal force");
  key("PDX1", c.pdx1, "Longitudinal friction Mux at Fznom");
  key("PDX2", c.pdx2, "Variation of friction Mux with load");
  key("PDX3", 0, "Variation of friction Mux with camber (in-plane model: 0)");
  key("PEX1", c.pex1, "Longitudinal curvature Efx at Fznom");
  key("PEX2", c.pex2, "Variation of curvature Efx with load");
  key("PEX3", c.pex3, "Variation of curvature Efx with load squared");
  key("PEX4", c.pex4, "Factor in curvature Efx while driving");
  key("PKX1", c.pkx1, "Longitudinal slip stiffness Kfx/Fz at Fznom");
  key("PKX2", c.pkx2, "Variation of slip stiffness Kfx/Fz with load");
  key("PKX3", c.pkx3, "Exponent in slip stiffness Kfx/Fz with load");
  key("PHX1", c.phx1, "Horizontal shift Shx at Fznom");
  key("PHX2", c.phx2, "Variation of shift Shx with load");
  key("PVX1", c.pvx1, "Vertical shift Svx/Fz at Fznom");
  key("PVX2", c.pvx2, "Variation of shift Svx/Fz with load");
  for (const char* k : {"PPX1", "PPX2", "PPX3", "PPX4"})
    key(k, 0, "Inflation pressure effect (not fitted: the file holds at NOMPRES)");
  section(s, "--------------------------------------------------------------rolling",
          "ROLLING_COEFFICIENTS");
  const MfRolling& r = f.rolling;
  key("QSY1", r.qsy1, "Rolling resistance torque coefficient");
  key("QSY2", r.qsy2, "Rolling resistance torque depending on Fx");
  key("QSY3", r.qsy3, "Rolling resistance torque depending on speed");
  key("QSY4", r.qsy4, "Rolling resistance torque depending on speed ^4");
  key("QSY5", 0, "Rolling resistance torque depending on camber squared (in-plane: 0)");
  key("QSY6", 0, "Rolling resistance torque depending on load and camber squared (0)");
  key("QSY7", r.qsy7, "Rolling resistance torque coefficient load dependency");
  key("QSY8", 0, "Rolling resistance torque coefficient pressure dependency (not fitted)");
}

}  // namespace modaltyre::tir

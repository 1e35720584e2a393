// `tir export`: fits of (A3.3)-(A3.8) to the model's footprints and the .tir text (tir_export.h).
#include "modaltyre/tir/tir_export.h"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/tir/mf_formulas.h"
#include "modaltyre/tir/slip_text.h"
#include "tir_text.h"

#ifndef MODALTYRE_VERSION
#define MODALTYRE_VERSION "unknown"
#endif

namespace modaltyre::tir {
namespace {

using Basis = std::function<double(double)>;

// Least squares y ~ c1 g1(x) + c2 g2(x) on relative residuals (each row divided by y).
std::pair<double, double> fit_two(const Basis& g1, const Basis& g2, const std::vector<double>& x,
                                  const std::vector<double>& y, const char* what) {
  Eigen::MatrixXd A(x.size(), 2);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(y[i] > 0)) throw ComputationError(std::string("the model's ") + what + " is not > 0");
    A(i, 0) = g1(x[i]) / y[i];
    A(i, 1) = g2(x[i]) / y[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < 2) {
    throw ComputationError(std::string("the ") + what + " fit is degenerate (give more loads)");
  }
  const Eigen::Vector2d c = qr.solve(b);
  if (!c.allFinite()) throw ComputationError(std::string("the ") + what + " fit failed");
  return {c(0), c(1)};
}

FitQuality quality(const std::vector<double>& model, const std::vector<double>& law) {
  FitQuality q;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const double r = (law[i] - model[i]) / model[i];
    q.rms_rel += r * r;
    q.max_abs_rel = std::max(q.max_abs_rel, std::abs(r));
  }
  q.rms_rel = std::sqrt(q.rms_rel / static_cast<double>(model.size()));
  return q;
}

std::string g(double v) { return detail::number_text(v); }

std::string pct(const FitQuality& q) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "RMS %.2f %%, max %.2f %%", 100 * q.rms_rel, 100 * q.max_abs_rel);
  return buf;
}

void fit_vertical(TirFit& f) {
  std::vector<double> x, y, rho, load;
  for (const auto& p : f.curve.points) {
    x.push_back(p.sinking_m / f.unloaded_radius_m);
    y.push_back(p.load_N / f.fnomin_N);
    rho.push_back(p.sinking_m);
    load.push_back(p.load_N);
  }
  const auto [q1, q2] =
      fit_two([](double v) { return v; }, [](double v) { return v * v; }, x, y, "sinking-load");
  const auto cz = stiffness_from_q_fz(q1, q2, f.unloaded_radius_m, f.fnomin_N);
  if (!(q1 > 0) || !cz) {
    throw ComputationError("the model's load-sinking curve has no rising MF form (q_Fz1 = " +
                           g(q1) + ", q_Fz2 = " + g(q2) + ")");
  }
  f.q_fz1 = q1;
  f.q_fz2 = q2;
  f.vertical_stiffness_N_m = *cz;
  MfVerticalLaw law{f.unloaded_radius_m, f.fnomin_N, *cz, q1, q2, 0, 0};
  std::vector<double> law_load, law_rho;
  for (std::size_t i = 0; i < rho.size(); ++i) {
    law_load.push_back(mf_load_N(law, rho[i]));
    law_rho.push_back(mf_deflection_m(law, load[i]).value_or(0));
  }
  f.load = quality(load, law_load);
  f.sinking = quality(rho, law_rho);
}

void fit_patch(TirFit& f) {
  std::vector<double> x, a, b;
  for (const auto& p : f.curve.points)
    x.push_back(p.load_N / (f.vertical_stiffness_N_m * f.unloaded_radius_m));
  for (const auto& p : f.curve.points) a.push_back(0.5 * p.length_m / f.unloaded_radius_m);
  const auto [ra2, ra1] = fit_two([](double v) { return v; }, [](double v) { return std::sqrt(v); },
                                  x, a, "contact length");
  f.q_ra1 = ra1;
  f.q_ra2 = ra2;
  std::vector<double> model_len, law_len, model_w, law_w;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double rho_z = x[i] * f.unloaded_radius_m;
    model_len.push_back(f.curve.points[i].length_m);
    law_len.push_back(2 * mf_half_length_m(f.unloaded_radius_m, ra1, ra2, rho_z));
  }
  f.length = quality(model_len, law_len);
  if (!f.curve.width_reason.empty()) return;
  for (const auto& p : f.curve.points) b.push_back(0.5 * *p.width_m / f.width_m);
  const auto [rb2, rb1] = fit_two([](double v) { return v; }, [](double v) { return std::cbrt(v); },
                                  x, b, "contact width");
  f.q_rb1 = rb1;
  f.q_rb2 = rb2;
  for (std::size_t i = 0; i < x.size(); ++i) {
    model_w.push_back(*f.curve.points[i].width_m);
    law_w.push_back(
        2 * mf_half_width_m(f.unloaded_radius_m, f.width_m, rb1, rb2, x[i] * f.unloaded_radius_m));
  }
  f.width = quality(model_w, law_w);
}

void fit_pressure(const contact::TyreModel& model, TirFit& f) {
  // The pressure moves the model's stiffness through the ring's pressure terms whenever the
  // modes give a ring fit (contact/carcass_source.h, docs/ring_model.md), and through the
  // optional inflation_pressure effect; with neither it does not act and PFZ1 is not a fit.
  if (!model.carcass.fit.valid && !model.config.effects.inflation_pressure.enabled) {
    f.pfz1_reason = "PFZ1 left out: the modes give no ring fit to move with the pressure (" +
                    model.carcass.fit.reason +
                    ") and the config's inflation_pressure effect is off, so the model's "
                    "stiffness does not depend on the pressure";
    return;
  }
  constexpr double kStep = 0.1;
  const double p = f.pressure_Pa;
  const double c0 = model_tangent_stiffness_N_m(model, f.fnomin_N, p);
  const double cp = model_tangent_stiffness_N_m(model, f.fnomin_N, p * (1 + kStep));
  const double cm = model_tangent_stiffness_N_m(model, f.fnomin_N, p * (1 - kStep));
  f.pfz1 = (cp - cm) / (2 * kStep * c0);  // (A3.5) by central differences
}

}  // namespace

TirFit fit_tir(const contact::TyreModel& model, const TirExportOptions& options) {
  const contact::TyreConfig& c = model.config;
  if (options.slip.enabled) check_slip_options(options.slip);  // before the footprints
  TirFit f;
  f.fnomin_N = model_fnomin_N(c, options.fnomin_N);
  f.unloaded_radius_m = c.outer_radius_m;
  f.pressure_Pa = c.inflation_pressure_Pa;
  f.rim_radius_m = c.rim_radius_m;
  f.aspect_ratio = c.aspect_ratio;
  if (c.section_width_m > 0) {
    f.width_m = c.section_width_m;
    f.width_source = "tyre.section_width_mm";
  } else {
    f.width_m = c.tread.width_m;
    f.width_source = "tread.contact_width_mm (the config states no tyre.section_width_mm)";
  }
  const auto loads = options.loads_N.empty() ? load_grid(f.fnomin_N, 0.25, 2, 12) : options.loads_N;
  if (loads.size() < 3) throw InputError({"--loads", 0, ""}, "give at least 3 loads to fit");
  // Each law has two coefficients: three loads that are not all different leave a fit with
  // fewer equations than unknowns (issue 38: 4000 4000 4000 ended as a failed computation).
  std::vector<double> distinct = loads;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() < 3) {
    std::ostringstream given;
    for (double l : loads) given << (given.tellp() > 0 ? " " : "") << l;
    throw InputError({"--loads", 0, ""},
                     "give at least 3 different loads to fit (given: " + given.str() + ")");
  }
  f.curve = sample_model(model, loads);
  fit_vertical(f);
  fit_patch(f);
  f.model_tangent_stiffness_N_m = model_tangent_stiffness_N_m(model, f.fnomin_N);
  fit_pressure(model, f);
  if (options.slip.enabled) {
    MfBasis basis;
    basis.unloaded_radius_m = f.unloaded_radius_m;
    basis.fnomin_N = f.fnomin_N;
    basis.nominal_pressure_Pa = basis.pressure_Pa = f.pressure_Pa;
    basis.vertical_stiffness_N_m = f.vertical_stiffness_N_m;
    f.slip = fit_slip(model, basis, options.slip);
  }
  return f;
}

std::string tir_text(const TirFit& f, const contact::TyreConfig& config,
                     const TirExportOptions& options) {
  std::ostringstream s;
  const auto key = [&s](const std::string& k, const std::string& v, const std::string& note) {
    detail::key_line(s, k, v, note);
  };
  const auto lo = f.curve.points.front().load_N, hi = f.curve.points.back().load_N;
  s << "[MDI_HEADER]\n";
  key("FILE_TYPE", "'tir'", "");
  key("FILE_VERSION", "3.0", "");
  key("FILE_FORMAT", "'ASCII'", "");
  s << "! : TIRE_VERSION :      MF-Tyre 6.2 ("
    << (f.slip ? "vertical, contact-patch, longitudinal and rolling-resistance sections only"
               : "vertical and contact-patch sections only")
    << ")\n"
    << "! : COMMENT :           written by modaltyre " << MODALTYRE_VERSION << " from "
    << printable(options.config_label, 200) << "\n"
    << "! : COMMENT :           tyre: " << printable(config.name, 120) << "\n"
    << "! : COMMENT :           fitted by least squares (relative residuals) to "
    << f.curve.points.size() << " footprints, " << g(lo) << " to " << g(hi) << " N\n"
    << "! : COMMENT :           residuals: load at sinking (A3.3) " << pct(f.load)
    << "; sinking at load " << pct(f.sinking) << "\n"
    << "! : COMMENT :           residuals: length (A3.7) " << pct(f.length) << "; width (A3.8) "
    << (f.width ? pct(*f.width) : "not fitted: " + f.curve.width_reason) << "\n"
    << "! : COMMENT :           model tangent stiffness at FNOMIN "
    << g(f.model_tangent_stiffness_N_m)
    << " N/m; VERTICAL_STIFFNESS = dF/drho of the fitted (A3.3) at FNOMIN\n"
    << "! : COMMENT :           WIDTH from " << f.width_source << "\n";
  if (!f.pfz1) s << "! : COMMENT :           " << f.pfz1_reason << "\n";
  for (const auto& c : options.comments)
    s << "! : COMMENT :           " << printable(c, 400) << "\n";
  s << "! : COMMENT :           [STRUCTURAL] and [INERTIA] left out: the hammer test's modes are "
       "those of its own boundary condition, not MF-Swift's rigid ring on a fixed rim\n";
  if (f.slip) {
    write_slip_comments(s, *f.slip);
  } else {
    s << "! : COMMENT :           no force and moment (slip) coefficients: the model predicts "
         "none\n";
  }
  s << "$----------------------------------------------------------------units\n[UNITS]\n";
  key("LENGTH", "'meter'", "");
  key("FORCE", "'newton'", "");
  key("ANGLE", "'radian'", "");
  key("MASS", "'kg'", "");
  key("TIME", "'second'", "");
  key("PRESSURE", "'pascal'", "");
  s << "$----------------------------------------------------------------model\n[MODEL]\n";
  key("FITTYP", "62", "Magic Formula version number");
  if (f.slip) write_slip_model_keys(s, *f.slip);
  s << "$-----------------------------------------------------------dimensions\n[DIMENSION]\n";
  key("UNLOADED_RADIUS", g(f.unloaded_radius_m), "Free tyre radius (tyre.outer_radius_mm)");
  key("WIDTH", g(f.width_m), "Nominal section width of the tyre");
  if (f.rim_radius_m > 0) key("RIM_RADIUS", g(f.rim_radius_m), "Nominal rim radius");
  if (f.aspect_ratio > 0) key("ASPECT_RATIO", g(f.aspect_ratio), "Nominal aspect ratio");
  s << "$-------------------------------------------------operating conditions\n"
       "[OPERATING_CONDITIONS]\n";
  key("INFLPRES", g(f.pressure_Pa), "Tyre inflation pressure");
  key("NOMPRES", g(f.pressure_Pa), "Nominal tyre inflation pressure");
  s << "$-------------------------------------------------------------vertical\n[VERTICAL]\n";
  key("FNOMIN", g(f.fnomin_N), "Nominal wheel load");
  key("VERTICAL_STIFFNESS", g(f.vertical_stiffness_N_m), "Tyre vertical stiffness at FNOMIN");
  key("Q_FZ2", g(f.q_fz2), "Quadratic term in load vs. deflection");
  if (f.pfz1) key("PFZ1", g(*f.pfz1), "Pressure effect on vertical stiffness");
  if (f.slip) write_slip_vertical_keys(s, *f.slip);
  s << "$---------------------------------------------------deflection load\n"
       "[DEFLECTION_LOAD_CURVE]\n{pen fz}\n0 0\n";
  for (const auto& p : f.curve.points) s << g(p.sinking_m) << " " << g(p.load_N) << "\n";
  s << "$--------------------------------------------------------contact patch\n"
       "[CONTACT_PATCH]\n";
  key("Q_RA1", g(f.q_ra1), "Square root term in contact length equation");
  key("Q_RA2", g(f.q_ra2), "Linear term in contact length equation");
  if (f.q_rb1) {
    key("Q_RB1", g(*f.q_rb1), "Root term in contact width equation");
    key("Q_RB2", g(*f.q_rb2), "Linear term in contact width equation");
  }
  if (f.slip) write_slip_sections(s, *f.slip);
  return s.str();
}

}  // namespace modaltyre::tir

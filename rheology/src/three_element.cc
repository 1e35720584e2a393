#include "modaltyre/rheology/three_element.h"

#include <cmath>

#include "modaltyre/core/conditions.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/rheology/contact_geometry.h"
#include "modaltyre/solvers/linear_least_squares.h"

namespace modaltyre::rheology {
namespace {

// Coefficients of E1 and of chi E1 in the static load, eq. (14) with dh/dt = 0.
double elastic_coef(double h, const ThreeElementOptions& o) {
  const double phi1 = half_contact_angle(h, o.r0_m);
  return 2.0 * o.tread_width_m * o.r0_m * o.r0_m * arc_stress_load_function(phi1) /
         o.section_height_m;  // = B_tr r0^2 lambda / H, eq. (17)
}
double friction_coef(double h, const ThreeElementOptions& o) {
  const double phi1 = half_contact_angle(h, o.r0_m);
  return 2.0 * o.tread_width_m * o.r0_m * phi1 * std::cos(phi1);  // eq. (18)
}

}  // namespace

StaticLoop read_static_loop_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"load_N", "deflection_mm", "branch"};
  schema.optional = {"pressure_kPa"};
  schema.text = {"branch"};
  const CsvTable t = read_csv(path, schema);
  StaticLoop loop;
  loop.path = path;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    StaticLoopRow row;
    row.line = t.line(r);
    row.load_N = t.number(r, "load_N");
    row.deflection_m = t.number(r, "deflection_mm") * 1e-3;
    // Load, pressure and branch words as every reader of conditions (core/conditions.h).
    const ConditionInfo& branch = condition_info(ConditionId::branch);
    const std::string& br = t.text(r, "branch");
    const auto branch_value = branch.value_of(br);
    if (!branch_value) throw InputError({path, row.line, "branch"}, branch.refusal(br));
    row.loading = *branch_value == 0;
    for (const ConditionId id : {ConditionId::load_N, ConditionId::pressure_kPa}) {
      // The pressure is not used by the fit, but a recorded one must still be in range.
      const ConditionInfo& c = condition_info(id);
      if (t.has(c.name) && !c.in_range(t.number(r, c.name)))
        throw InputError({path, row.line, c.name}, c.refusal(number_text(t.number(r, c.name))));
    }
    if (row.deflection_m <= 0)
      throw InputError({path, row.line, "deflection_mm"}, "deflection must be > 0 mm");
    loop.rows.push_back(row);
  }
  return loop;
}

double static_loop_load(double E1, double chi, double h, bool loading,
                        const ThreeElementOptions& o) {
  return E1 * elastic_coef(h, o) + (loading ? 1.0 : -1.0) * chi * E1 * friction_coef(h, o);
}

double eta1_eq22(double mass_kg, double log_decrement, double period_s, double contact_length_m) {
  return 2.0 * mass_kg * log_decrement / (period_s * contact_length_m);  // seed 000 eq. (22)
}

StaticLoopFit identify_static_loop(const StaticLoop& loop, const ThreeElementOptions& o) {
  if (!(o.r0_m > 0))
    throw InputError("the static loop needs the free radius r0 (--r0-mm or tyre.outer_radius_mm)");
  if (!(o.tread_width_m > 0))
    throw InputError(
        "the static loop needs the tread width B_tr (--tread-width-mm or "
        "tread.contact_width_mm)");
  if (!(o.section_height_m > 0))
    throw InputError(
        "the static loop needs the section height H that eps1 = Delta_P / H "
        "refers to (--section-height-mm)");
  int nl = 0, nu = 0;
  for (const auto& r : loop.rows) {
    (r.loading ? nl : nu)++;
    if (r.deflection_m >= o.r0_m)
      throw InputError({loop.path, r.line, "deflection_mm"}, "deflection exceeds the radius r0");
  }
  if (nl < 1 || nu < 1 || nl + nu < 3)
    throw InputError({loop.path, 0, "branch"},
                     "the static loop needs rows on both the loading and the unloading branch "
                     "(at least three rows) to separate elastic and dry-friction forces");
  const auto n = static_cast<Eigen::Index>(loop.rows.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& r = loop.rows[static_cast<std::size_t>(i)];
    A(i, 0) = elastic_coef(r.deflection_m, o);
    A(i, 1) = (r.loading ? 1.0 : -1.0) * friction_coef(r.deflection_m, o);
    b(i) = r.load_N;
  }
  const solvers::LinearFit fit = solvers::solve_linear_least_squares(A, b);
  StaticLoopFit s;
  s.E1_Pa = fit.coef(0);
  if (!(s.E1_Pa > 0)) throw ComputationError("static loop: E1 is not positive");
  s.E1_se = fit.std_error(0);
  s.chi = fit.coef(1) / fit.coef(0);
  // delta method for chi = c2 / c1 (neglecting the c1-c2 covariance, small for a closed loop)
  s.chi_se = std::abs(s.chi) *
             std::sqrt(std::pow(fit.std_error(1) / std::max(1e-300, std::abs(fit.coef(1))), 2) +
                       std::pow(s.E1_se / s.E1_Pa, 2));
  if (fit.coef(1) == 0) s.chi_se = fit.std_error(1) / s.E1_Pa;
  s.residual_rms_N = fit.residual_rms;
  s.rows = static_cast<int>(n);
  return s;
}

FreeVibrationResult identify_free_vibration(const DecaySignal& signal, const StaticLoop* loop,
                                            const ThreeElementOptions& o) {
  if (!(o.mass_kg > 0))
    throw InputError("free-vibration needs the reduced mass m (--mass-kg): tyre + rim + fixture");
  if (!(o.contact_length_m > 0) && !(o.r0_m > 0))
    throw InputError(
        "free-vibration needs the contact length L_C (--contact-length-mm) or the "
        "free radius r0 (--r0-mm or --config) to compute it from h_Z0");
  FreeVibrationResult res;
  res.decay = fit_free_decay(signal);
  const auto& d = res.decay;
  std::string lc_note;
  if (o.contact_length_m > 0) {
    res.contact_length_m = o.contact_length_m;
    lc_note = "L_C given";
  } else {
    if (!(d.equilibrium_m > 0 && d.equilibrium_m < o.r0_m))
      throw InputError({signal.path, 0, "deflection_mm"},
                       "the equilibrium deflection h_Z0 of the decay is not in (0, r0); give "
                       "--contact-length-mm");
    res.contact_length_m = contact_length(d.equilibrium_m, o.r0_m);
    lc_note = "L_C = 2 r0 sin(phi1) at the decay's equilibrium deflection h_Z0";
  }
  res.eta1_Pa_s = eta1_eq22(o.mass_kg, d.log_decrement, d.period_s, res.contact_length_m);
  res.eta1_se =
      res.eta1_Pa_s * std::hypot(d.log_decrement_se / d.log_decrement, d.period_se_s / d.period_s);

  auto& rep = res.report;
  rep.method = "free-vibration";
  rep.rows = d.samples;
  rep.residual_rms = d.residual_rms_m * 1e3;
  rep.residual_unit = "mm";
  rep.parameters = {
      {"period_s", d.period_s, "s", d.period_se_s},
      {"log_decrement", d.log_decrement, "-", d.log_decrement_se},
      {"eta1", res.eta1_Pa_s, "Pa s", res.eta1_se},
      {"log_decrement_peaks", d.log_decrement_peaks, "-", 0.0},
      {"equilibrium_deflection", d.equilibrium_m * 1e3, "mm", d.equilibrium_se_m * 1e3},
      {"contact_length", res.contact_length_m * 1e3, "mm", 0.0},
      {"damping_coefficient", 2 * o.mass_kg * d.log_decrement / d.period_s, "N s/m",
       2 * o.mass_kg * d.log_decrement / d.period_s *
           std::hypot(d.log_decrement_se / d.log_decrement, d.period_se_s / d.period_s)}};
  rep.notes.push_back(
      "period and log decrement from a damped-sine fit to the whole decay; "
      "log_decrement_peaks = mean ln(a_i/a_(i+1)) over measured peaks");
  rep.notes.push_back(lc_note);
  if (loop) {
    res.static_fit = identify_static_loop(*loop, o);
    rep.parameters.push_back({"E1", res.static_fit->E1_Pa, "Pa", res.static_fit->E1_se});
    rep.parameters.push_back({"chi", res.static_fit->chi, "-", res.static_fit->chi_se});
    rep.parameters.push_back({"static_residual_rms", res.static_fit->residual_rms_N, "N", 0.0});
    rep.notes.push_back(
        "E1, chi: least squares of eq. (14) at dh/dt = 0 over both branches of "
        "the static loop (" +
        std::to_string(res.static_fit->rows) + " rows)");
  }
  return res;
}

}  // namespace modaltyre::rheology

#include "modaltyre/contact/validation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>

#include "modaltyre/contact/measurements.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/solvers/least_squares.h"

namespace modaltyre::contact {
namespace {

struct Calibratable {
  std::function<double(const TyreConfig&)> value;  ///< current value in config units
  double min, max;  ///< physically plausible range searched by the calibration
};

/// Scalar config keys that may be calibrated.
const std::map<std::string, Calibratable>& calibratable() {
  static const std::map<std::string, Calibratable> keys = {
      {"modal.compliance_scale", {[](const TyreConfig& c) { return c.compliance_scale; }, 0.2, 5}},
      {"tread.modulus_MPa",
       {[](const TyreConfig& c) { return c.tread.modulus_Pa * 1e-6; }, 0.1, 100}},
      {"tread.thickness_mm",
       {[](const TyreConfig& c) { return c.tread.thickness_m * 1e3; }, 1, 50}},
      {"tread.contact_width_mm",
       {[](const TyreConfig& c) { return c.tread.width_m * 1e3; }, 20, 500}},
      {"tyre.outer_radius_mm",
       {[](const TyreConfig& c) { return c.outer_radius_m * 1e3; }, 100, 1500}},
      // Starts at 10 rad^2/s^2 when not stated (the fit to resolved orders may give 0).
      {"modal.extension_bending_s2_rad2_s2",
       {[](const TyreConfig& c) { return c.extension_s2 > 0 ? c.extension_s2 : 10.0; }, 1e-3, 1e6}},
  };
  return keys;
}

std::string assign(const std::string& key, double value) {
  std::ostringstream s;
  s.precision(17);
  s << key << "=" << value;
  return s.str();
}

// The conditions a row is predicted at.
OperatingConditions conditions_of(const MeasuredFootprint& row, const TyreConfig& config) {
  return row.conditions ? *row.conditions : config.default_conditions(row.load_N);
}

// Predicted footprints of the rows. No effect on: the model's own operator, the rows in file
// order each warm-started from the previous (what validate computed before effects existed);
// with effects: FootprintPredictor::predict() at each row's conditions.
std::vector<Prediction> predict_rows(const TyreModel& model,
                                     const std::vector<MeasuredFootprint>& rows) {
  const TyreConfig& config = model.config;
  std::vector<Prediction> out;
  if (!config.effects.any()) {
    std::vector<LoadCase> cases;
    for (const auto& r : rows) {
      const OperatingConditions c = conditions_of(r, config);
      cases.push_back({c.load_N, c.horizontal_force_N});
    }
    for (auto& f : solve_footprints(model, cases)) {
      out.push_back(prediction_from(std::move(f), config));
    }
    return out;
  }
  const FootprintPredictor predictor(model);
  for (const auto& r : rows) {
    const OperatingConditions c = conditions_of(r, config);
    Prediction p = predictor.predict(config, c);
    // The applied load, not the elastic tyre's share of it (dry_friction), is the row's load.
    p.footprint.load = {c.load_N, c.horizontal_force_N};
    out.push_back(std::move(p));
  }
  return out;
}

void require_converged(const std::vector<Prediction>& res, const std::string& stage) {
  for (const auto& p : res) {
    if (!p.ok) {
      std::ostringstream m;
      m << stage << ": load case " << p.footprint.load.load_N
        << " N did not converge: " << p.message;
      throw ComputationError(m.str());
    }
  }
}

MeasuredFootprint footprint_of(const MeasuredRow& r) {
  MeasuredFootprint m;
  m.row = r.row;
  m.line = r.line;
  m.load_N = r.conditions.load_N;
  m.conditions = r.conditions;
  auto value = [&](const char* name) -> std::optional<double> {
    const auto it = r.observed.find(name);
    return it == r.observed.end() ? std::nullopt : std::optional<double>(it->second);
  };
  m.sinking_mm = value("sinking_mm");
  m.length_mm = value("length_mm");
  m.width_mm = value("width_mm");
  return m;
}

}  // namespace

std::vector<MeasuredFootprint> read_footprint_measurements(const std::string& path) {
  CsvSchema schema;
  schema.required = {"load_N"};
  schema.optional = {"sinking_mm", "length_mm", "width_mm"};
  const CsvTable t = read_csv(path, schema);
  if (!t.has("sinking_mm") && !t.has("length_mm")) {
    throw InputError({path, 1, "sinking_mm"},
                     "no observable column: give sinking_mm and/or length_mm");
  }
  std::vector<MeasuredFootprint> out;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    MeasuredFootprint m;
    m.row = static_cast<int>(i) + 1;
    m.line = t.line(i);
    m.load_N = t.number(i, "load_N");
    if (!(m.load_N > 0)) throw InputError({path, m.line, "load_N"}, "load must be > 0 N");
    // The tyre config's limit on loads_N: beyond it a unit error the solver would fail on.
    if (m.load_N > 1e7) throw InputError({path, m.line, "load_N"}, "load must be at most 1e7 N");
    for (const char* col : {"sinking_mm", "length_mm", "width_mm"}) {
      if (!t.has(col)) continue;
      const double v = t.number(i, col);
      if (!(v > 0)) throw InputError({path, m.line, col}, "must be > 0 mm");
      if (v > 1e4) throw InputError({path, m.line, col}, "must be at most 1e4 mm (a unit error?)");
      if (std::string(col) == "sinking_mm") m.sinking_mm = v;
      if (std::string(col) == "length_mm") m.length_mm = v;
      if (std::string(col) == "width_mm") m.width_mm = v;
    }
    for (const auto& prev : out) {
      if (prev.load_N == m.load_N) {
        throw InputError({path, m.line, "load_N"},
                         "duplicate load (same as line " + std::to_string(prev.line) + ")");
      }
    }
    out.push_back(m);
  }
  return out;
}

const std::vector<std::string>& validation_observables() {
  static const std::vector<std::string> names = {"sinking_mm", "length_mm", "width_mm"};
  return names;
}

std::optional<double> measured_value(const MeasuredFootprint& m, const std::string& observable) {
  if (observable == "sinking_mm") return m.sinking_mm;
  if (observable == "length_mm") return m.length_mm;
  if (observable == "width_mm") return m.width_mm;
  return std::nullopt;
}

std::vector<MeasuredFootprint> read_validation_measurements(const std::string& path,
                                                            const TyreConfig& config) {
  // Files of the original shape keep their reader (and its checks, e.g. one row per load);
  // condition columns, a sweep's extra columns or effects need the conditions of every row.
  static const std::vector<std::string> plain = {"load_N", "sinking_mm", "length_mm", "width_mm"};
  bool conditions = config.effects.any();
  for (const auto& c : read_csv_header(path)) {
    conditions = conditions || std::find(plain.begin(), plain.end(), c) == plain.end();
  }
  if (!conditions) return read_footprint_measurements(path);
  const MeasurementSet set = read_measurements(path, config);
  bool compared = false;
  for (const auto& o : set.observables) {
    for (const auto& v : validation_observables()) compared = compared || o == v;
  }
  if (!compared) {
    throw InputError(
        {path, 1, "sinking_mm"},
        "no observable validate compares: give any of sinking_mm, length_mm, width_mm");
  }
  std::vector<MeasuredFootprint> out;
  for (const auto& r : set.rows) out.push_back(footprint_of(r));
  return out;
}

std::string range_bound_side(double value, double min, double max, bool log_scale) {
  const double span = log_scale ? std::log(max / min) : max - min;
  const double lo = log_scale ? std::log(value / min) : value - min;
  const double hi = log_scale ? std::log(max / value) : max - value;
  if (lo < 1e-3 * span) return "lower";
  if (hi < 1e-3 * span) return "upper";
  return "";
}

ValidationReport validate_footprints(const std::string& config_path,
                                     const std::vector<std::string>& overrides,
                                     const std::vector<MeasuredFootprint>& measured) {
  const TyreConfig base = load_tyre_config(config_path, overrides);
  const auto ident = modal::identify_modes(modal::read_hammer_csv(base.hammer_csv));
  const auto& vs = base.validation;
  ValidationReport rep;
  Calibration& cal = rep.calibration;
  cal.keys = vs.calibrate;
  cal.rows = vs.calibration_rows;
  cal.observables = vs.observables;
  std::vector<MeasuredFootprint> cal_rows;
  for (int r : cal.rows) {
    if (r < 1 || r > static_cast<int>(measured.size())) {
      throw InputError({config_path, 0, "validation.calibration_rows"},
                       "row " + std::to_string(r) + " does not exist in the measured file (" +
                           std::to_string(measured.size()) + " rows)");
    }
    cal_rows.push_back(measured[r - 1]);
  }
  for (const auto& key : cal.keys) {
    if (!calibratable().count(key)) {
      std::string list;
      for (const auto& kv : calibratable()) list += (list.empty() ? "" : ", ") + kv.first;
      throw InputError({config_path, 0, "validation.calibrate"},
                       "'" + key + "' cannot be calibrated; choose from: " + list);
    }
    cal.initial_values.push_back(calibratable().at(key).value(base));
  }
  const auto& known = validation_observables();
  for (const auto& obs : cal.keys.empty() ? std::vector<std::string>{} : cal.observables) {
    if (std::find(known.begin(), known.end(), obs) == known.end()) {
      throw InputError(
          {config_path, 0, "validation.calibration_observables"},
          "'" + obs + "' cannot be fitted; choose from: sinking_mm, length_mm, width_mm");
    }
  }
  for (const auto& row : cal_rows) {
    for (const auto& obs : cal.observables) {
      if (!measured_value(row, obs)) {
        throw InputError({config_path, 0, "validation.calibration_observables"},
                         "calibration row " + std::to_string(row.row) + " has no " + obs);
      }
    }
  }

  auto model_for = [&](const Eigen::VectorXd& log_values) {
    std::vector<std::string> ov = overrides;
    for (std::size_t k = 0; k < cal.keys.size(); ++k) {
      ov.push_back(assign(cal.keys[k], std::exp(log_values(static_cast<Eigen::Index>(k)))));
    }
    return build_tyre_model(load_tyre_config(config_path, ov), ident);
  };

  Eigen::VectorXd x(static_cast<Eigen::Index>(cal.keys.size()));
  for (std::size_t k = 0; k < cal.keys.size(); ++k) {
    x(static_cast<Eigen::Index>(k)) = std::log(cal.initial_values[k]);
  }
  if (!cal.keys.empty()) {
    // Parameters are positive: fit their logarithms (relative steps, no sign flips).
    const std::size_t n_res = cal_rows.size() * cal.observables.size();
    auto residual = [&](const Eigen::VectorXd& lx) {
      // Outside the plausible range: a large residual makes the step fail instead of the model.
      for (std::size_t k = 0; k < cal.keys.size(); ++k) {
        const auto& c = calibratable().at(cal.keys[k]);
        const double v = std::exp(lx(static_cast<Eigen::Index>(k)));
        if (!(v >= c.min && v <= c.max)) {
          return Eigen::VectorXd::Constant(static_cast<Eigen::Index>(n_res), 1e6).eval();
        }
      }
      const auto res = predict_rows(model_for(lx), cal_rows);
      require_converged(res, "calibration");
      std::vector<double> r;
      for (std::size_t i = 0; i < cal_rows.size(); ++i) {
        for (const auto& obs : cal.observables) {
          r.push_back(res[i].observable(obs) / *measured_value(cal_rows[i], obs) - 1.0);
        }
      }
      return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())).eval();
    };
    solvers::LeastSquaresOptions lso;
    lso.relative_step = 1e-5;
    lso.step_tolerance = 1e-6;  // 1e-6 relative in each parameter is far below its meaning
    lso.cost_tolerance = 1e-8;
    const auto fit = solvers::levenberg_marquardt(residual, x, lso);
    x = fit.x;
    cal.converged = fit.converged;
    cal.evaluations = fit.evaluations;
    cal.rms_rel_residual =
        fit.residual.size() ? std::sqrt(fit.residual.squaredNorm() / fit.residual.size()) : 0.0;
    for (std::size_t k = 0; k < cal.keys.size(); ++k) {
      const double v = std::exp(x(static_cast<Eigen::Index>(k)));
      const auto& range = calibratable().at(cal.keys[k]);
      cal.values.push_back(v);
      cal.at_bound.push_back(range_bound_side(v, range.min, range.max, true));  // log-fitted
    }
    if (cal.rms_rel_residual > 1e3) {
      throw ComputationError("calibration found no parameters within their plausible ranges");
    }
  }
  rep.model = model_for(x);
  const auto predicted = predict_rows(rep.model, measured);
  require_converged(predicted, "validation");
  for (const auto& p : predicted) rep.footprints.push_back(p.footprint);
  for (const auto& m : measured) rep.with_conditions = rep.with_conditions || m.conditions;

  const std::set<int> cal_set(cal.rows.begin(), cal.rows.end());
  std::map<std::string, double> sq;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    ValidationRow row;
    row.measured = measured[i];
    row.calibration = cal_set.count(measured[i].row) > 0;
    row.sinking_mm = predicted[i].sinking_mm;
    row.length_mm = predicted[i].length_mm;
    row.width_mm = predicted[i].width_mm;
    auto rel_error = [&](const std::string& obs) -> std::optional<double> {
      const auto m = measured_value(row.measured, obs);
      if (!m) return std::nullopt;
      const double e = predicted[i].observable(obs) / *m - 1;
      if (!row.calibration) {
        sq[obs] += e * e;
        ++rep.predicted_rows[obs];
      }
      return e;
    };
    row.sinking_rel_error = rel_error("sinking_mm");
    row.length_rel_error = rel_error("length_mm");
    row.width_rel_error = rel_error("width_mm");
    rep.rows.push_back(row);
  }
  for (const auto& [obs, s] : sq) rep.rms_rel_error[obs] = std::sqrt(s / rep.predicted_rows[obs]);
  return rep;
}

}  // namespace modaltyre::contact

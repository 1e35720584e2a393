#include "modaltyre/contact/validation.h"

#include <cmath>
#include <functional>
#include <set>
#include <sstream>

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
      {"tread.modulus_MPa", {[](const TyreConfig& c) { return c.tread.modulus_Pa * 1e-6; }, 0.1, 100}},
      {"tread.thickness_mm", {[](const TyreConfig& c) { return c.tread.thickness_m * 1e3; }, 1, 50}},
      {"tread.contact_width_mm", {[](const TyreConfig& c) { return c.tread.width_m * 1e3; }, 20, 500}},
      {"tyre.outer_radius_mm", {[](const TyreConfig& c) { return c.outer_radius_m * 1e3; }, 100, 1500}},
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

std::vector<FootprintResult> solve_rows(const TyreModel& model,
                                        const std::vector<MeasuredFootprint>& rows) {
  std::vector<LoadCase> cases;
  for (const auto& r : rows) cases.push_back({r.load_N, model.config.horizontal_force_N});
  return solve_footprints(model, cases);
}

void require_converged(const std::vector<FootprintResult>& res, const std::string& stage) {
  for (const auto& r : res) {
    if (!r.converged) {
      std::ostringstream m;
      m << stage << ": load case " << r.load.load_N << " N did not converge: " << r.message;
      throw ComputationError(m.str());
    }
  }
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
    for (const char* col : {"sinking_mm", "length_mm", "width_mm"}) {
      if (!t.has(col)) continue;
      const double v = t.number(i, col);
      if (!(v > 0)) throw InputError({path, m.line, col}, "must be > 0 mm");
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
  for (const auto& row : cal_rows) {
    for (const auto& obs : cal.observables) {
      if ((obs == "sinking_mm" && !row.sinking_mm) || (obs == "length_mm" && !row.length_mm)) {
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
      const TyreModel m = model_for(lx);
      const auto res = solve_rows(m, cal_rows);
      require_converged(res, "calibration");
      std::vector<double> r;
      for (std::size_t i = 0; i < cal_rows.size(); ++i) {
        for (const auto& obs : cal.observables) {
          if (obs == "sinking_mm")
            r.push_back(res[i].sinking_m * 1e3 / *cal_rows[i].sinking_mm - 1.0);
          if (obs == "length_mm")
            r.push_back(res[i].contact_length_m * 1e3 / *cal_rows[i].length_mm - 1.0);
        }
      }
      return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())).eval();
    };
    solvers::LeastSquaresOptions lso;
    lso.relative_step = 1e-5;
    lso.step_tolerance = 1e-6;   // 1e-6 relative in each parameter is far below its meaning
    lso.cost_tolerance = 1e-8;
    const auto fit = solvers::levenberg_marquardt(residual, x, lso);
    x = fit.x;
    cal.converged = fit.converged;
    cal.evaluations = fit.evaluations;
    cal.rms_rel_residual = fit.residual.size()
                               ? std::sqrt(fit.residual.squaredNorm() / fit.residual.size())
                               : 0.0;
    for (std::size_t k = 0; k < cal.keys.size(); ++k) {
      cal.values.push_back(std::exp(x(static_cast<Eigen::Index>(k))));
    }
    if (cal.rms_rel_residual > 1e3) {
      throw ComputationError("calibration found no parameters within their plausible ranges");
    }
  }
  rep.model = model_for(x);
  rep.footprints = solve_rows(rep.model, measured);
  require_converged(rep.footprints, "validation");

  const std::set<int> cal_set(cal.rows.begin(), cal.rows.end());
  std::map<std::string, double> sq;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    ValidationRow row;
    row.measured = measured[i];
    row.calibration = cal_set.count(measured[i].row) > 0;
    row.sinking_mm = rep.footprints[i].sinking_m * 1e3;
    row.length_mm = rep.footprints[i].contact_length_m * 1e3;
    if (row.measured.sinking_mm) row.sinking_rel_error = row.sinking_mm / *row.measured.sinking_mm - 1;
    if (row.measured.length_mm) row.length_rel_error = row.length_mm / *row.measured.length_mm - 1;
    if (!row.calibration) {
      if (row.sinking_rel_error) {
        sq["sinking_mm"] += *row.sinking_rel_error * *row.sinking_rel_error;
        ++rep.predicted_rows["sinking_mm"];
      }
      if (row.length_rel_error) {
        sq["length_mm"] += *row.length_rel_error * *row.length_rel_error;
        ++rep.predicted_rows["length_mm"];
      }
    }
    rep.rows.push_back(row);
  }
  for (const auto& [obs, s] : sq) rep.rms_rel_error[obs] = std::sqrt(s / rep.predicted_rows[obs]);
  return rep;
}

}  // namespace modaltyre::contact

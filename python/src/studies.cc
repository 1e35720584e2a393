// modaltyre.validate, sweep, transient, effects, discover: one library call each, the result
// as the command's JSON document (report/), time series and sweep columns as NumPy arrays.
#include <optional>

#include "bindings.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/discover/discover.h"
#include "modaltyre/report/condition_settings.h"
#include "modaltyre/report/discover_json.h"
#include "modaltyre/report/effects_json.h"
#include "modaltyre/report/sweep_columns.h"
#include "modaltyre/report/traction_flexing.h"
#include "modaltyre/report/transient_json.h"
#include "modaltyre/report/validation_json.h"
#include "modaltyre/studies/measurements.h"
#include "modaltyre/studies/sweep.h"
#include "modaltyre/studies/validation.h"
#include "modaltyre/transient/transient.h"
#include "to_python.h"

namespace modaltyre::python {
namespace {

py::object validate(const py::object& config_arg, const py::object& measured_arg,
                    const py::dict& overrides, const py::dict& conditions) {
  const std::string config_path = path_arg(config_arg, "config_path");
  const std::string measured = path_arg(measured_arg, "measured_csv");
  const auto sets = overrides_of(overrides);
  const auto settings = conditions_of(conditions);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const auto config = contact::load_tyre_config(config_path, sets);
    auto rows = studies::read_validation_measurements(measured, config);
    report::apply_to_measurements(settings, rows, measured, "conditions");
    j = report::validation_json(studies::validate_footprints(config, rows));
    j["conditions"] = report::settings_json(settings);
  }
  return checked(j);
}

py::dict sweep(const py::object& path_object, const py::object& threads_object,
               const py::dict& overrides, bool warm_start) {
  const std::string path = path_arg(path_object, "sweep_yaml");
  const std::optional<int> threads = threads_arg(threads_object, "threads");
  const auto sets = overrides_of(overrides);
  std::vector<report::SweepColumn> cols;
  {
    py::gil_scoped_release release;
    const auto plan = studies::plan_sweep(studies::read_sweep_spec(path, sets));
    studies::SweepOptions opt;
    opt.threads = threads.value_or(0);
    opt.warm_start = warm_start;
    cols = report::sweep_columns(plan, studies::run_sweep(plan, opt));
  }
  py::dict out;
  const py::object np_array = py::module_::import("numpy").attr("array");
  for (const auto& c : cols) {
    out[py::str(c.name)] =
        c.numeric ? py::object(owned_array(c.numbers)) : np_array(py::cast(c.texts), "str");
  }
  return out;
}

py::object run_transient(const py::object& config_arg, const std::string& scenario,
                         const py::dict& overrides, const py::dict& conditions) {
  const std::string config_path = path_arg(config_arg, "config_path");
  auto sets = overrides_of(overrides);
  const auto settings = conditions_of(conditions);
  nlohmann::json j;
  std::vector<std::pair<std::string, std::vector<double>>> series;
  {
    py::gil_scoped_release release;
    const transient::Scenario sc = transient::parse_scenario(scenario);
    report::map_transient_conditions(settings, sc, sets, "conditions");
    refuse_repeated_overrides(sets);  // hold_s and transient.load_hold.hold_s both given
    const auto config = contact::load_tyre_config(config_path, sets);
    const auto model = transient::build_transient_model(contact::build_tyre_model(config));
    // The patch the config states, as `modaltyre transient` (2D, or 3D with footprint_3d:).
    const transient::TransientResult r = transient::run_scenario(model, sc);
    if (!r.ok()) throw ComputationError(r.message);
    j = report::transient_json(model, r);
    j["conditions"] = report::settings_json(settings);
    series = report::transient_series(r);
  }
  py::dict out = checked(j).cast<py::dict>();
  py::dict s;
  for (const auto& [name, values] : series) s[py::str(name)] = owned_array(values);
  out["series"] = s;
  return out;
}

py::object run_discover(const py::object& config_arg, const py::object& measured_arg,
                        const py::dict& overrides, const py::object& threads_object) {
  const std::string config_path = path_arg(config_arg, "config_path");
  const std::string measured = path_arg(measured_arg, "measured_csv");
  const std::optional<int> threads = threads_arg(threads_object, "threads");
  const auto sets = overrides_of(overrides);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const auto config = contact::load_tyre_config(config_path, sets);
    const auto data = studies::read_measurements(measured, config);
    discover::DiscoverOptions opt;  // the CLI's defaults
    opt.threads = threads.value_or(0);
    opt.traction_flexing = report::flexing_resistance_N;  // traction rows, as the CLI
    j = report::discover_json(discover::discover(config, data, opt), measured, data.rows.size());
  }
  return checked(j);
}

}  // namespace

void bind_studies(py::module_& m) {
  m.def("validate", &validate, py::arg("config_path"), py::arg("measured_csv"),
        py::arg("overrides") = py::dict(), py::arg("conditions") = py::dict(),
        "Measured against predicted footprints with the config's declared calibration: the "
        "dict of `modaltyre validate CONFIG MEASURED --json` (sinking, length, width [mm], "
        "relative errors [-], RMS over the predicted rows). `conditions`: {'hold_s': 60} = "
        "--set hold_s=60, a condition the file has no column of, on every row.");
  m.def("sweep", &sweep, py::arg("sweep_yaml"), py::arg("threads") = py::none(),
        py::arg("overrides") = py::dict(), py::arg("warm_start") = false,
        "Runs a sweep file (`modaltyre sweep`): {column: NumPy array} with the columns of its "
        "CSV in order (conditions and parameters as given, sinking_mm, length_mm, width_mm, "
        "rolling_resistance_N, vertical_stiffness_N_mm, peak_pressure_kPa, iterations; NaN "
        "where a case failed; status, message, valid as str). No CSV is written.");
  m.def("transient", &run_transient, py::arg("config_path"), py::arg("scenario"),
        py::arg("overrides") = py::dict(), py::arg("conditions") = py::dict(),
        "Time-domain scenario (load-hold | free-vibration | rolling | cleat) on the config's "
        "patch (3D with footprint_3d:, e.g. configs/sf350.yaml; else 2D): "
        "the dict of `modaltyre transient --json` plus 'series': {t_s, load_N, "
        "hub_displacement_mm, sinking_mm, contact_length_mm, longitudinal_force_N, and on the "
        "3D patch width_mm, contact_area_mm2, on a soil (overrides {'ground.model': "
        "'bekker', ...}, 2D) soil_sinkage_mm, compaction_resistance_N} as NumPy arrays (the "
        "columns of --csv). "
        "`conditions`: the scenario's, {'load_N': 3000, "
        "'hold_s': 60} = --set load_N=3000 --set hold_s=60.");
  m.def(
      "effects", [] { return py::object(checked(report::effects_json())["effects"]); },
      "The switchable model effects (`modaltyre effects --json`'s list): name, description, "
      "parameters with key, unit, default, min, max.");
  m.def("discover", &run_discover, py::arg("config_path"), py::arg("measured_csv"),
        py::arg("overrides") = py::dict(), py::arg("threads") = py::none(),
        "Locates the gap between model and measurements and names the missing effect: the "
        "dict of `modaltyre discover CONFIG MEASURED --json` (gaps as relative RMS, ΔBIC, "
        "parameters in their keys' units).");
}

}  // namespace modaltyre::python

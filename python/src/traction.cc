// modaltyre.traction: steady rolling at slip on a soil (report/traction_json.h, the library call
// of `modaltyre traction`), the command's JSON document with its columns as NumPy arrays.
#include <limits>

#include "bindings.h"
#include "modaltyre/report/traction_json.h"
#include "to_python.h"

namespace modaltyre::python {
namespace {

py::object traction(const py::object& config_arg, const py::object& loads, const py::object& slips,
                    const py::object& ground_arg, const py::dict& overrides,
                    const py::object& passes_arg, const std::string& slip_reference,
                    const py::object& speed_arg) {
  const std::string config_path = path_arg(config_arg, "config_path");
  const std::string ground_path = optional_path_arg(ground_arg, "ground");
  // passes=True is no count (bool is an int in Python); run_traction checks the range.
  const int passes = static_cast<int>(int_arg(passes_arg, "passes", std::numeric_limits<int>::min(),
                                              std::numeric_limits<int>::max()));
  const std::vector<double> load_N = numbers_arg(loads, "loads_N");
  const std::vector<double> slip = numbers_arg(slips, "slips");
  const auto sets = overrides_of(overrides);
  if (slip_reference != "rolling" && slip_reference != "unloaded")
    throw InputError({"slip_reference", 0, ""}, "must be 'rolling' or 'unloaded'");
  const double speed_km_h = speed_arg.is_none() ? -1.0 : number_arg(speed_arg, "speed_km_h");
  if (!speed_arg.is_none() && !(speed_km_h >= 0 && speed_km_h <= 100))
    throw InputError({"speed_km_h", 0, ""}, "must be in [0, 100] km/h");
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    report::TractionSetup setup = report::traction_setup(config_path, ground_path, sets);
    setup.slip_reference = slip_reference == "unloaded" ? contact::SlipReference::unloaded
                                                        : contact::SlipReference::rolling;
    setup.speed_km_h = speed_km_h;
    const double speed = report::traction_speed_km_h(setup);
    const auto results = report::run_traction(setup, load_N, slip, passes);
    contact::TyreConfig config = setup.config;
    report::use_2d_patch_of_3d(config);
    j = report::traction_json(config, setup.ground, results, setup.rigid, passes,
                              setup.slip_reference, setup.rigid ? 0.0 : speed);
  }
  py::dict out = checked(j).cast<py::dict>();
  // The converged cases' numbers as columns (one entry per converged case, in the document's
  // order; a failed slip is in "cases" with its reason, no numbers).
  py::dict columns;
  std::vector<const nlohmann::json*> done;
  for (const auto& c : j.at("cases"))
    if (c.at("converged").get<bool>()) done.push_back(&c);
  if (!done.empty()) {
    for (const auto& [key, value] : done.front()->items()) {
      if (!value.is_number()) continue;
      std::vector<double> column;
      for (const auto* c : done) column.push_back(c->at(key).get<double>());
      columns[py::str(key)] = owned_array(column);
    }
  }
  out["columns"] = columns;
  return out;
}

}  // namespace

void bind_traction(py::module_& m) {
  m.def("traction", &traction, py::arg("config_path"), py::arg("loads_N"), py::arg("slips"),
        py::arg("ground") = py::none(), py::arg("overrides") = py::dict(), py::arg("passes") = 1,
        py::arg("slip_reference") = "rolling", py::arg("speed_km_h") = py::none(),
        "Steady rolling at slip on a soil = `modaltyre traction CONFIG [--ground SOIL] --load "
        "N... --slip S... [--passes P] [--slip-reference R] [--speed-km-h V] --json` "
        "(docs/soil.md section 5): the dict of its document (cases, curves with towed_point "
        "and self_propelled_point) plus 'columns': {slip, load_N, soil_sinkage_mm, "
        "rut_depth_mm, sinking_mm, tyre_deflection_mm, drawbar_pull_N, thrust_N, "
        "motion_resistance_N, compaction_resistance_N, flexing_resistance_N, "
        "bulldozing_resistance_N, torque_Nm, entry_angle_deg, exit_angle_deg, "
        "contact_length_mm, bekker_width_mm, rolling_radius_mm, loaded_radius_mm, window_mm, "
        "tractive_efficiency, iterations (, pass)} as NumPy arrays, one entry per converged "
        "case (load by load, slip by slip, pass by pass). `ground`: a soil file (its keys then "
        "set with overrides {'ground.bekker.n': 0.8}); None: the config's ground: section. "
        "{'tyre.rigid': True}: the rigid wheel. Slip (driven 1 - V/(omega r) > 0, braked "
        "omega r/V - 1 < 0) against r = the rolling radius on the rigid road ('rolling', ISTVS) "
        "or R0 ('unloaded'). speed_km_h: the tyre's flexing loss's speed (0-100; None: the "
        "config's transient.rolling.speed_km_h).");
}

}  // namespace modaltyre::python

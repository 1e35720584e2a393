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
                    const py::object& passes_arg) {
  const std::string config_path = path_arg(config_arg, "config_path");
  const std::string ground_path = optional_path_arg(ground_arg, "ground");
  // passes=True is no count (bool is an int in Python); run_traction checks the range.
  const int passes = static_cast<int>(int_arg(passes_arg, "passes", std::numeric_limits<int>::min(),
                                              std::numeric_limits<int>::max()));
  const std::vector<double> load_N = numbers_arg(loads, "loads_N");
  const std::vector<double> slip = numbers_arg(slips, "slips");
  const auto sets = overrides_of(overrides);
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const report::TractionSetup setup = report::traction_setup(config_path, ground_path, sets);
    const auto results = report::run_traction(setup, load_N, slip, passes);
    contact::TyreConfig config = setup.config;
    report::use_2d_patch_of_3d(config);
    j = report::traction_json(config, setup.ground, results, setup.rigid, passes);
  }
  py::dict out = checked(j).cast<py::dict>();
  // The cases' numbers as columns (one entry per case, in the document's order).
  py::dict columns;
  const auto& cases = j.at("cases");
  if (!cases.empty()) {
    for (const auto& [key, value] : cases.front().items()) {
      if (!value.is_number()) continue;
      std::vector<double> column;
      for (const auto& c : cases) column.push_back(c.at(key).get<double>());
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
        "Steady rolling at slip on a soil = `modaltyre traction CONFIG [--ground SOIL] --load "
        "N... --slip S... [--passes P] --json` (docs/soil.md section 5): the dict of its "
        "document plus 'columns': {slip, load_N, soil_sinkage_mm, rut_depth_mm, sinking_mm, "
        "tyre_deflection_mm, drawbar_pull_N, thrust_N, motion_resistance_N, torque_Nm, "
        "entry_angle_deg, exit_angle_deg, contact_length_mm, bekker_width_mm, iterations (, "
        "pass)} as NumPy arrays, one entry per case (load by load, slip by slip, pass by "
        "pass). `ground`: a soil file (its keys then set with overrides {'ground.bekker.n': "
        "0.8}); None: the config's ground: section. {'tyre.rigid': True}: the rigid wheel. "
        "Slip as Wong: driven 1 - V/(omega R) > 0, braked omega R/V - 1 < 0.");
}

}  // namespace modaltyre::python

// modaltyre.identify: the identify command's fit (report/identify_run.h) without its outputs
// (plot, written configs).
#include <optional>

#include "bindings.h"
#include "modaltyre/report/identify_run.h"
#include "to_python.h"

namespace modaltyre::python {
namespace {

py::object identify(const std::string& method, const py::object& path, const py::object& config,
                    const py::object& r0_mm, const py::object& tread_width_mm,
                    const py::object& mass_kg, const py::object& contact_length_mm,
                    const py::object& section_height_mm, const py::object& pressure_kPa,
                    const py::object& static_loop, int samples, const std::string& sampling,
                    bool intercept, double max_h_r0) {
  report::IdentifyInputs in;  // numbers: -1 = not given, as the command's options
  in.method = method;
  in.file = optional_path_arg(path, "path");
  in.geometry_config =
      report::identify_geometry_config(method, optional_path_arg(config, "config"));
  in.r0_mm = optional_number_arg(r0_mm, "r0_mm").value_or(-1);
  in.tread_width_mm = optional_number_arg(tread_width_mm, "tread_width_mm").value_or(-1);
  in.mass_kg = optional_number_arg(mass_kg, "mass_kg").value_or(-1);
  in.contact_length_mm = optional_number_arg(contact_length_mm, "contact_length_mm").value_or(-1);
  in.section_height_mm = optional_number_arg(section_height_mm, "section_height_mm").value_or(-1);
  in.pressure_kPa = optional_number_arg(pressure_kPa, "pressure_kPa").value_or(-1);
  in.static_file = optional_path_arg(static_loop, "static");
  in.samples = samples;
  in.sampling = sampling;
  in.intercept = intercept;
  in.max_h_r0 = max_h_r0;
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = report::run_identify(in).document;
  }
  return checked(j);
}

}  // namespace

void bind_identify(py::module_& m) {
  m.def("identify", &identify, py::arg("method"), py::arg("path") = py::none(), py::kw_only(),
        py::arg("config") = py::none(), py::arg("r0_mm") = py::none(),
        py::arg("tread_width_mm") = py::none(), py::arg("mass_kg") = py::none(),
        py::arg("contact_length_mm") = py::none(), py::arg("section_height_mm") = py::none(),
        py::arg("pressure_kPa") = py::none(), py::arg("static") = py::none(),
        py::arg("samples") = 6, py::arg("sampling") = "deflection", py::arg("intercept") = false,
        py::arg("max_h_r0") = 0.117,
        "Rheological parameters of seed 000 (`modaltyre identify METHOD PATH --json`): method "
        "load-deflection | b-factors | contact-stress | free-vibration | soil-rolling; options "
        "as the command's (config: a tyre config for r0, pressure and tread width; r0_mm, "
        "tread_width_mm, contact_length_mm, section_height_mm [mm], mass_kg [kg], pressure_kPa "
        "[kPa, gauge], static: the static-loop CSV). Parameters carry their units in the dict.");
}

}  // namespace modaltyre::python

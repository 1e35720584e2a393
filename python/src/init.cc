// modaltyre.init: `modaltyre init` (init/init_tyre.h) from Python: a commented tyre config from
// a size, the modal test's and the operating pressure and the modal data; the same document as
// `init --json` (report/init_json.h), the config text under "config" unless `output` is given.
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/command_files.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/init/init_tyre.h"
#include "modaltyre/report/init_json.h"
#include "to_python.h"

namespace modaltyre::python {
namespace {

// Orders as the CLI's --orders: ints >= 0, or "r" for the rigid rotation mode (-1).
std::vector<int> orders_arg(const py::handle& v) {
  std::vector<int> out;
  if (v.is_none()) return out;
  if (py::isinstance<py::str>(v) || !py::isinstance<py::sequence>(v))
    throw InputError({"orders", 0, ""}, "must be a list of orders (ints >= 0, or 'r')");
  for (const auto& item : v.cast<py::sequence>()) {
    if (py::isinstance<py::str>(item)) {
      const std::string w = item.cast<std::string>();
      if (w != "r" && w != "R")
        throw InputError({"orders", 0, ""},
                         "'" + w + "' is not an order (0-999) or r (the rotation mode)");
      out.push_back(-1);
      continue;
    }
    // An int of any size (2**70 too) or a bool is named, never a RuntimeError of the cast.
    out.push_back(static_cast<int>(int_arg(item, "orders", 0, 999)));
  }
  return out;
}

py::object run_init(const std::string& size, const py::object& test_pressure_kPa,
                    const py::object& pressure_kPa, const py::object& frequencies_hz,
                    const py::object& damping_ratios, const py::object& orders,
                    const py::object& hammer_csv, const py::object& belt_mass_kg,
                    const std::string& boundary, const py::object& wheel_mass_kg,
                    const py::object& belt_width_mm, const py::object& tread_depth_mm,
                    const py::object& tread_width_mm, const py::object& fnomin_N,
                    const std::string& name, bool two_d, const py::object& output) {
  init::InitInputs in;  // numbers: None = not given, as an option left out
  in.size = size;
  in.name = name;
  in.test_pressure_kPa = number_arg(test_pressure_kPa, "test_pressure_kPa");
  in.pressure_kPa = optional_number_arg(pressure_kPa, "pressure_kPa");
  if (!frequencies_hz.is_none()) in.frequencies_hz = numbers_arg(frequencies_hz, "frequencies_hz");
  if (!damping_ratios.is_none()) in.damping_ratios = numbers_arg(damping_ratios, "damping_ratios");
  in.orders = orders_arg(orders);
  in.hammer_csv = optional_path_arg(hammer_csv, "hammer_csv");
  in.belt_mass_kg = optional_number_arg(belt_mass_kg, "belt_mass_kg");
  if (boundary != "free" && boundary != "rim-fixed")
    throw InputError({"boundary", 0, ""}, "'" + boundary + "' is neither free nor rim-fixed");
  in.boundary = boundary;
  in.wheel_mass_kg = optional_number_arg(wheel_mass_kg, "wheel_mass_kg");
  in.belt_width_mm = optional_number_arg(belt_width_mm, "belt_width_mm");
  in.tread_depth_mm = optional_number_arg(tread_depth_mm, "tread_depth_mm");
  in.tread_width_mm = optional_number_arg(tread_width_mm, "tread_width_mm");
  in.fnomin_N = optional_number_arg(fnomin_N, "fnomin_N");
  in.two_d = two_d;
  in.output_path = optional_path_arg(output, "output");
  CommandFiles files;  // the config must not replace the hammer data it names
  files.input(in.hammer_csv, "hammer_csv");
  if (!output.is_none()) files.output(in.output_path, "output");
  files.check();
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const init::InitResult r = init::init_tyre(in);
    j = report::init_json(r, in.output_path);
    if (!in.output_path.empty()) write_file_atomically(in.output_path, r.yaml);
  }
  return checked(j);
}

}  // namespace

void bind_init(py::module_& m) {
  m.def("init", &run_init, py::arg("size"), py::kw_only(), py::arg("test_pressure_kPa"),
        py::arg("pressure_kPa") = py::none(), py::arg("frequencies_hz") = py::none(),
        py::arg("damping_ratios") = py::none(), py::arg("orders") = py::none(),
        py::arg("hammer_csv") = py::none(), py::arg("belt_mass_kg") = py::none(),
        py::arg("boundary") = "free", py::arg("wheel_mass_kg") = py::none(),
        py::arg("belt_width_mm") = py::none(), py::arg("tread_depth_mm") = py::none(),
        py::arg("tread_width_mm") = py::none(), py::arg("fnomin_N") = py::none(),
        py::arg("name") = "", py::arg("two_d") = false, py::arg("output") = py::none(),
        "A tyre config that was never calibrated (`modaltyre init --json`): size designation "
        "(e.g. '195/60R14'), the modal test's and the operating pressure [kPa], and "
        "frequencies_hz (with damping_ratios and orders, 'r' for the rotation mode, if known) "
        "or a hammer_csv; modal masses from the ring's tension (docs/ring_model.md). Returns "
        "what init decided; the config text under 'config', or written to `output`.");
}

}  // namespace modaltyre::python

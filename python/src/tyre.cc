// modaltyre.Tyre, modaltyre.Footprint and modaltyre.fit_modes: the footprint and fit-modes
// commands' library calls (report/footprint_json.h, report/modes_json.h) without the CLI.
#include <memory>
#include <optional>

#include "bindings.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/report/check_finite.h"
#include "modaltyre/report/footprint_json.h"
#include "modaltyre/report/modes_json.h"
#include "to_python.h"

namespace modaltyre::python {
namespace {

// One load case of `footprint --json` with its arrays as NumPy copies.
struct Footprint {
  double load_N = 0;
  double sinking_mm = 0;
  double length_mm = 0;
  py::object width_mm = py::none();
  bool converged = false;
  int iterations = 0;
  bool valid = true;
  py::array_t<double> x_mm, pressure_kPa;
  py::object map = py::none();
  py::dict data;
};

Footprint footprint_of(const nlohmann::json& c, bool patch3d) {
  Footprint f;
  f.load_N = c.at("load_N").get<double>();
  f.sinking_mm = c.at("sinking_mm").get<double>();
  f.length_mm = c.at("contact_length_mm").get<double>();
  if (patch3d) f.width_mm = py::float_(c.at("width_mm").get<double>());
  f.converged = c.at("converged").get<bool>();
  f.iterations = c.at("iterations").get<int>();
  f.valid = c.at("valid").get<bool>();
  f.x_mm = column_of(c.at("units"), "x_mm");
  f.pressure_kPa = column_of(c.at("units"), "pressure_kPa");
  if (c.contains("map")) {
    py::dict m;
    for (const char* k : {"x_mm", "y_mm", "pressure_kPa"}) m[k] = numeric_array(c["map"][k]);
    f.map = std::move(m);
  }
  f.data = to_python(c);
  return f;
}

// The model, built once (immutable, shared by every call; safe to use from several threads).
class Tyre {
 public:
  Tyre(const py::object& config_path_arg, const py::dict& overrides) {
    const std::string config_path = path_arg(config_path_arg, "config_path");
    const auto sets = overrides_of(overrides);
    py::gil_scoped_release release;
    model_ = std::make_shared<const contact::TyreModel>(
        contact::build_tyre_model(contact::load_tyre_config(config_path, sets)));
  }

  // The document of `footprint --json` (checked for non-finite numbers, as the CLI does) at
  // the config's conditions with those stated (`--set hold_s=60`).
  nlohmann::json document(const std::vector<double>& loads, std::optional<double> fx,
                          const py::dict& conditions) const {
    const auto settings = conditions_of(conditions);
    report::refuse_footprint_settings(settings, "load_N", "horizontal_force_N", "conditions");
    py::gil_scoped_release release;
    auto cases = report::footprint_cases(model_->config, loads, fx);
    const auto shown = report::apply_to_footprint_cases(settings, model_->config, cases);
    const auto results = contact::predict_all(*model_, cases);
    report::require_converged(results);
    nlohmann::json j = report::footprint_json(*model_, results);
    j["conditions"] = report::footprint_conditions_json(shown);
    report::check_finite(j);
    return j;
  }

  std::vector<Footprint> footprints(const std::vector<double>& loads, std::optional<double> fx,
                                    const py::dict& conditions) const {
    if (loads.empty()) throw InputError({"loads_N", 0, ""}, "give at least one load [N]");
    const nlohmann::json j = document(loads, fx, conditions);
    std::vector<Footprint> out;
    for (const auto& c : j.at("cases")) out.push_back(footprint_of(c, patch3d()));
    return out;
  }

  bool patch3d() const { return model_->config.footprint_3d.has_value(); }
  const contact::TyreConfig& config() const { return model_->config; }

 private:
  std::shared_ptr<const contact::TyreModel> model_;
};

}  // namespace

void bind_tyre(py::module_& m) {
  py::class_<Footprint>(m, "Footprint",
                        "One static footprint (a case of `modaltyre footprint --json`). Arrays "
                        "are NumPy copies owned by the object.")
      .def_readonly("load_N", &Footprint::load_N, "applied vertical load [N]")
      .def_readonly("sinking_mm", &Footprint::sinking_mm, "sinking (vertical deflection) [mm]")
      .def_readonly("length_mm", &Footprint::length_mm, "contact length along the road [mm]")
      .def_readonly("width_mm", &Footprint::width_mm,
                    "contact width [mm] on the 3D patch; None on the 2D patch (whose width is "
                    "the config's tread.width_mm, an input)")
      .def_readonly("converged", &Footprint::converged, "the contact solver converged")
      .def_readonly("iterations", &Footprint::iterations, "active-set iterations")
      .def_readonly("valid", &Footprint::valid,
                    "inside the model's validity range (README, \"Validity range\"); the reason "
                    "is data['validity']")
      .def_readonly("x_mm", &Footprint::x_mm,
                    "unit positions along the road from the contact centre [mm]")
      .def_readonly("pressure_kPa", &Footprint::pressure_kPa,
                    "contact pressure per unit [kPa] (on the 3D patch: the centre line's)")
      .def_readonly("map", &Footprint::map,
                    "3D patch: {'x_mm': (nx,), 'y_mm': (ny,), 'pressure_kPa': (ny, nx)} "
                    "[mm, mm, kPa]; None on the 2D patch")
      .def_readonly("data", &Footprint::data,
                    "the case as `footprint --json` prints it (every field, lists)")
      .def("__repr__", [](const Footprint& f) {
        return "<Footprint " + std::to_string(f.load_N) + " N: sinking " +
               std::to_string(f.sinking_mm) + " mm, length " + std::to_string(f.length_mm) + " mm>";
      });

  py::class_<Tyre>(m, "Tyre",
                   "A tyre model built once from a config (YAML), shared by every prediction. "
                   "The GIL is released while it is built and while it solves.")
      .def(py::init<const py::object&, const py::dict&>(), py::arg("config_path"),
           py::arg("overrides") = py::dict(),
           "Reads and checks the config (`overrides`: {'tread.modulus_MPa': 8}, like --set) "
           "and builds the model. InputError names file, line and key.")
      .def(
          "footprint",
          [](const Tyre& t, const py::object& load_N, const py::object& fx,
             const py::dict& conditions) {
            return t
                .footprints({number_arg(load_N, "load_N")},
                            optional_number_arg(fx, "horizontal_force_N"), conditions)
                .front();
          },
          py::arg("load_N"), py::arg("horizontal_force_N") = py::none(),
          py::arg("conditions") = py::dict(),
          "The static footprint at `load_N` [N] with `horizontal_force_N` [N] at the axle "
          "(default: the config's) = `modaltyre footprint CONFIG --load N --json`. "
          "`conditions`: {'hold_s': 60, 'surface': 'soil'} = --set hold_s=60 --set surface=soil "
          "(pressure_kPa, hold_s, speed_kmh, branch, surface; README, \"Conditions with --set\").")
      .def(
          "footprints",
          [](const Tyre& t, const py::object& loads, const py::object& fx,
             const py::dict& conditions) {
            return t.footprints(numbers_arg(loads, "loads_N"),
                                optional_number_arg(fx, "horizontal_force_N"), conditions);
          },
          py::arg("loads_N"), py::arg("horizontal_force_N") = py::none(),
          py::arg("conditions") = py::dict(),
          "One Footprint per load [N], in order (one solve per load), at `conditions`.")
      .def(
          "report",
          [](const Tyre& t, const py::object& loads, const py::object& fx,
             const py::dict& conditions) {
            return to_python(t.document(numbers_arg(loads, "loads_N"),
                                        optional_number_arg(fx, "horizontal_force_N"), conditions));
          },
          py::arg("loads_N") = py::tuple(), py::arg("horizontal_force_N") = py::none(),
          py::arg("conditions") = py::dict(),
          "The whole document of `footprint --json` as a dict (default loads: the config's "
          "loads_N), at `conditions` (stated in its 'conditions' object).")
      .def_property_readonly(
          "name", [](const Tyre& t) { return t.config().name; }, "the config's tyre name")
      .def_property_readonly(
          "patch", [](const Tyre& t) { return t.patch3d() ? "3d" : "2d"; },
          "'3d' with a footprint_3d: section, else '2d'")
      .def_property_readonly(
          "loads_N", [](const Tyre& t) { return t.config().loads_N; },
          "the config's default loads [N]");

  m.def(
      "fit_modes",
      [](const py::object& path_object) {
        const std::string path = path_arg(path_object, "path");
        nlohmann::json j;
        {
          py::gil_scoped_release release;
          j = report::modes_json(modal::identify_modes(modal::read_hammer_csv(path)));
        }
        return checked(j);
      },
      py::arg("path"),
      "Harmonic fit of a hammer-test CSV (mode,freq_hz,damping_ratio,point,angle_deg,radial,"
      "tangential): the dict of `modaltyre fit-modes PATH --json` (frequencies [Hz], damping "
      "ratio [-], order, kind, R2, aliasing, dispersion fit [rad^2/s^2]).");
}

}  // namespace modaltyre::python

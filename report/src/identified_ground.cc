#include "modaltyre/report/identified_ground.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "modaltyre/core/config_edit.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::report {
namespace {

// A YAML double-quoted scalar for any text (escapes every quote and control byte).
std::string yaml_text(const std::string& text) {
  YAML::Emitter e;
  e << YAML::DoubleQuoted << text;
  return e.c_str();
}

struct Keys {
  std::vector<std::string> overrides, notes;
  void set(const std::string& key, double value, double lo, double hi, const std::string& where) {
    if (!std::isfinite(value) || value < lo || value > hi)
      throw InputError({where, 0, key}, "the identified value " + number_text(value) +
                                            " is outside the range [" + number_text(lo) + ", " +
                                            number_text(hi) + "] the soil reader takes");
    overrides.push_back(key + "=" + number_text(round_sig(value, 8)));
  }
};

Keys bevameter_keys(const rheology::BevameterResult& r, const rheology::PlateData& d,
                    const std::string& where) {
  Keys k;
  k.overrides.push_back("ground.model=bekker");
  k.set("ground.bekker.n", r.n, 1e-9, 3, where);
  k.set("ground.bekker.k_c", r.k_c, 0, 1e9, where);
  k.set("ground.bekker.k_phi", r.k_phi, 0, 1e12, where);
  k.notes.push_back("ground.bekker.{n, k_c, k_phi}: Bekker's law from the plate-sinkage rows (" +
                    rheology::bekker_b_convention(d.shape) + ")");
  if (r.has_unloading) {
    // A negative k0 has no soil behind it: the fit through the origin instead (said).
    const bool origin = r.k0 < 0;
    k.set("ground.bekker.unloading.k0", origin ? 0.0 : r.k0, 0, 1e12, where);
    k.set("ground.bekker.unloading.Au", origin ? r.Au_through_origin : r.Au, 0, 1e15, where);
    k.notes.push_back(origin ? "ground.bekker.unloading: the fitted k0 < 0 is impossible; "
                               "written: the fit through the origin, k0 = 0, Au = " +
                                   number_text(round_sig(r.Au_through_origin, 6)) + " kN/m^4"
                             : "ground.bekker.unloading.{k0, Au}: Wong's k_u = k0 + Au z_max "
                               "from the unloading cycles");
  }
  return k;
}

Keys shear_keys(const rheology::ShearResult& r, const std::string& section,
                const std::string& where) {
  Keys k;
  k.set(section + "cohesion_kPa", std::max(r.cohesion_kPa, 0.0), 0, 1e5, where);
  k.set(section + "friction_angle_deg", r.friction_angle_deg, 0, 89, where);
  k.set(section + "shear_modulus_K_mm", r.K_mm, 1e-12, 1e4, where);
  k.notes.push_back(section +
                    "{cohesion_kPa, friction_angle_deg, shear_modulus_K_mm}: "
                    "Janosi-Hanamoto from the shear rows" +
                    (r.cohesion_kPa < 0 ? " (the fitted c < 0 written as 0)" : ""));
  return k;
}

// A new soil file's skeleton: the identified keys are set into it like into a BASE.
std::string new_soil_text(const std::string& data_file) {
  const std::string stem = std::filesystem::path(data_file).stem().string();
  return "ground:\n  model: bekker\n  name: " + yaml_text(stem + " (identified)") +
         "\n  source: " + yaml_text("modaltyre identify bevameter " + data_file) +
         "\n  bekker:\n    n: 1\n    k_c: 0\n    k_phi: 1\n";
}

}  // namespace

IdentifiedGround identified_ground_file(const IdentifyRun& run, const std::string& data_file,
                                        const std::string& base_path, const std::string& out_path) {
  const auto* bev = std::get_if<BevameterRun>(&run.fit);
  const auto* shear = std::get_if<ShearRun>(&run.fit);
  if (!bev && !shear)
    throw InputError({"--write-ground", 0, ""},
                     "a soil file takes the soil tests: identify bevameter or shear");
  std::string text;
  ground::GroundSettings base;
  if (!base_path.empty()) {
    text = read_yaml_file(base_path, "a soil file");
    base = ground::load_ground_file(base_path);
    // A plate test's file said it had no shear keys yet: the shear test now gives them.
    if (shear) {
      const std::string stale = "# No shear keys yet:";
      const std::size_t at = text.find(stale);
      if (at != std::string::npos && (at == 0 || text[at - 1] == '\n'))
        text.erase(at, text.find('\n', at) - at + 1);
    }
  } else if (shear) {
    throw InputError({"--write-ground", 0, ""},
                     "a shear test gives no pressure-sinkage law, so a soil file of it alone "
                     "would run on assumed normal keys: write it into the plate test's soil "
                     "file with --into-ground SOIL.yaml (identify bevameter ... --write-ground "
                     "SOIL.yaml first)");
  } else {
    text = new_soil_text(data_file);
  }
  const std::string where = base_path.empty() ? out_path : base_path;
  Keys keys;
  if (bev) {
    if (!base_path.empty() && base.model != ground::GroundModel::bekker)
      throw InputError({base_path, 0, "ground.model"},
                       "the plate test gives a Bekker soil; this soil file is " +
                           std::string(ground::to_string(base.model)) +
                           ": write a new file (--write-ground without --into-ground)");
    keys = bevameter_keys(bev->result, bev->data, where);
  } else {
    if (!base.soil())
      throw InputError({base_path, 0, "ground.model"},
                       "--into-ground takes a soil file (model bekker or kelvin_voigt)");
    keys = shear_keys(
        shear->result,
        base.model == ground::GroundModel::bekker ? "ground.bekker." : "ground.kelvin_voigt.",
        where);
  }
  const std::string marker = "set by modaltyre identify " + run.document.value("method", "");
  const std::optional<std::string> edited =
      set_keys_in_text(text, base_path.empty() ? out_path : base_path, keys.overrides, marker);
  IdentifiedGround out;
  out.notes = keys.notes;
  out.text = "# Soil file written by modaltyre identify " + run.document.value("method", "") +
             " from " + printable(data_file, 200) +
             (base_path.empty() ? "" : " into " + printable(base_path, 200)) +
             " (docs/soil.md section 6).\n";
  for (const auto& n : out.notes) out.text += "# " + n + "\n";
  if (bev && base_path.empty())
    out.text +=
        "# No shear keys yet: identify shear SHEAR.csv --into-ground THIS_FILE --write-ground "
        "OUT.yaml adds them (traction needs them).\n";
  out.text += edited ? *edited : ConfigTree::from_string(text, where, keys.overrides).dump();
  // Read back as --ground reads it: the file written is one the soil reader takes.
  const ConfigTree tree = ConfigTree::from_string(out.text, out_path);
  out.ground = ground::read_ground_settings(tree.root().section("ground"), tree);
  tree.reject_unknown_keys();
  return out;
}

}  // namespace modaltyre::report

#include "modaltyre/studies/measurements.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::studies {

using contact::Branch;
using contact::observable_names;
using contact::OperatingConditions;
using contact::Surface;
using contact::TyreConfig;

const std::vector<std::string>& condition_names() {
  static const std::vector<std::string> names = {
      "load_N", "pressure_kPa", "hold_s", "speed_kmh", "branch", "surface", "horizontal_force_N"};
  return names;
}

std::optional<double> MeasuredRow::value(const std::string& observable) const {
  const auto it = observed.find(observable);
  return it == observed.end() ? std::nullopt : std::optional<double>(it->second);
}

double condition_value(const OperatingConditions& c, const std::string& name) {
  if (name == "load_N") return c.load_N;
  if (name == "pressure_kPa") return c.pressure_kPa;
  if (name == "hold_s") return c.hold_s;
  if (name == "speed_kmh") return c.speed_kmh;
  if (name == "branch") return c.branch == Branch::unloading ? 1.0 : 0.0;
  if (name == "surface") return c.surface == Surface::soil ? 1.0 : 0.0;
  if (name == "horizontal_force_N") return c.horizontal_force_N;
  throw std::invalid_argument("unknown condition " + name);
}

MeasurementSet read_measurements(const std::string& path, const TyreConfig& defaults) {
  CsvSchema schema;
  schema.required = {"load_N"};
  schema.optional = {
      "pressure_kPa", "hold_s", "speed_kmh", "horizontal_force_N", "branch", "surface",
      // written by `modaltyre sweep`, ignored here
      "vertical_stiffness_N_mm", "peak_pressure_kPa", "iterations", "valid", "status", "message"};
  schema.text = {"branch", "surface", "valid", "status", "message"};
  for (const auto& o : observable_names()) schema.optional.push_back(o);
  // A failed sweep row has empty number cells: the status check below names it before they
  // are read.
  schema.may_be_empty = {"message", "vertical_stiffness_N_mm", "peak_pressure_kPa", "iterations",
                         "valid"};
  for (const auto& o : observable_names()) schema.may_be_empty.push_back(o);
  // A sweep's parameter columns are dotted config keys, ignored here.
  schema.accept_text_column = [](const std::string& c) { return c.find('.') != std::string::npos; };
  const CsvTable t = read_csv(path, schema);
  MeasurementSet set;
  set.path = path;
  for (const auto& o : observable_names()) {
    if (t.has(o)) set.observables.push_back(o);
  }
  for (const auto& c : condition_names()) {
    if (t.has(c)) set.conditions.push_back(c);
  }
  set.loads_only = true;
  for (const auto& c : t.columns()) {
    set.loads_only = set.loads_only &&
                     (c == "load_N" || c == "sinking_mm" || c == "length_mm" || c == "width_mm");
  }
  if (set.observables.empty()) {
    throw InputError({path, 1, "sinking_mm"},
                     "no observable column: give any of sinking_mm, length_mm, width_mm, "
                     "rolling_resistance_N");
  }
  for (std::size_t i = 0; i < t.rows(); ++i) {
    MeasuredRow r;
    r.row = static_cast<int>(i) + 1;
    r.line = t.line(i);
    auto at = [&](const std::string& col) { return InputLocation{path, r.line, col}; };
    if (t.has("status") && t.text(i, "status") != "ok") {
      throw InputError(at("status"), "row is marked '" + printable(t.text(i, "status")) +
                                         "': remove failed sweep rows from measured data");
    }
    r.conditions = defaults.default_conditions(t.number(i, "load_N"));
    OperatingConditions& c = r.conditions;
    // The tyre config's limits (loads_N, horizontal_force_N): beyond them a unit error, and the
    // solver would fail on it instead of the reader saying so.
    if (!(c.load_N >= contact::kMinLoad_N && c.load_N <= contact::kMaxLoad_N)) {
      throw InputError(at("load_N"), "load must be in [1e-6, 1e7] N");
    }
    if (t.has("pressure_kPa")) {
      c.pressure_kPa = t.number(i, "pressure_kPa");
      if (!(c.pressure_kPa > 0 && c.pressure_kPa <= 2000)) {
        throw InputError(at("pressure_kPa"), "inflation pressure must be in (0, 2000] kPa");
      }
    }
    if (t.has("hold_s")) {
      c.hold_s = t.number(i, "hold_s");
      // The sweep's limit on condition values: 1e7 s (116 days) is far past any creep.
      if (!(c.hold_s >= 0 && c.hold_s <= 1e7)) {
        throw InputError(at("hold_s"), "hold time must be in [0, 1e7] s");
      }
    }
    if (t.has("speed_kmh")) {
      c.speed_kmh = t.number(i, "speed_kmh");
      if (!(c.speed_kmh >= 0 && c.speed_kmh <= 400)) {
        throw InputError(at("speed_kmh"), "speed must be in [0, 400] km/h");
      }
    }
    if (t.has("horizontal_force_N")) {
      c.horizontal_force_N = t.number(i, "horizontal_force_N");
      if (!(std::abs(c.horizontal_force_N) <= 1e7)) {
        throw InputError(at("horizontal_force_N"), "horizontal force must be in [-1e7, 1e7] N");
      }
      if (defaults.footprint_3d && c.horizontal_force_N != 0) {
        throw InputError(at("horizontal_force_N"),
                         "the config's 3D patch (footprint_3d) takes no horizontal force");
      }
    }
    if (t.has("branch")) {
      const std::string& b = t.text(i, "branch");
      if (b == "load" || b == "loading") {
        c.branch = Branch::loading;
      } else if (b == "unload" || b == "unloading") {
        c.branch = Branch::unloading;
      } else {
        throw InputError(at("branch"), "'" + printable(b) + "' is not one of: load, unload");
      }
    }
    if (t.has("surface")) {
      const std::string& s = t.text(i, "surface");
      if (s == "rigid") {
        c.surface = Surface::rigid;
      } else if (s == "soil") {
        c.surface = Surface::soil;
      } else {
        throw InputError(at("surface"), "'" + printable(s) + "' is not one of: rigid, soil");
      }
    }
    for (const auto& o : set.observables) {
      const double v = t.number(i, o);
      if (o != "rolling_resistance_N" && !(v > 0)) throw InputError(at(o), "must be > 0 mm");
      // A footprint of tens of metres is a unit error (and a calibration target no model meets).
      if (o != "rolling_resistance_N" && v > 1e4) throw InputError(at(o), "must be at most 1e4 mm");
      if (o == "rolling_resistance_N" && !(std::abs(v) <= 1e7))
        throw InputError(at(o), "must be in [-1e7, 1e7] N");
      r.observed[o] = v;
    }
    set.rows.push_back(std::move(r));
  }
  return set;
}

}  // namespace modaltyre::studies

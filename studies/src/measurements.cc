#include "modaltyre/studies/measurements.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/conditions.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/studies/traction_rows.h"

namespace modaltyre::studies {

using contact::observable_names;
using contact::OperatingConditions;
using contact::TyreConfig;

const std::vector<std::string>& condition_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& c : condition_catalogue()) n.push_back(c.name);
    return n;
  }();
  return names;
}

std::optional<double> MeasuredRow::value(const std::string& observable) const {
  const auto it = observed.find(observable);
  return it == observed.end() ? std::nullopt : std::optional<double>(it->second);
}

double condition_value(const OperatingConditions& c, const std::string& name) {
  const ConditionInfo* info = find_condition(name);
  if (info == nullptr) throw std::invalid_argument("unknown condition " + name);
  return contact::condition_value(c, info->id);
}

int MeasurementSet::traction_rows() const {
  int n = 0;
  for (const auto& r : rows) n += r.traction.has_value();
  return n;
}

std::string std_column(const std::string& observable) {
  const auto unit = observable.rfind('_');
  return observable.substr(0, unit) + "_std" + observable.substr(unit);
}

MeasurementSet read_measurements(const std::string& path, const TyreConfig& defaults) {
  CsvSchema schema;
  schema.required = {"load_N"};
  // Numbers first, then words: the order the "expected:" list of an unknown column shows.
  for (const bool text : {false, true}) {
    for (const auto& c : condition_catalogue()) {
      // A footprint row states no slip (footprint_refusal): traction rows carry it.
      if (c.id == ConditionId::load_N || !footprint_refusal(c.id).empty() || c.is_text() != text)
        continue;
      schema.optional.push_back(c.name);
      if (text) schema.text.push_back(c.name);
    }
  }
  // written by `modaltyre sweep`, ignored here
  for (const char* c :
       {"vertical_stiffness_N_mm", "peak_pressure_kPa", "iterations", "valid", "status", "message"})
    schema.optional.push_back(c);
  for (const char* c : {"valid", "status", "message"}) schema.text.push_back(c);
  for (const auto& o : observable_names()) schema.optional.push_back(o);
  for (const auto& o : observable_names()) schema.optional.push_back(std_column(o));
  // A failed sweep row has empty number cells: the status check below names it before they
  // are read.
  schema.may_be_empty = {"message", "vertical_stiffness_N_mm", "peak_pressure_kPa", "iterations",
                         "valid"};
  // A measurement left out of a row (not measured, or lost) is an empty cell or NA: that row
  // then compares the observables it has (issue 38).
  for (const auto& o : observable_names()) schema.may_be_empty.push_back(o);
  for (const auto& o : observable_names()) schema.may_be_empty.push_back(std_column(o));
  add_traction_columns(schema);
  schema.missing_words = {"NA", "N/A"};  // R, spreadsheets; "nan" stays refused as a number
  // A sweep's parameter columns are dotted config keys, ignored here.
  schema.accept_text_column = [](const std::string& c) { return c.find('.') != std::string::npos; };
  const CsvTable t = read_csv(path, schema);
  MeasurementSet set;
  set.path = path;
  for (const auto& o : observable_names()) {
    if (t.has(o)) set.observables.push_back(o);
  }
  for (const auto& o : traction_observable_names()) {
    if (t.has(o)) set.observables.push_back(o);
  }
  check_traction_columns(t);
  for (const auto& c : condition_names()) {
    if (t.has(c)) set.conditions.push_back(c);
  }
  set.loads_only = true;
  for (const auto& c : t.columns()) {
    set.loads_only = set.loads_only &&
                     (c == "load_N" || c == "sinking_mm" || c == "length_mm" || c == "width_mm" ||
                      c == "sinking_std_mm" || c == "length_std_mm" || c == "width_std_mm");
  }
  for (const auto& o : observable_names()) {
    if (t.has(std_column(o)) && !t.has(o)) {
      throw InputError(
          {path, 1, std_column(o)},
          "a standard deviation without its measurement: the file has no " + o + " column");
    }
  }
  if (set.observables.empty()) {
    throw InputError({path, 1, "sinking_mm"},
                     "no observable column: give any of sinking_mm, length_mm, width_mm, "
                     "rolling_resistance_N, or a traction test's slip with any of "
                     "drawbar_pull_N, soil_sinkage_mm, torque_Nm");
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
    for (const auto& info : condition_catalogue()) {
      if (!t.has(info.name) || is_traction_column(info.name)) continue;
      double v = 0;
      if (info.is_text()) {
        const std::string& word = t.text(i, info.name);
        const auto value = info.value_of(word);
        if (!value) throw InputError(at(info.name), info.refusal(word));
        v = *value;
      } else {
        v = t.number(i, info.name);
        if (!info.in_range(v)) throw InputError(at(info.name), info.refusal(number_text(v)));
      }
      contact::set_condition(c, info.id, v);
    }
    if (defaults.footprint_3d && t.has("horizontal_force_N") && c.horizontal_force_N != 0) {
      throw InputError(at("horizontal_force_N"),
                       "the config's 3D patch (footprint_3d) takes no horizontal force");
    }
    const bool traction = is_traction_row(t, i);
    refuse_mixed_row(t, i, traction);
    if (traction) {
      read_traction_row(t, i, set.observables, defaults.transient.rolling.speed_m_s * 3.6, r);
      set.rows.push_back(std::move(r));
      continue;
    }
    for (const auto& o : set.observables) {
      if (is_traction_observable(o) || t.missing(i, o)) continue;  // not measured in this row
      const double v = t.number(i, o);
      if (o != "rolling_resistance_N" && !(v > 0)) throw InputError(at(o), "must be > 0 mm");
      // A footprint of tens of metres is a unit error (and a calibration target no model meets).
      if (o != "rolling_resistance_N" && v > 1e4) throw InputError(at(o), "must be at most 1e4 mm");
      if (o == "rolling_resistance_N" && !(std::abs(v) <= 1e7))
        throw InputError(at(o), "must be in [-1e7, 1e7] N");
      r.observed[o] = v;
      const std::string sc = std_column(o);
      if (!t.has(sc) || t.missing(i, sc)) continue;  // its noise not stated
      const double sd = t.number(i, sc);
      if (!(sd >= 0 && sd <= std::max(std::abs(v), 1.0) * 1e3)) {
        throw InputError(at(sc),
                         "a standard deviation must be >= 0 (and not 1000 times the value)");
      }
      r.observed_std[o] = sd;
    }
    if (r.observed.empty()) {
      throw InputError(at(set.observables.front()),
                       "no measured value in this row (every observable is empty or NA): "
                       "remove the row");
    }
    set.rows.push_back(std::move(r));
  }
  return set;
}

}  // namespace modaltyre::studies

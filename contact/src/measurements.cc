#include "modaltyre/contact/measurements.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::contact {
namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> cols;
  std::stringstream ss(line);
  std::string c;
  while (std::getline(ss, c, ',')) cols.push_back(trimmed(c));
  if (!line.empty() && line.back() == ',') cols.push_back("");
  return cols;
}

// Header of the file as read_csv() sees it (UTF-8 BOM dropped, first line that is neither
// blank nor a comment after trimming, cells trimmed), with its line number.
std::vector<std::string> header_of(const std::string& path, int* header_line) {
  std::ifstream in(path, std::ios::binary);
  std::string raw;
  int line_no = 0;
  while (in && std::getline(in, raw)) {
    ++line_no;
    if (line_no == 1 && raw.compare(0, 3, "\xEF\xBB\xBF") == 0) raw.erase(0, 3);
    const std::string line = trimmed(raw);
    if (line.empty() || line[0] == '#') continue;
    *header_line = line_no;
    return fields_of(line);
  }
  return {};
}

// The cells of line `wanted` of the file (empty if there is no such line).
std::vector<std::string> cells_on_line(const std::string& path, int wanted) {
  std::ifstream in(path, std::ios::binary);
  std::string raw;
  for (int line_no = 1; in && std::getline(in, raw); ++line_no) {
    if (line_no == wanted) return fields_of(trimmed(raw));
  }
  return {};
}

}  // namespace

const std::vector<std::string>& condition_names() {
  static const std::vector<std::string> names = {
      "load_N", "pressure_kPa", "hold_s", "speed_kmh", "branch", "surface", "horizontal_force_N"};
  return names;
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
      "vertical_stiffness_N_mm", "peak_pressure_kPa", "iterations", "status", "message"};
  schema.text = {"branch", "surface", "status", "message"};
  for (const auto& o : observable_names()) schema.optional.push_back(o);
  {
    // A FIFO or device would block both readings of the file below: refuse it instead.
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(path, ec) && !fs::is_directory(path, ec) && !fs::is_regular_file(path, ec)) {
      throw InputError({path, 0, ""}, "is not a regular file (a pipe or device?)");
    }
  }
  int header_line = 0;
  const std::vector<std::string> header = header_of(path, &header_line);
  for (const auto& c : header) {
    if (c.find('.') != std::string::npos) {  // a sweep's parameter column (dotted config key)
      schema.optional.push_back(c);
      schema.text.push_back(c);
    }
  }
  CsvTable t;
  try {
    t = read_csv(path, schema);
  } catch (const InputError& e) {
    // A failed sweep row has empty observable cells: say that it failed rather than that its
    // first empty cell is not a number.
    const auto status = std::find(header.begin(), header.end(), "status");
    if (status != header.end() && e.where().line > header_line) {
      const auto cells = cells_on_line(path, e.where().line);
      const auto k = static_cast<std::size_t>(status - header.begin());
      if (cells.size() == header.size() && !cells[k].empty() && cells[k] != "ok") {
        throw InputError(
            {path, e.where().line, "status"},
            "row is marked '" + cells[k] + "': remove failed sweep rows from measured data");
      }
    }
    throw;
  }
  MeasurementSet set;
  set.path = path;
  for (const auto& o : observable_names()) {
    if (t.has(o)) set.observables.push_back(o);
  }
  for (const auto& c : condition_names()) {
    if (t.has(c)) set.conditions.push_back(c);
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
      throw InputError(at("status"), "row is marked '" + t.text(i, "status") +
                                         "': remove failed sweep rows from measured data");
    }
    r.conditions = defaults.default_conditions(t.number(i, "load_N"));
    OperatingConditions& c = r.conditions;
    if (!(c.load_N > 0)) throw InputError(at("load_N"), "load must be > 0 N");
    if (t.has("pressure_kPa")) {
      c.pressure_kPa = t.number(i, "pressure_kPa");
      if (!(c.pressure_kPa > 0 && c.pressure_kPa <= 2000)) {
        throw InputError(at("pressure_kPa"), "inflation pressure must be in (0, 2000] kPa");
      }
    }
    if (t.has("hold_s")) {
      c.hold_s = t.number(i, "hold_s");
      if (!(c.hold_s >= 0)) throw InputError(at("hold_s"), "hold time must be >= 0 s");
    }
    if (t.has("speed_kmh")) {
      c.speed_kmh = t.number(i, "speed_kmh");
      if (!(c.speed_kmh >= 0 && c.speed_kmh <= 400)) {
        throw InputError(at("speed_kmh"), "speed must be in [0, 400] km/h");
      }
    }
    if (t.has("horizontal_force_N")) c.horizontal_force_N = t.number(i, "horizontal_force_N");
    if (t.has("branch")) {
      const std::string& b = t.text(i, "branch");
      if (b == "load" || b == "loading") {
        c.branch = Branch::loading;
      } else if (b == "unload" || b == "unloading") {
        c.branch = Branch::unloading;
      } else {
        throw InputError(at("branch"), "'" + b + "' is not one of: load, unload");
      }
    }
    if (t.has("surface")) {
      const std::string& s = t.text(i, "surface");
      if (s == "rigid") {
        c.surface = Surface::rigid;
      } else if (s == "soil") {
        c.surface = Surface::soil;
      } else {
        throw InputError(at("surface"), "'" + s + "' is not one of: rigid, soil");
      }
    }
    for (const auto& o : set.observables) {
      const double v = t.number(i, o);
      if (o != "rolling_resistance_N" && !(v > 0)) throw InputError(at(o), "must be > 0 mm");
      r.observed[o] = v;
    }
    set.rows.push_back(std::move(r));
  }
  return set;
}

}  // namespace modaltyre::contact

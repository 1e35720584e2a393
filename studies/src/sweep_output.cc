#include "modaltyre/studies/sweep_output.h"

#include <cmath>

#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::studies {

using namespace contact;

const std::vector<std::string>& sweep_observable_columns() {
  // The observables of predictor.h first (the columns read_measurements() reads), then the
  // solver's by-products (which it ignores).
  static const std::vector<std::string> cols = {"sinking_mm",
                                                "length_mm",
                                                "width_mm",
                                                "rolling_resistance_N",
                                                "vertical_stiffness_N_mm",
                                                "peak_pressure_kPa",
                                                "iterations",
                                                "status",
                                                "message",
                                                "valid"};
  return cols;
}

const std::vector<std::string>& sweep_std_columns() {
  static const std::vector<std::string> cols = {"sinking_std_mm", "length_std_mm", "width_std_mm"};
  return cols;
}

std::string sweep_number(double v) { return number_text(v); }

std::string csv_field(const std::string& text) {
  std::string t = text;
  for (char& c : t) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  if (t.find_first_of(",\"") == std::string::npos) return t;
  std::string q = "\"";
  for (char c : t) {
    if (c == '"') q.push_back('"');
    q.push_back(c);
  }
  q.push_back('"');
  return q;
}

std::string sweep_csv_header(const SweepPlan& plan, bool with_std) {
  std::string out;
  bool first = true;
  for (const auto& c : plan.columns) {
    out += (first ? "" : ",") + csv_field(c);
    first = false;
  }
  for (const auto& c : sweep_observable_columns()) out += "," + c;
  if (with_std) {
    for (const auto& c : sweep_std_columns()) out += "," + c;
  }
  out += "\n";
  return out;
}

std::string sweep_csv_row(const SweepPlan& plan, const SweepRow& r, std::size_t i,
                          const SweepStd* std) {
  std::string out;
  bool first = true;
  for (const auto& cell : plan.cells(i)) {
    if (!first) out += ",";
    out += cell;
    first = false;
  }
  if (r.ok) {
    for (double v : {r.sinking_mm, r.length_mm, r.width_mm, r.rolling_resistance_N,
                     r.vertical_stiffness_N_mm, r.peak_pressure_kPa}) {
      out += "," + sweep_number(v);
    }
    out += "," + std::to_string(r.iterations) + ",ok," + csv_field(r.message) +
           (r.valid ? ",true" : ",false");
  } else {
    out += ",,,,,,,,failed," + csv_field(r.message) + ",";
  }
  if (std) {
    for (double v : *std) out += "," + (r.ok && std::isfinite(v) ? sweep_number(v) : "");
  }
  out += "\n";
  return out;
}

std::string sweep_csv(const SweepPlan& plan, const SweepResult& result,
                      const std::vector<SweepStd>* stds) {
  MODALTYRE_CHECK(result.rows.size() == plan.cases.size(), "sweep rows and cases disagree");
  MODALTYRE_CHECK(!stds || stds->size() == plan.cases.size(), "sweep stds and cases disagree");
  std::string out = sweep_csv_header(plan, stds != nullptr);
  out.reserve(plan.cases.size() * 96);
  for (std::size_t i = 0; i < plan.cases.size(); ++i) {
    out += sweep_csv_row(plan, result.rows[i], i, stds ? &(*stds)[i] : nullptr);
  }
  return out;
}

}  // namespace modaltyre::studies

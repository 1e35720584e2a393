#include "modaltyre/studies/traction_rows.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/conditions.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::studies {
namespace {

constexpr const char* kSlip = "slip";
constexpr const char* kPass = "pass";
// The ranges of `modaltyre traction` (app/cmd_traction.cc, report/traction_run.cc).
constexpr double kMinSlip = -0.99, kMaxSlip = 1;
constexpr int kMaxPasses = 20;
// The flexing loss's speed range of `traction --speed-km-h` (report/traction_run.cc).
constexpr double kMaxTractionSpeed_kmh = 100;

bool has_traction_observable(const CsvTable& t) {
  for (const auto& o : traction_observable_names())
    if (t.has(o)) return true;
  return false;
}

}  // namespace

const std::vector<std::string>& traction_observable_names() {
  static const std::vector<std::string> names = {"drawbar_pull_N", "soil_sinkage_mm", "torque_Nm"};
  return names;
}

bool is_traction_observable(const std::string& name) {
  const auto& n = traction_observable_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

void add_traction_columns(CsvSchema& schema) {
  // A file may hold footprint rows (slip empty) and traction rows side by side.
  for (const char* c : {kSlip, kPass}) {
    // The slip may be a condition of the catalogue too (core/conditions.h): declared once.
    if (std::find(schema.optional.begin(), schema.optional.end(), c) == schema.optional.end())
      schema.optional.push_back(c);
    schema.may_be_empty.push_back(c);
  }
  for (const auto& o : traction_observable_names()) {
    schema.optional.push_back(o);
    schema.may_be_empty.push_back(o);
  }
}

void check_traction_columns(const CsvTable& t) {
  const bool observed = has_traction_observable(t);
  if (observed && !t.has(kSlip)) {
    for (const auto& o : traction_observable_names())
      if (t.has(o))
        throw InputError({t.path(), 1, o},
                         "a traction observable needs a slip column (the slip of each row, ISTVS "
                         "against the rolling radius, as `modaltyre traction` takes it)");
  }
  for (const char* c : {kSlip, kPass})
    if (t.has(c) && !observed)
      throw InputError({t.path(), 1, c},
                       std::string("a ") + c +
                           " column without a traction observable: give any of drawbar_pull_N, "
                           "soil_sinkage_mm, torque_Nm");
}

bool is_traction_column(const std::string& name) { return name == kSlip || name == kPass; }

bool is_traction_row(const CsvTable& t, std::size_t i) {
  return t.has(kSlip) && !t.missing(i, kSlip);
}

void refuse_mixed_row(const CsvTable& t, std::size_t i, bool traction_row) {
  const int line = t.line(i);
  if (!traction_row) {
    if (t.has(kPass) && !t.missing(i, kPass))
      throw InputError({t.path(), line, kPass}, "a pass without a slip: give the row's slip");
    for (const auto& o : traction_observable_names())
      if (t.has(o) && !t.missing(i, o))
        throw InputError({t.path(), line, o},
                         "a traction observable in a row without a slip: give the row's slip, or "
                         "leave " +
                             o + " empty in a footprint row");
    return;
  }
  for (const auto& o : contact::observable_names())
    if (t.has(o) && !t.missing(i, o))
      throw InputError({t.path(), line, o},
                       "a footprint observable in a traction row (its slip is given): a row is "
                       "either a footprint (slip empty) or a traction test (" +
                           o + " empty)");
}

void read_traction_row(const CsvTable& t, std::size_t i,
                       const std::vector<std::string>& observables, double rolling_speed_kmh,
                       MeasuredRow& r) {
  auto at = [&](const std::string& col) { return InputLocation{t.path(), r.line, col}; };
  TractionPoint p;
  p.slip = t.number(i, kSlip);
  // The catalogue's range and words first (core/conditions.h), then traction's own.
  if (const ConditionInfo* c = find_condition(kSlip); c && !c->in_range(p.slip))
    throw InputError(at(kSlip), c->refusal(number_text(p.slip)));
  if (!(p.slip >= kMinSlip && p.slip <= kMaxSlip))
    throw InputError(at(kSlip), "slip " + number_text(p.slip) +
                                    " outside [-0.99, 1] (a braked wheel locks at -1, a driven "
                                    "one spins in place at 1; slip is a fraction, not %)");
  if (t.has(kPass) && !t.missing(i, kPass)) {
    const double pass = t.number(i, kPass);
    if (!(pass >= 1 && pass <= kMaxPasses && pass == std::floor(pass)))
      throw InputError(at(kPass), "pass " + number_text(pass) + " must be a whole number 1-20");
    p.pass = static_cast<int>(pass);
  }
  r.traction = p;
  r.conditions.slip = p.slip;  // the condition the soil effects' regime is (core/conditions.h)
  if (!t.has("speed_kmh")) r.conditions.speed_kmh = rolling_speed_kmh;
  if (!(r.conditions.speed_kmh <= kMaxTractionSpeed_kmh))
    throw InputError(at("speed_kmh"),
                     "a traction row's speed (its tyre's flexing loss) must be at most 100 km/h, "
                     "got " +
                         number_text(r.conditions.speed_kmh) +
                         " (steady traction on soil is a slow process)");
  for (const auto& o : observables) {
    if (!is_traction_observable(o) || t.missing(i, o)) continue;
    const double v = t.number(i, o);
    if (o == "soil_sinkage_mm" && !(v > 0 && v <= 1e4))
      throw InputError(at(o), "must be in (0, 1e4] mm");
    if (o != "soil_sinkage_mm" && !(std::abs(v) <= 1e7))
      throw InputError(at(o), "must be in [-1e7, 1e7]");
    r.observed[o] = v;
  }
  if (r.observed.empty())
    throw InputError(at(kSlip),
                     "no measured value in this traction row (drawbar_pull_N, soil_sinkage_mm "
                     "and torque_Nm empty or NA): remove the row");
}

}  // namespace modaltyre::studies

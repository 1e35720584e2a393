#pragma once
// The operating-condition catalogue: every condition a measurement row, a sweep case or a
// command's `--set` can state (name, unit, range, meaning, and for the text conditions the
// words that name each value), declared once. Readers check values against it: the measurement
// CSV (studies/measurements.h), the sweep file (studies/sweep_spec.h), rheology's static loop
// (its branch column). The values act on the tyre through contact::OperatingConditions
// (contact/effects.h), which binds each entry to its field; this table is vocabulary only.
//
//   load_N              vertical load [N], in [1e-6, 1e7]
//   pressure_kPa        gauge inflation pressure [kPa], in (0, 2000]
//   hold_s              time the load has been held [s], in [0, 1e7] (1e7 s, 116 days, is far
//                       past any creep)
//   speed_kmh           rolling speed [km/h], in [0, 400]
//   branch              load | unload (also: loading | unloading)
//   surface             rigid | soil
//   horizontal_force_N  horizontal force at the axle [N], in [-1e7, 1e7]
//   slip                slip of a traction row (as `traction --slip` takes it), in [-1, 1]; a
//                       footprint row is standing or free-rolling and states none
// The upper limits are those of the tyre config's own keys: beyond them a unit error, which a
// solver would fail on instead of the reader saying so.
#include <optional>
#include <string>
#include <vector>

namespace modaltyre {

/// In condition_catalogue() order (the order discover reports conditions in).
enum class ConditionId {
  load_N,
  pressure_kPa,
  hold_s,
  speed_kmh,
  branch,
  surface,
  horizontal_force_N,
  slip
};

struct ConditionInfo {
  ConditionId id;
  std::string name;     ///< CSV column, sweep key and `--set` name, e.g. "hold_s"
  std::string unit;     ///< "" for a text condition
  std::string meaning;  ///< what it is, used in messages: "hold time"
  double min = 0, max = 0;
  bool min_open = false;  ///< (min, max] instead of [min, max]
  /// Text conditions: words[i] names value i (the first word is the one written back);
  /// empty for a number.
  std::vector<std::vector<std::string>> words = {};

  bool is_text() const { return !words.empty(); }
  /// "(0, 2000] kPa"; for a text condition "load, unload".
  std::string range_text() const;
  bool in_range(double v) const { return (min_open ? v > min : v >= min) && v <= max; }
  /// The value a word names (an index into words); nullopt for any other word.
  std::optional<int> value_of(const std::string& word) const;
  /// The message for a value outside the range or a word not in the list, e.g. "hold time must
  /// be in [0, 1e7] s, got -1" or "'up' is not one of: load, unload (or loading, unloading)";
  /// `given` is the value as written.
  std::string refusal(const std::string& given) const;
};

/// Every condition, in ConditionId order.
const std::vector<ConditionInfo>& condition_catalogue();
const ConditionInfo& condition_info(ConditionId id);
/// nullptr when no condition has that name.
const ConditionInfo* find_condition(const std::string& name);

}  // namespace modaltyre

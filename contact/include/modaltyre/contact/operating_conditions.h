#pragma once
// The operating conditions one prediction is taken at (a measurement row, a sweep case, a
// command's `--set`), bound to the condition catalogue of core/conditions.h: names, units,
// ranges and words are declared there once; this header holds the values and reads and writes
// them by catalogue entry.
#include <optional>
#include <string>

#include "modaltyre/core/conditions.h"

namespace modaltyre::contact {

/// In the order of the catalogue's words (branch: load, unload; surface: rigid, soil).
enum class Branch { loading, unloading };
enum class Surface { rigid, soil };

/// Conditions of one measurement row or sweep case (defaults: the config's).
/// A record of what the user stated, in the units of the measurement CSV and the sweep columns
/// (the unit is in each name): the rows are printed back as stated, and a round trip through SI
/// would move printed digits (kPa -> Pa -> kPa is inexact for ~14 % of two-decimal values, km/h
/// -> m/s -> km/h for ~8 %; issue 17). The physics reads SI through the accessors, the one place
/// where each conversion is written.
struct OperatingConditions {
  double load_N = 0;
  double horizontal_force_N = 0;
  double pressure_kPa = 230;
  double hold_s = 0;     ///< time the load has been held (0: measured right after loading)
  double speed_kmh = 0;  ///< rolling speed (0: standing)
  Branch branch = Branch::loading;
  Surface surface = Surface::rigid;
  double slip = 0;  ///< a traction row's slip (ISTVS, as `traction --slip`); 0: not slipping

  double pressure_Pa() const { return pressure_kPa * 1e3; }
  /// Seed 000 eq. (3) states its pressure law in bar.
  double pressure_bar() const { return pressure_kPa * 1e-2; }
  double speed_m_per_s() const { return speed_kmh / 3.6; }
};

/// A condition as a number (branch: 0 load / 1 unload; surface: 0 rigid / 1 soil).
double condition_value(const OperatingConditions& c, ConditionId id);
/// Sets one condition; `value` as condition_value() gives it (checked by the reader before).
void set_condition(OperatingConditions& c, ConditionId id, double value);

/// The words the catalogue writes for a branch or surface: "load", "unload", "rigid", "soil".
const char* branch_name(Branch b);
const char* surface_name(Surface s);
/// The branch or surface a catalogue word names ("load" or "loading", ...); nullopt otherwise.
std::optional<Branch> branch_named(const std::string& name);
std::optional<Surface> surface_named(const std::string& name);

}  // namespace modaltyre::contact

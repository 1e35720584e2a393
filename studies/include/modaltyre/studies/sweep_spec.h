#pragma once
// Parameter sweeps from a sweep file (this header: the file; sweep_plan.h, sweep_run.h and
// sweep_output.h the rest): the Cartesian product of condition and parameter values,
// each case a static footprint prediction (predictor.h: effects switched on in the config act),
// run in parallel (OpenMP) with results independent of the number of threads. A sweep with an
// effect on writes data the effect-free model cannot reproduce: the input of the discrepancy
// workflow (`discover`), which reads the CSV with read_measurements() (measurements.h).
//
// Sweep file (YAML; paths relative to the sweep file):
//   base: ../sf350.yaml                 # tyre config every case starts from (required)
//   set:                                # overrides applied to every case (optional)
//     tread.modulus_MPa: 8              #   dotted config keys (nested mappings also accepted)
//     effects.tread_relaxation.enabled: true   # switch an effect on for every case
//     horizontal_force_N: 0             #   or condition values
//   grid:                               # keys -> lists, Cartesian product in written order,
//     hold_s: [0, 30, 120]              #   the last key varies fastest (required, non-empty)
//     load_N: [2131, 3261, 5478]
//   output: table3_loads.csv            # CSV path (required unless the caller gives one)
//
// Condition keys (the catalogue of core/conditions.h: the columns of measurements.h, the
// fields of contact::OperatingConditions; ranges and words checked against it):
//   load_N              vertical load [N], in (0, 1e7]; required in grid or set
//   horizontal_force_N  horizontal force at the axle [N], in [-1e7, 1e7]
//   pressure_kPa        inflation pressure [kPa], in (0, 2000]
//   hold_s              time the load has been held [s], in [0, 1e7]
//   speed_kmh           rolling speed [km/h], in [0, 400]
//   branch              load | unload (text; also loading | unloading)
//   surface             rigid | soil (text)
// A condition not given takes the base config's value (TyreConfig::default_conditions: its
// horizontal_force_N and inflation pressure, no hold, standing, loading branch, rigid road).
// Conditions act only through the effects that use them. Every other key is a dotted config
// key, applied like `--set key=value` in the order base < set < (command-line set) < grid.
// Cases that differ only in their conditions share one immutable model (contact::TyreModel).
//
// CSV columns: every condition given in set: (then --set), in the order written, then every
// grid key in the order written; then sweep_observable_columns(). It is valid measured data for
// read_measurements(): conditions not written there take the reader's config defaults, so give
// every condition an effect acts through whenever it differs from the base config's default.
//
// Every input problem (unknown top-level key, missing base, empty or non-list grid value, a key
// that is not a valid config key, a value it rejects, a condition out of range or a branch or
// surface not in its list) is an InputError naming the sweep file, line and key, raised by
// parse_sweep_spec() or plan_sweep() before any model is built.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/core/errors.h"

namespace modaltyre::studies {

/// A scalar value as written in the sweep file (YAML text) and, if it is a number, its value.
struct SweepValue {
  std::string text;  ///< scalar text (for the CSV)
  std::string yaml;  ///< YAML text given to the config as an override
  std::optional<double> number;
  int line = 0;  ///< 1-based line in the sweep file (0: command line)
};

struct SweepAssignment {
  std::string key;  ///< dotted config key or condition name
  SweepValue value;
  InputLocation where;  ///< sweep file:line:"set.KEY", or "--set":0:KEY
};

struct SweepAxis {
  std::string key;  ///< dotted config key or condition name, as written
  std::vector<SweepValue> values;
  InputLocation where;     ///< sweep file:line:"grid.KEY"
  bool condition = false;  ///< an operating condition (is_sweep_condition), not a parameter
};

struct SweepSpec {
  std::string file;         ///< the sweep file as given
  std::string base_config;  ///< resolved path of the base tyre config
  InputLocation base_where;
  std::vector<SweepAssignment> set;  ///< sweep file's set:, then command-line overrides
  std::vector<SweepAxis> grid;
  std::string output;  ///< resolved CSV path ("" if the file names none)
  InputLocation output_where;
};

/// An operating condition of the catalogue (load_N, horizontal_force_N, pressure_kPa, hold_s,
/// speed_kmh, branch, surface), not a config key.
bool is_sweep_condition(const std::string& key);

/// Reads a sweep file; `overrides` ("dotted.key=value", e.g. from --set) apply to every case
/// after the file's set:. Throws InputError naming file, line and key.
SweepSpec read_sweep_spec(const std::string& path, const std::vector<std::string>& overrides = {});
/// Same from YAML text; `name` is the file name used in messages and to resolve paths.
SweepSpec parse_sweep_spec(const std::string& yaml, const std::string& name,
                           const std::vector<std::string>& overrides = {});

}  // namespace modaltyre::studies

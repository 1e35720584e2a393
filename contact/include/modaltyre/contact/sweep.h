#pragma once
// Parameter sweeps from a sweep file: the Cartesian product of condition and parameter values,
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
// Condition keys (the operating conditions of effects.h, the columns of measurements.h):
//   load_N              vertical load [N], > 0; required in grid or set
//   horizontal_force_N  horizontal force at the axle [N]
//   pressure_kPa        inflation pressure [kPa], in (0, 2000]
//   hold_s              time the load has been held [s], >= 0
//   speed_kmh           rolling speed [km/h], in [0, 400]
//   branch              load | unload (text)
//   surface             rigid | soil (text)
// A condition not given takes the base config's value (TyreConfig::default_conditions: its
// horizontal_force_N and inflation pressure, no hold, standing, loading branch, rigid road).
// Conditions act only through the effects that use them. Every other key is a dotted config
// key, applied like `--set key=value` in the order base < set < (command-line set) < grid.
// Cases that differ only in their conditions share one immutable model (FootprintPredictor).
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
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::contact {

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
  InputLocation where;  ///< sweep file:line:"grid.KEY"
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

/// The condition columns a sweep understands (load_N, horizontal_force_N, pressure_kPa, hold_s,
/// speed_kmh, branch, surface).
bool is_sweep_condition(const std::string& key);

/// Reads a sweep file; `overrides` ("dotted.key=value", e.g. from --set) apply to every case
/// after the file's set:. Throws InputError naming file, line and key.
SweepSpec read_sweep_spec(const std::string& path, const std::vector<std::string>& overrides = {});
/// Same from YAML text; `name` is the file name used in messages and to resolve paths.
SweepSpec parse_sweep_spec(const std::string& yaml, const std::string& name,
                           const std::vector<std::string>& overrides = {});

struct SweepCase {
  std::vector<std::size_t> value_index;  ///< per grid axis
  std::size_t model = 0;                 ///< index into SweepPlan::models
  OperatingConditions conditions;        ///< given ones, the rest from the model's config
  LoadCase load;                         ///< conditions.load_N and .horizontal_force_N
};

struct SweepPlan {
  SweepSpec spec;
  std::vector<std::string> columns;  ///< condition/parameter columns of the CSV
  /// Per column: grid axis index, or -1 for a condition that comes from set:.
  std::vector<int> column_axis;
  /// Per column: the CSV cell of a condition from set: (empty for grid columns).
  std::vector<std::string> set_cells;
  std::vector<TyreConfig> models;            ///< one per distinct parameter combination
  std::vector<std::vector<std::string>> model_overrides;  ///< "key=value" list per model
  std::vector<SweepCase> cases;              ///< grid order, last axis fastest

  /// Cells of the condition/parameter columns of case i (formatted as in the CSV).
  std::vector<std::string> cells(std::size_t i) const;
};

/// Expands the grid, builds and validates the config of every distinct parameter combination
/// (cheap: no model is built) and checks every condition value. InputError on any problem.
SweepPlan plan_sweep(const SweepSpec& spec);

struct SweepRow {
  bool ok = false;
  double sinking_mm = 0;
  double length_mm = 0;
  double width_mm = 0;                 ///< config width, or the crown-profile width (contact_width)
  double rolling_resistance_N = 0;     ///< 0 unless rolling_speed acts at a speed > 0
  double vertical_stiffness_N_mm = 0;  ///< applied load / sinking
  double peak_pressure_kPa = 0;
  int iterations = 0;
  /// ok: the solver's note ("converged in N active-set iterations"), never empty so that the
  /// CSV reads back as measured data; failed: the reason.
  std::string message;
};

struct SweepOptions {
  int threads = 0;  ///< OpenMP threads; 0 = omp_get_max_threads()
  /// false (default): every case starts cold, exactly like solve_footprint() with no effect on
  /// and FootprintPredictor::predict() with effects (same values and iterations, bit for bit).
  /// true: every case of a model starts from the contact set of one fixed reference case of
  /// that model (its median-load case, solved cold); deterministic for any thread count, fewer
  /// iterations (~10 % less time on the SF-350 load sweep), the same contact set, values equal
  /// up to the restricted solver's tolerance.
  bool warm_start = false;
  /// Called with the number of newly finished cases, from any worker thread (must be
  /// thread-safe and cheap). The library never prints.
  std::function<void(std::size_t)> progress;
  /// Plan indices to compute (a distributed sweep's share, see sweep_share()); null = all.
  /// Rows of the other cases stay default (ok = false, empty message) and are not counted
  /// as failed. Models with no case in the share are not built.
  const std::vector<std::size_t>* only_cases = nullptr;
};

struct SweepResult {
  std::vector<SweepRow> rows;  ///< one per case, in plan order
  std::size_t failed = 0;
  int threads = 1;  ///< threads actually used
};

/// Runs every case: FootprintPredictor::predict(case config, case conditions) on one predictor
/// per distinct model, or, for a model with no effect on, solve_footprint() on its operator (the
/// same footprint: without effects only load_N and horizontal_force_N act). A case that fails
/// (no convergence, a model that cannot be built for a computational reason) is a row with
/// ok = false and its reason; an InputError raised while building a model (e.g. unreadable
/// hammer data) is rethrown.
SweepResult run_sweep(const SweepPlan& plan, const SweepOptions& options = {});

/// The share of rank `rank` (0-based) out of `ranks` in a distributed sweep (MPI): the cases
/// ordered by model, then plan order, cut into `ranks` contiguous chunks whose sizes differ by
/// at most one, so that every rank computes about as many cases and builds only the few models
/// its chunk touches. Returned in plan order. The shares partition the plan, and a case's row
/// does not depend on which rank computes it, so gathering the rows gives the single-process
/// CSV byte for byte.
std::vector<std::size_t> sweep_share(const SweepPlan& plan, int rank, int ranks);

/// One CSV line of case i (with its trailing newline), as in sweep_csv().
std::string sweep_csv_row(const SweepPlan& plan, const SweepRow& row, std::size_t i);
/// The CSV header line (with its trailing newline), as in sweep_csv().
std::string sweep_csv_header(const SweepPlan& plan);

/// Observable columns, after the condition/parameter columns: sinking_mm, length_mm, width_mm,
/// rolling_resistance_N (predictor.h's observables, read back by read_measurements()), then
/// vertical_stiffness_N_mm, peak_pressure_kPa, iterations, status (ok | failed), message.
const std::vector<std::string>& sweep_observable_columns();

/// The CSV text: header, then one line per case; numbers with %.10g, text fields quoted when
/// they hold a comma or a quote. Byte-identical for identical rows.
std::string sweep_csv(const SweepPlan& plan, const SweepResult& result);

/// Formats a number as in the sweep CSV (%.10g).
std::string sweep_number(double v);
/// Quotes a CSV field if needed (comma, quote; newlines become spaces).
std::string csv_field(const std::string& text);

}  // namespace modaltyre::contact

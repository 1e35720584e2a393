#pragma once
// Small helpers shared by the subcommands: output routing and number formatting.
// The library never prints; only the app does.
#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/core/command_files.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/core/progress.h"
#include "modaltyre/report/check_finite.h"
#include "modaltyre/report/command_inputs.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::app {

/// Ends the program with `code` and no message: the message was printed by another process
/// (rank 0 of a distributed sweep reports for all ranks).
struct QuietExit {
  int code = 1;
};

/// Prints JSON to stdout (pretty, 2-space indent). Non-finite numbers are refused: they would
/// be written as null and silently corrupt a researcher's pipeline.
void print_json(const nlohmann::json& j);

/// Throws ComputationError if any number in the document is not finite.
using report::check_finite;

/// A CLI11 check of a number option: finite and in (lo, hi] (or [lo, hi] with `lo_inclusive`).
/// The message states the range, the unit and why the range is physical (`why`); CLI::Range
/// lets NaN through and says neither. Exit 2 through CLI11's ValidationError.
CLI::Validator physical_range(double lo, double hi, const std::string& unit, const std::string& why,
                              bool lo_inclusive = false);

/// Adds to every number option of `app` and its subcommands (CLI11 type FLOAT, INT, UINT) a check
/// that its text is a decimal number: CLI11 itself reads 0x1000, 0b101 and 0o17 as integers and
/// strtod hexadecimal floats (0x10p4), which no user means. Call once all commands are registered.
void require_decimal_numbers(CLI::App& app);

/// Adds to every output option (--output, --plot, --csv, --map-csv, --out-config, --write-config)
/// of `app` and its subcommands a check made before anything is computed: not empty, not a
/// directory, in a folder that exists (issue 38: an empty --output failed only after the
/// computation, without a path; --out-config nodir/x.yaml blamed modal.hammer_csv).
void check_output_paths(CLI::App& app);

/// Fixed-point formatting for tables ("0.0", never "-0.0").
std::string fixed(double v, int decimals);

/// A gnuplot colour for the k-th data set of a figure (" lc N", 0-based k; the default linetypes
/// without the pale yellow), so that a data set and its fit can share one.
std::string plot_colour(int k);

/// A relative value as a percentage with two decimals: 0.0123 -> "1.23 %".
std::string pct(double rel);

/// `v`, or +0 when it prints as zero with `decimals` decimals (for printf "%.*f" columns).
double unsigned_zero(double v, int decimals);

/// The propagation's options of a command (footprint, validate: docs/uncertainty.md):
/// --uncertainty-method and --samples, added by add_uncertainty_method_options().
struct UncertaintyMethodArgs {
  std::string method = "auto";
  int samples = 200;
  uncertainty::PropagationOptions options() const;
};
void add_uncertainty_method_options(CLI::App* cmd, UncertaintyMethodArgs& a);

/// The propagation's progress on stderr, one bar per phase (the differences, then the samples):
/// set options.progress = bar.callback() and call finish() after the propagation.
class UncertaintyProgress {
 public:
  std::function<void(int, int)> callback();
  void finish();

 private:
  std::unique_ptr<ProgressBar> bar_;
  int phase_total_ = 0, shown_done_ = 0;
};

/// Rounds to a number of significant digits for JSON (keeps output stable and readable).
using modaltyre::round_sig;

}  // namespace modaltyre::app

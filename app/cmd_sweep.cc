// modaltyre sweep SWEEP.yaml [--threads N] [--set key=value]... [--output FILE] [--json] [--warm-start]
//
// Exit codes: 0 when at least one case succeeded (failed cases are rows marked failed in the
// CSV); 1 when every case failed (the CSV is still written, so the reasons can be read); 2 for a
// bad sweep file, config or output path, before anything is computed.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/contact/sweep.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/progress.h"

namespace modaltyre::app {
namespace {

struct SweepArgs {
  std::string sweep;
  int threads = 0;
  std::vector<std::string> overrides;
  std::string output;
  bool json = false;
  bool warm_start = false;
};

// The output must be writable before hours of computing go into it.
void check_output(const std::string& path, const InputLocation& where) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target(path);
  fs::path folder = target.parent_path();
  if (folder.empty()) folder = ".";
  if (fs::is_directory(target, ec)) {
    throw InputError(where, "output '" + path + "' is a directory, not a CSV file");
  }
  if (!fs::is_directory(folder, ec)) {
    throw InputError(where, "output folder '" + folder.string() + "' does not exist");
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    throw InputError(where, "output folder '" + folder.string() + "' is not writable");
  }
}

}  // namespace

void register_sweep(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Parameter sweep from a sweep file: static footprints for the Cartesian product of the "
      "grid's condition (load_N, horizontal_force_N, pressure_kPa, hold_s, speed_kmh, branch, "
      "surface) and config-key values (effects switched on with effects.NAME.enabled act), in "
      "parallel, one CSV row per case (identical for any thread count; failed cases are rows "
      "marked failed; readable as measured data by discover and validate).");
  cmd->add_option("SWEEP", a->sweep,
                  "sweep file (YAML: base, set, grid, output), e.g. configs/sweeps/table3_loads.yaml")
      ->required();
  cmd->add_option("--threads", a->threads, "OpenMP threads (default: OMP_NUM_THREADS or all cores)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--set", a->overrides,
                  "override a config key for every case, e.g. --set tread.modulus_MPa=8");
  cmd->add_option("--output", a->output, "CSV path (default: the sweep file's output:)");
  cmd->add_flag("--json", a->json, "print the summary as JSON on stdout");
  cmd->add_flag("--warm-start", a->warm_start,
                "start each case's contact solve from a fixed reference solution of its model "
                "instead of cold (same contact sets, fewer iterations; still identical for any "
                "thread count)");
  cmd->callback([a] {
    auto spec = contact::read_sweep_spec(a->sweep, a->overrides);
    if (!a->output.empty()) {
      spec.output = a->output;
      spec.output_where = {"--output", 0, ""};
    }
    if (spec.output.empty()) {
      throw InputError({spec.file, 1, "output"}, "required: CSV path (or give --output)");
    }
    check_output(spec.output, spec.output_where);
    const contact::SweepPlan plan = contact::plan_sweep(spec);

    const auto start = std::chrono::steady_clock::now();
    ProgressBar bar(plan.cases.size(), "sweep");
    contact::SweepOptions opt;
    opt.threads = a->threads;
    opt.warm_start = a->warm_start;
    opt.progress = [&bar](std::size_t n) { bar.tick(n); };
    const contact::SweepResult res = contact::run_sweep(plan, opt);
    bar.finish();
    write_file_atomically(spec.output, contact::sweep_csv(plan, res));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::size_t n = plan.cases.size();
    const double rate = wall > 0 ? static_cast<double>(n) / wall : 0.0;
    char line[512];
    std::snprintf(line, sizeof line,
                  "sweep: %zu cases (%zu model%s), %zu failed, %.3f s wall, %.1f cases/s, %d "
                  "thread%s -> %s\n",
                  n, plan.models.size(), plan.models.size() == 1 ? "" : "s", res.failed, wall, rate, res.threads,
                  res.threads == 1 ? "" : "s", spec.output.c_str());
    std::cerr << line;
    if (a->json) {
      print_json({{"sweep", spec.file},
                  {"output", spec.output},
                  {"cases", n},
                  {"ok", n - res.failed},
                  {"failed", res.failed},
                  {"models", plan.models.size()},
                  {"threads", res.threads},
                  {"warm_start", a->warm_start},
                  {"wall_s", round_sig(wall, 6)},
                  {"cases_per_s", round_sig(rate, 6)}});
    }
    if (res.failed == n) {
      std::string first;
      for (const auto& r : res.rows) {
        if (!r.ok) {
          first = r.message;
          break;
        }
      }
      throw ComputationError("all " + std::to_string(n) + " cases failed (first: " + first +
                             "); the reasons are in " + spec.output);
    }
  });
}

}  // namespace modaltyre::app

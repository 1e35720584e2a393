// modaltyre sweep SWEEP.yaml [--threads N] [--set key=value]... [--output FILE] [--json]
//                 [--uncertainty]
//                            [--warm-start]
// mpirun -n K modaltyre sweep SWEEP.yaml ...   (built with -DMODALTYRE_WITH_MPI=ON)
//
// Exit codes: 0 when at least one case succeeded (failed cases are rows marked failed in the
// CSV); 1 when every case failed (the CSV is still written, so the reasons can be read); 2 for a
// bad sweep file, config or output path, before anything is computed.
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/progress.h"
#include "modaltyre/studies/sweep.h"
#include "modaltyre/uncertainty/propagation.h"
#include "mpi_session.h"

namespace modaltyre::app {
namespace {

struct SweepArgs {
  std::string sweep;
  int threads = 0;
  std::vector<std::string> overrides;
  std::string output;
  bool output_given = false;  ///< --output stated (an empty path is then refused)
  bool json = false;
  bool warm_start = false;
  bool uncertainty = false;
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

// The spec (with --output) and its plan: everything is checked before anything is computed.
struct Prepared {
  studies::SweepSpec spec;
  studies::SweepPlan plan;
};

Prepared prepare(const SweepArgs& a) {
  Prepared p;
  refuse_repeated_overrides(a.overrides);
  p.spec = studies::read_sweep_spec(a.sweep, a.overrides);
  if (a.output_given) {
    if (a.output.empty()) {
      throw InputError({"", 0, "--output"}, "the output path is empty; name a CSV file to write");
    }
    p.spec.output = a.output;
    p.spec.output_where = {"--output", 0, ""};
  }
  if (p.spec.output.empty()) {
    throw InputError({p.spec.file, 1, "output"}, "required: CSV path (or give --output)");
  }
  check_output(p.spec.output, p.spec.output_where);
  p.plan = studies::plan_sweep(p.spec);
  // The CSV must not replace the sweep file, its base config or the hammer data they read.
  CommandFiles files;
  files.input(p.spec.file, "SWEEP");
  for (const auto& model : p.plan.models) report::add_config_inputs(files, model, "base:");
  files.output(p.spec.output, a.output_given ? "--output" : p.spec.file + ": output");
  files.check();
  return p;
}

struct Summary {
  std::size_t failed = 0;
  std::size_t invalid = 0;  // ok cases outside the model's validity range
  int threads = 1;
  int ranks = 1;
  double wall_s = 0;
  std::string first_failure;  // a failed case's reason, when every case failed
};

void report(const SweepArgs& a, const Prepared& p, const Summary& s) {
  const std::size_t n = p.plan.cases.size();
  const double rate = s.wall_s > 0 ? static_cast<double>(n) / s.wall_s : 0.0;
  char line[640];
  std::snprintf(
      line, sizeof line,
      "sweep: %zu cases (%zu model%s), %zu failed, %.3f s wall, %.1f cases/s, %d "
      "thread%s%s -> %s\n",
      n, p.plan.models.size(), p.plan.models.size() == 1 ? "" : "s", s.failed, s.wall_s, rate,
      s.threads, s.threads == 1 ? "" : "s",
      s.ranks > 1 ? (" per rank x " + std::to_string(s.ranks) + " MPI ranks").c_str() : "",
      p.spec.output.c_str());
  std::cerr << line;
  if (s.invalid > 0) {
    std::cerr << "warning: " << s.invalid << " of " << n - s.failed
              << " cases are outside the model's validity range (column valid = false, the "
                 "reason in message): they are not predictions (README, \"Validity range\")\n";
  }
  if (a.json) {
    print_json({{"sweep", p.spec.file},
                {"output", p.spec.output},
                {"cases", n},
                {"ok", n - s.failed},
                {"failed", s.failed},
                {"outside_validity_range", s.invalid},
                {"models", p.plan.models.size()},
                {"threads", s.threads},
                {"mpi_ranks", s.ranks},
                {"warm_start", a.warm_start},
                {"wall_s", round_sig(s.wall_s, 6)},
                {"cases_per_s", round_sig(rate, 6)}});
  }
  if (s.failed == n) {
    throw ComputationError("all " + std::to_string(n) + " cases failed (first: " + s.first_failure +
                           "); the reasons are in " + p.spec.output);
  }
}

std::string first_failure(const studies::SweepResult& res, const std::vector<std::size_t>* share) {
  const std::size_t n = share ? share->size() : res.rows.size();
  for (std::size_t k = 0; k < n; ++k) {
    const auto& r = res.rows[share ? (*share)[k] : k];
    if (!r.ok) return r.message;
  }
  return "see the CSV";
}

// sweep --uncertainty (docs/uncertainty.md section 8): per model, its inputs' uncertainty
// propagated to its ok cases' conditions (footprint --uncertainty's method: linear, sampled
// where its curvature check fails). A model whose perturbed predictions fail keeps empty cells,
// with a warning.
std::vector<studies::SweepStd> sweep_bands(const studies::SweepPlan& plan,
                                           const studies::SweepResult& res, int threads) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<studies::SweepStd> out(plan.cases.size(), {nan, nan, nan});
  ProgressBar bar(plan.models.size(), "uncertainty");
  for (std::size_t m = 0; m < plan.models.size(); ++m) {
    std::vector<std::size_t> idx;
    std::vector<contact::OperatingConditions> cases;
    for (std::size_t i = 0; i < plan.cases.size(); ++i) {
      if (plan.cases[i].model != m || !res.rows[i].ok) continue;
      idx.push_back(i);
      cases.push_back(plan.cases[i].conditions);
    }
    bar.tick(1);
    if (cases.empty()) continue;
    uncertainty::PropagationOptions o;
    o.threads = threads;
    try {
      const auto& config = plan.models[m];
      const auto r = uncertainty::propagate(config, contact::config_modes(config), cases, o);
      for (std::size_t k = 0; k < idx.size(); ++k) {
        const auto& b = r.cases[k].bands;  // output_names(): sinking, length, width, ...
        out[idx[k]] = {b[0].std, b[1].std, b[2].std};
      }
    } catch (const ComputationError& e) {
      std::cerr << "warning: no band for model " << m + 1 << " of " << plan.models.size()
                << " (its std cells are empty): " << e.what() << "\n";
    }
  }
  bar.finish();
  return out;
}

// One process: OpenMP threads over every case.
void run_local(const SweepArgs& a) {
  const Prepared p = prepare(a);
  const auto start = std::chrono::steady_clock::now();
  ProgressBar bar(p.plan.cases.size(), "sweep");
  studies::SweepOptions opt;
  opt.threads = a.threads;
  opt.warm_start = a.warm_start;
  opt.progress = [&bar](std::size_t n) { bar.tick(n); };
  const studies::SweepResult res = studies::run_sweep(p.plan, opt);
  bar.finish();
  std::optional<std::vector<studies::SweepStd>> stds;
  if (a.uncertainty) stds = sweep_bands(p.plan, res, a.threads);
  write_file_atomically(p.spec.output, studies::sweep_csv(p.plan, res, stds ? &*stds : nullptr));
  Summary s;
  s.failed = res.failed;
  s.invalid = res.invalid;
  s.threads = res.threads;
  s.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (s.failed == p.plan.cases.size()) s.first_failure = first_failure(res, nullptr);
  report(a, p, s);
}

#ifdef MODALTYRE_WITH_MPI
// Cores of this node shared between its ranks, unless --threads or OMP_NUM_THREADS says.
int threads_per_rank(const SweepArgs& a, const mpi::Session& session) {
  if (a.threads > 0) return a.threads;
  if (std::getenv("OMP_NUM_THREADS")) return omp_get_max_threads();
  return std::max(1, omp_get_num_procs() / session.ranks_on_node());
}

// K ranks: each computes its share (studies::sweep_share) with OpenMP threads; rank 0 gathers
// the rows, puts them in plan order and writes the one CSV (byte-identical to run_local's).
// Every rank reads and plans the same sweep, so input errors are found by all; the ranks then
// agree on the outcome so that one message is printed and every rank exits with its code.
void run_distributed(const SweepArgs& a) {
  mpi::Session session;
  const auto start = std::chrono::steady_clock::now();
  std::exception_ptr error;
  int code = 0;
  Prepared p;
  std::vector<std::size_t> share;
  studies::SweepResult res;
  std::string rows;
  try {
    p = prepare(a);
    share = studies::sweep_share(p.plan, session.rank(), session.ranks());
    ProgressBar bar(share.size(), "sweep, rank 0 of " + std::to_string(session.ranks()),
                    session.rank() == 0 ? ProgressBar::Mode::automatic : ProgressBar::Mode::never);
    studies::SweepOptions opt;
    opt.threads = threads_per_rank(a, session);
    opt.warm_start = a.warm_start;
    opt.only_cases = share;
    opt.progress = [&bar](std::size_t n) { bar.tick(n); };
    res = studies::run_sweep(p.plan, opt);
    bar.finish();
    for (std::size_t i : share) rows += studies::sweep_csv_row(p.plan, res.rows[i], i);
  } catch (const InputError&) {
    error = std::current_exception();
    code = 2;
  } catch (...) {
    error = std::current_exception();
    code = 1;
  }
  const mpi::Session::Outcome outcome = session.agree(code);
  if (outcome.code != 0) {
    if (outcome.report && error) std::rethrow_exception(error);
    throw QuietExit{outcome.code};
  }

  const std::size_t failed = session.sum(res.failed);
  const std::size_t invalid = session.sum(res.invalid);
  std::vector<std::string> parts;
  try {
    parts = session.gather(rows);
  } catch (const ComputationError&) {
    if (session.rank() != 0) throw QuietExit{1};
    throw;
  }
  if (session.rank() != 0) {
    if (failed == p.plan.cases.size()) throw QuietExit{1};
    return;
  }
  // Each part holds its rank's share in plan order, one line per case (csv_field turns
  // newlines in messages into spaces).
  std::vector<std::string_view> line_of(p.plan.cases.size());
  for (int r = 0; r < session.ranks(); ++r) {
    const std::vector<std::size_t> its = studies::sweep_share(p.plan, r, session.ranks());
    std::string_view text = parts[static_cast<std::size_t>(r)];
    for (std::size_t i : its) {
      const std::size_t end = text.find('\n');
      MODALTYRE_CHECK(end != std::string_view::npos,
                      "rank " + std::to_string(r) + " sent too few rows");
      line_of[i] = text.substr(0, end + 1);
      text.remove_prefix(end + 1);
    }
    MODALTYRE_CHECK(text.empty(), "rank " + std::to_string(r) + " sent too many rows");
  }
  std::string csv = studies::sweep_csv_header(p.plan);
  for (const auto& line : line_of) csv += line;
  write_file_atomically(p.spec.output, csv);

  Summary s;
  s.failed = failed;
  s.invalid = invalid;
  s.threads = res.threads;
  s.ranks = session.ranks();
  s.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (failed == p.plan.cases.size()) s.first_failure = first_failure(res, &share);
  report(a, p, s);
}
#endif

}  // namespace

void register_sweep(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Parameter sweep from a sweep file: static footprints for the Cartesian product of the "
      "grid's condition (load_N, horizontal_force_N, pressure_kPa, hold_s, speed_kmh, branch, "
      "surface) and config-key values (effects switched on with effects.NAME.enabled act), in "
      "parallel, one CSV row per case (identical for any thread count; failed cases are rows "
      "marked failed; readable as measured data by discover and validate). Under mpirun (build "
      "option MODALTYRE_WITH_MPI) the cases are split over the ranks and rank 0 writes the same "
      "CSV.");
  cmd->add_option(
         "SWEEP", a->sweep,
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
  cmd->add_flag("--uncertainty", a->uncertainty,
                "add each case's standard deviation of sinking, length and width "
                "(sinking_std_mm, length_std_mm, width_std_mm: the inputs' uncertainty "
                "propagated per model, docs/uncertainty.md); one process only");
  cmd->callback([a, cmd] {
    a->output_given = cmd->count("--output") > 0;
    if (mpi::launcher_world_size() > 1 && a->uncertainty) {
      throw InputError({"--uncertainty", 0, ""},
                       "the bands are computed in one process: run the sweep without mpirun, "
                       "or without --uncertainty");
    }
    if (mpi::launcher_world_size() > 1) {
#ifdef MODALTYRE_WITH_MPI
      run_distributed(*a);
      return;
#else
      throw InputError({"mpirun", 0, ""},
                       "started as one of " + std::to_string(mpi::launcher_world_size()) +
                           " MPI ranks, but this modaltyre was built without MPI: every rank "
                           "would run the whole sweep. Rebuild with -DMODALTYRE_WITH_MPI=ON, or "
                           "run it without mpirun");
#endif
    }
    run_local(*a);
  });
}

}  // namespace modaltyre::app

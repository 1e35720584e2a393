#pragma once
// Running a sweep plan: one footprint prediction per case, in parallel (OpenMP) with results
// independent of the number of threads; sweep_share() cuts a plan for distributed (MPI) runs.
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "modaltyre/studies/sweep_plan.h"

namespace modaltyre::studies {

struct SweepRow {
  bool ok = false;
  double sinking_mm = 0;
  double length_mm = 0;
  double width_mm = 0;                 ///< config width, or the crown-profile width (contact_width)
  double rolling_resistance_N = 0;     ///< 0 unless rolling_speed acts at a speed > 0
  double vertical_stiffness_N_mm = 0;  ///< applied load / sinking
  double peak_pressure_kPa = 0;
  int iterations = 0;
  /// ok rows: inside the model's validity range (contact/validity.h); if not, the message says
  /// why instead of the solver's note.
  bool valid = true;
  /// ok: the solver's note ("converged in N active-set iterations"), never empty so that the
  /// CSV reads back as measured data; failed: the reason.
  std::string message;
};

struct SweepOptions {
  int threads = 0;  ///< OpenMP threads; 0 = omp_get_max_threads()
  /// false (default): every case starts cold, exactly like contact::predict() (same values and
  /// iterations, bit for bit).
  /// true: every case of a model starts from the contact set of one fixed reference case of
  /// that model (its median-load case, solved cold); deterministic for any thread count, fewer
  /// iterations (~10 % less time on the SF-350 load sweep), the same contact set, values equal
  /// up to the restricted solver's tolerance.
  bool warm_start = false;
  /// Called with the number of newly finished cases, from any worker thread (must be
  /// thread-safe and cheap). The library never prints.
  std::function<void(std::size_t)> progress;
  /// Plan indices to compute (a distributed sweep's share, see sweep_share(); viewed, not
  /// copied: it must outlive the run); absent = all, an empty share computes nothing.
  /// Rows of the other cases stay default (ok = false, empty message) and are not counted
  /// as failed. Models with no case in the share are not built.
  std::optional<std::span<const std::size_t>> only_cases;
};

struct SweepResult {
  std::vector<SweepRow> rows;  ///< one per case, in plan order
  std::size_t failed = 0;
  std::size_t invalid = 0;  ///< ok rows outside the validity range
  int threads = 1;          ///< threads actually used
};

/// Runs every case: contact::predict(model, case conditions) on one immutable model per distinct
/// parameter combination, shared by the threads (without effects only load_N and
/// horizontal_force_N act: the model's own operator, as `footprint`). A case that fails
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

}  // namespace modaltyre::studies

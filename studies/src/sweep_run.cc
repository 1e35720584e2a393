#include "modaltyre/studies/sweep_run.h"

#include <omp.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <new>
#include <string>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/contact/validity.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/thread_env.h"

namespace modaltyre::studies {

using namespace contact;

namespace {

SweepRow failed_row(const std::string& why) {
  SweepRow row;
  row.message = why;
  return row;
}

SweepRow row_from(const Prediction& p, const OperatingConditions& c) {
  SweepRow row;
  row.iterations = p.footprint.iterations;
  if (!p.ok()) {
    row.message = p.message.empty() ? "did not converge" : p.message;
    return row;
  }
  row.ok = true;
  // Never empty: read_measurements() refuses empty text cells, and an ok row must read back.
  row.message = p.footprint.message.empty() ? "converged" : p.footprint.message;
  row.sinking_mm = p.sinking_mm;
  row.length_mm = p.length_mm;
  row.width_mm = p.width_mm;
  row.rolling_resistance_N = p.rolling_resistance_N;
  // Secant stiffness of the applied load (dry friction moves the elastic tyre's load, not F).
  row.vertical_stiffness_N_mm = c.load_N / row.sinking_mm;
  double peak = 0;
  for (const auto& u : p.footprint.units) peak = std::max(peak, u.pressure_Pa);
  row.peak_pressure_kPa = peak * 1e-3;
  return row;
}

// One case: the model's own parameters at the case's conditions (contact::predict: the
// effect-free path, bit for bit the values of `modaltyre footprint`, when no effect is on).
Prediction solve_case(const TyreModel& model, const SweepCase& sc, const std::vector<char>& warm) {
  PredictOptions o;
  o.warm_active = warm;
  return predict(model, sc.conditions, o);
}

// One distinct model, built for one batch and released after it.
struct ModelSlot {
  std::unique_ptr<const TyreModel> model;  // read-only once built: shared by threads
  std::vector<char> warm;                  // reference contact set (empty: cold starts)
  std::string error;                       // reason the model could not be built
  std::exception_ptr input_error;
};

// Fixed warm-start reference of a model: its median-load case (ties: plan order), solved cold,
// so that the reference does not depend on which thread gets there first.
std::vector<char> reference_contact_set(const SweepPlan& plan,
                                        const std::vector<std::size_t>& cases,
                                        const TyreModel& model) {
  std::vector<std::size_t> by_load = cases;
  std::sort(by_load.begin(), by_load.end(), [&](std::size_t a, std::size_t b) {
    const double la = plan.cases[a].conditions.load_N, lb = plan.cases[b].conditions.load_N;
    return la != lb ? la < lb : a < b;
  });
  const Prediction ref = solve_case(model, plan.cases[by_load[by_load.size() / 2]], {});
  return ref.ok() ? ref.footprint.active : std::vector<char>{};
}

void build_slot(const SweepPlan& plan, std::size_t mi, const std::vector<std::size_t>& cases,
                bool warm_start, ModelSlot& slot) {
  try {
    slot.model = std::make_unique<const TyreModel>(build_tyre_model(plan.models[mi]));
    if (warm_start && !cases.empty()) slot.warm = reference_contact_set(plan, cases, *slot.model);
  } catch (const InputError&) {
    slot.input_error = std::current_exception();
  } catch (const std::bad_alloc&) {
    slot.model.reset();
    slot.error = "model not built: out of memory";
  } catch (const std::exception& e) {
    slot.model.reset();
    slot.error = std::string("model not built: ") + e.what();
  }
}

SweepRow run_case(const SweepCase& sc, const ModelSlot& slot) {
  if (!slot.model) return failed_row(slot.error);
  try {
    SweepRow row = row_from(solve_case(*slot.model, sc, slot.warm), sc.conditions);
    if (row.ok) {
      const Validity v = validity(slot.model->config, row.sinking_mm * 1e-3, row.length_mm * 1e-3);
      row.valid = v.valid;
      if (!v.valid) row.message = "outside the validity range: " + v.reason;
    }
    return row;
  } catch (const std::bad_alloc&) {
    return failed_row("out of memory");
  } catch (const std::exception& e) {
    return failed_row(e.what());
  }
}

}  // namespace

SweepResult run_sweep(const SweepPlan& plan, const SweepOptions& options) {
  SweepResult result;
  check_omp_num_threads();  // the default below reads it (a Python caller has no main())
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  result.threads = threads;
  result.rows.resize(plan.cases.size());

  // all_of: every case of a model (the warm-start reference is chosen among them, so that a
  // distributed share starts from the same reference as the whole sweep); run_of: the cases
  // to compute here.
  std::vector<std::vector<std::size_t>> all_of(plan.models.size()), run_of(plan.models.size());
  for (std::size_t i = 0; i < plan.cases.size(); ++i) all_of[plan.cases[i].model].push_back(i);
  if (options.only_cases) {
    for (const std::size_t i : *options.only_cases) {
      MODALTYRE_CHECK(i < plan.cases.size(), "sweep share names a case outside the plan");
      run_of[plan.cases[i].model].push_back(i);
    }
  } else {
    run_of = all_of;
  }
  std::vector<std::size_t> models;  // those with something to compute
  for (std::size_t mi = 0; mi < plan.models.size(); ++mi) {
    if (!run_of[mi].empty()) models.push_back(mi);
  }

  // Models are built and used in batches of `threads` (each holds dense m x m matrices: only a
  // few are alive at once, however many parameter combinations the grid has).
  const std::size_t batch = static_cast<std::size_t>(std::max(threads, 1));
  for (std::size_t first = 0; first < models.size(); first += batch) {
    const std::size_t count = std::min(batch, models.size() - first);
    std::vector<ModelSlot> slots(count);
    std::vector<std::size_t> slot_of(plan.models.size(), 0);

#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (std::size_t s = 0; s < count; ++s) {
      const std::size_t mi = models[first + s];
      build_slot(plan, mi, all_of[mi], options.warm_start, slots[s]);
    }
    for (const auto& slot : slots) {
      if (slot.input_error) std::rethrow_exception(slot.input_error);
    }

    std::vector<std::size_t> pending;
    for (std::size_t s = 0; s < count; ++s) {
      const std::size_t mi = models[first + s];
      slot_of[mi] = s;
      pending.insert(pending.end(), run_of[mi].begin(), run_of[mi].end());
    }
    const long n_pending = static_cast<long>(pending.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (long t = 0; t < n_pending; ++t) {
      const std::size_t i = pending[t];
      const SweepCase& sc = plan.cases[i];
      result.rows[i] = run_case(sc, slots[slot_of[sc.model]]);
      if (options.progress) options.progress(1);
    }
  }
  for (const auto& cases : run_of) {
    for (std::size_t i : cases) {
      result.failed += result.rows[i].ok ? 0 : 1;
      result.invalid += result.rows[i].ok && !result.rows[i].valid ? 1 : 0;
    }
  }
  return result;
}

std::vector<std::size_t> sweep_share(const SweepPlan& plan, int rank, int ranks) {
  MODALTYRE_CHECK(ranks >= 1 && rank >= 0 && rank < ranks, "sweep share: bad rank");
  std::vector<std::size_t> by_model(plan.cases.size());
  for (std::size_t i = 0; i < by_model.size(); ++i) by_model[i] = i;
  std::stable_sort(by_model.begin(), by_model.end(), [&](std::size_t a, std::size_t b) {
    return plan.cases[a].model < plan.cases[b].model;
  });
  // Chunk r is [r n / K, (r + 1) n / K): sizes differ by at most one.
  const std::size_t n = by_model.size(), k = static_cast<std::size_t>(ranks);
  const std::size_t r = static_cast<std::size_t>(rank);
  std::vector<std::size_t> share(by_model.begin() + static_cast<long>(r * n / k),
                                 by_model.begin() + static_cast<long>((r + 1) * n / k));
  std::sort(share.begin(), share.end());
  return share;
}

}  // namespace modaltyre::studies

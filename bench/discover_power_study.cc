// Discover's power and false-name rate measured by simulation (issue 23, docs/discover.md
// "Detection limits"): the check of the reported detection limits against discover itself.
//
//  1. Power curves: for an effect, the limit discover reports on a noise-only data set; then
//     data planted at 0.7, 1.0 and 1.3 x that limit (fresh noise each draw) run through the
//     whole workflow: the fraction of draws that name the effect first should cross 80 % near
//     1.0 x (the limit is the 80 % point by its definition).
//  2. False-name rate: noise-only data sets with six testable candidates and different noise
//     levels per observable (sinking 1 %, length 3 %); the fraction that names anything.
// On the 2D variant (configs/sf350_2d_table3.yaml), data generated on discover's 2 mm mesh;
// draws in parallel (each discover on one thread). A few minutes on 2 cores.
//   build/bench/discover_power_study [draws per point, default 20] [noise-only sets, default 50]
#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "modaltyre/discover/discover.h"

using namespace modaltyre;

namespace {

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";

struct Design {
  std::string effect;  // planted; its strength parameter scaled by `times` x its default
  std::vector<contact::OperatingConditions> rows;
  std::map<std::string, double> noise;  // relative, per observable
};

const contact::TyreConfig& config() {
  static const contact::TyreConfig c =
      contact::load_tyre_config(kConfig, {"contact.unit_length_mm=2"});
  return c;
}

// Rows predicted with the effect at `times` x its catalogue default strength (0: off), noise.
studies::MeasurementSet make(const Design& d, double times, unsigned seed) {
  static const contact::TyreModel model = contact::build_tyre_model(config());
  contact::TyreConfig truth = config();
  if (times > 0) {
    const contact::EffectInfo& info = *contact::find_effect(d.effect);
    truth.effects.enabled(info.id) = true;
    const auto& p = info.parameters.front();  // the strength (discover's detection_limit.cc)
    double& v = p.ref(truth.effects);
    v = info.id == contact::EffectId::soil_compliance ? p.default_value / times
                                                      : times * p.default_value;
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  studies::MeasurementSet set;
  set.path = "planted " + d.effect;
  for (const auto& kv : d.noise) set.observables.push_back(kv.first);
  set.conditions = {"load_N", "pressure_kPa", "hold_s", "branch"};
  for (const auto& c : d.rows) {
    studies::MeasuredRow r;
    r.row = r.line = static_cast<int>(set.rows.size()) + 1;
    r.conditions = c;
    const auto pr = contact::predict(model, contact::parameters_of(truth), c);
    for (const auto& kv : d.noise)
      r.observed[kv.first] = pr.observable(kv.first) * (1 + kv.second * unit(rng));
    set.rows.push_back(r);
  }
  return set;
}

std::vector<contact::OperatingConditions> grid(
    const std::vector<double>& loads, int levels,
    const std::function<void(contact::OperatingConditions&, int)>& vary, int copies = 1) {
  std::vector<contact::OperatingConditions> out;
  for (int c = 0; c < copies; ++c) {
    for (int l = 0; l < levels; ++l) {
      for (double f : loads) {
        auto o = config().default_conditions(f);
        vary(o, l);
        out.push_back(o);
      }
    }
  }
  return out;
}

discover::DiscoverReport run(const studies::MeasurementSet& data, bool limits) {
  discover::DiscoverOptions opt;
  opt.threads = 1;
  opt.detection_limits = limits;
  return discover::discover(contact::load_tyre_config(kConfig), data, opt);
}

// The limit discover reports for d.effect on a noise-only set of d's rows.
discover::DetectionLimit reported_limit(const Design& d, unsigned seed) {
  const auto report = run(make(d, 0, seed), true);
  for (const auto& c : report.rounds.back()) {
    if (c.name == d.effect) return c.limit;
  }
  return {};
}

void power_curve(const Design& d, int draws) {
  // The reported limit varies with the noise level each set's residuals give (its RMS from 16
  // rows scatters by ~18 %): the median over 9 noise-only sets.
  std::vector<discover::DetectionLimit> limits(9);
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < 9; ++k) limits[k] = reported_limit(d, 990 + k);
  std::printf("\n%s on %zu rows: limits on 9 noise-only sets (x default):", d.effect.c_str(),
              d.rows.size());
  for (const auto& l : limits) {
    if (!l.computed()) {
      std::printf(" none (%s)\n", l.reason.c_str());
      return;
    }
    std::printf(" %.3g", l.magnitude);
  }
  std::sort(limits.begin(), limits.end(),
            [](const auto& a, const auto& b) { return a.magnitude < b.magnitude; });
  const discover::DetectionLimit* lim = &limits[4];
  std::printf(
      "\n  median: %s = %.4g (%.3g x default), power at the default %.0f %%; observable "
      "RMS at the limit:",
      lim->parameter.c_str(), lim->value, lim->magnitude, 100 * lim->power_at_default);
  for (const auto& kv : lim->observable_rms_rel) {
    std::printf(" %s %.2f %%", kv.first.c_str(), 100 * kv.second);
  }
  std::printf("\n  x limit   named first (of %d)\n", draws);
  for (double f : {0.5, 0.7, 1.0, 1.3}) {
    int named = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : named)
    for (int k = 0; k < draws; ++k) {
      const auto r = run(make(d, f * lim->magnitude, 100 + k), false);
      named += !r.effects.empty() && r.effects.front().name == d.effect;
    }
    std::printf("  %7.1f   %d (%.0f %%)\n", f, named, 100.0 * named / draws);
  }
}

void false_names(int sets) {
  Design d;
  d.noise = {{"sinking_mm", 0.01}, {"length_mm", 0.03}};
  const double hold[] = {0, 120}, kpa[] = {200, 260};
  d.rows = grid({2500, 5500, 8500}, 4, [&](auto& c, int l) {
    c.hold_s = hold[l % 2];
    c.pressure_kPa = kpa[l / 2];
  });
  int named = 0, testable = 0;
  std::map<std::string, int> by;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : named)
  for (int k = 0; k < sets; ++k) {
    const auto r = run(make(d, 0, 5000 + k), false);
    if (!r.effects.empty()) {
      ++named;
#pragma omp critical
      ++by[r.effects.front().name];
    }
#pragma omp critical
    {
      testable = 0;
      for (const auto& c : r.rounds.front()) testable += c.testable;
    }
  }
  std::printf(
      "\nfalse names: %d of %d noise-only sets (%.1f %%), %zu rows, %d testable "
      "candidates, noise sinking 1 %% / length 3 %%\n",
      named, sets, 100.0 * named / sets, d.rows.size(), testable);
  for (const auto& kv : by) std::printf("  %s: %d\n", kv.first.c_str(), kv.second);
}

}  // namespace

int main(int argc, char** argv) {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  const int draws = argc > 1 ? std::atoi(argv[1]) : 20;
  const int sets = argc > 2 ? std::atoi(argv[2]) : 50;
  const double hold[] = {0, 20, 60, 300};
  Design creep{"tread_relaxation",
               grid(
                   {3000, 6500}, 4, [&](auto& c, int l) { c.hold_s = hold[l]; }, 2),
               {{"sinking_mm", 0.025}, {"length_mm", 0.025}}};
  Design friction{"dry_friction",
                  grid(
                      {3000, 6500}, 2,
                      [](auto& c, int l) {
                        c.branch = l ? contact::Branch::unloading : contact::Branch::loading;
                      },
                      4),
                  {{"sinking_mm", 0.025}, {"length_mm", 0.025}}};
  if (draws > 0) {
    power_curve(creep, draws);
    power_curve(friction, draws);
  }
  if (sets > 0) false_names(sets);
  return 0;
}

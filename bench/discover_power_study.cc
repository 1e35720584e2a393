// Discover's power and false-name rate measured by simulation (issue 23, docs/discover.md
// "Detection limits"): the check of the reported detection limits against discover itself.
//
//  1. Power curves: for an effect, the limit discover reports on a noise-only data set; then
//     data planted at 0.7, 1.0 and 1.3 x that limit (fresh noise each draw) run through the
//     whole workflow: the fraction of draws that name the effect first should cross 80 % near
//     1.0 x (the limit is the 80 % point by its definition).
//  2. False-name rate: noise-only data sets with six testable candidates and different noise
//     levels per observable (sinking 1 %, length 3 %); the fraction that names anything.
//  3. The naming rule's review: on 24-row sets (six testable candidates, 2.5 % noise), noise-only
//     and with tread_relaxation or dry_friction planted, the first round of discover scored
//     under the current rule (a 25 % cross-validated gain at any number of rows) and under rules
//     whose gain threshold falls with the rows (NamingRule::cv_gain_z = 2, 1.5, 1): the fraction
//     of sets each names anything (noise-only) or the planted effect first. One discover run per
//     set serves every rule: the first round's candidates do not depend on the rule.
// On the 2D variant (configs/sf350_2d_table3.yaml), data generated on discover's 2 mm mesh;
// draws in parallel (each discover on one thread). A few minutes on 2 cores.
//   build/bench/discover_power_study [draws per point, default 20] [noise-only sets, default 50]
//                                    [rule-review sets per case, default 0] [1: simulated review]
//                                    [copies of the 24-row review design, 1-16, default 1;
//                                     negative: noise-only review sets only]
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

const contact::TyreModel* model_for_review() {
  static const contact::TyreModel model = contact::build_tyre_model(config());
  return &model;
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

// The effect a rule names first in discover's first round (empty: none).
std::string first_named(const discover::DiscoverReport& r, const discover::NamingRule& rule,
                        const std::map<std::string, int>& entries) {
  const discover::CandidateScore* best = nullptr;
  for (const auto& c : r.rounds.front()) {
    if (!c.testable || c.failures > 0) continue;
    std::vector<double> before, after;
    std::vector<int> n;
    for (const auto& kv : c.cv_before) {
      before.push_back(kv.second);
      after.push_back(c.cv_after.at(kv.first));
      n.push_back(entries.at(kv.first));
    }
    if (!rule.names(c.delta_bic, before, after, n, c.cv_rms_before, c.cv_rms_after)) continue;
    if (!best || c.delta_bic > best->delta_bic) best = &c;
  }
  return best ? best->name : "";
}

const std::vector<double> kRuleZ = {0, 2, 1.5, 1};  // NamingRule::cv_gain_z; 0: the current rule

// The 24-row review design (3 loads x 2 pressures x 2 hold times x 2 branches), `copies` times.
std::vector<contact::OperatingConditions> review_rows(int copies = 1) {
  const double hold[] = {0, 120}, kpa[] = {200, 260};
  return grid(
      {2500, 5500, 8500}, 8,
      [&](auto& c, int l) {
        c.hold_s = hold[l % 2];
        c.pressure_kPa = kpa[(l / 2) % 2];
        c.branch = l / 4 ? contact::Branch::unloading : contact::Branch::loading;
      },
      copies);
}

// The same rules in the detection-limit simulation (the model linearised at the fit of one
// noise-only set): the probability of naming tread_relaxation and dry_friction at their
// catalogue defaults with the rows repeated 1, 4 and 16 times (24, 96, 384 rows).
void rule_review_simulated() {
  const Design d{"", review_rows(), {{"sinking_mm", 0.025}, {"length_mm", 0.025}}};
  const auto data = make(d, 0, 7000);
  const discover::Evaluator ev(*model_for_review(), data);
  std::vector<int> all(data.rows.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const auto base = discover::make_variant(config(), {});
  const auto fit = discover::fit_variant(ev, config(), base, all);
  std::printf("\nrule review, simulated (24-row design repeated r times): power at the default\n");
  for (double z : kRuleZ) {
    const discover::LimitFinder f(ev, fit.config, base, fit, {10, 0.25, 0.1, z});
    std::printf("  z=%g:", z);
    for (auto id : {contact::EffectId::tread_relaxation, contact::EffectId::dry_friction}) {
      for (double m : {0.5, 1.0}) {
        std::printf("  %s %.1fx r=1/4/16: %.0f/%.0f/%.0f %%", contact::effect_info(id).name.c_str(),
                    m, 100 * f.power(id, m, 1), 100 * f.power(id, m, 4), 100 * f.power(id, m, 16));
      }
    }
    std::printf("\n");
  }
}

// `copies` repeats the 24-row design (fresh noise per row); `noise_only` skips the planted cases.
void rule_review(int sets, int copies, bool noise_only) {
  const std::vector<double>& zs = kRuleZ;
  const auto rows = review_rows(copies);
  const std::map<std::string, double> noise = {{"sinking_mm", 0.025}, {"length_mm", 0.025}};
  struct Case {
    std::string effect;
    double times;
  };
  // Planted near the current rule's limits on these rows (rule_review_simulated: the current
  // rule names tread_relaxation at 0.5 x with 88 %, dry_friction at 0.5 x with 14 %).
  std::vector<Case> cases = {{"", 0}, {"tread_relaxation", 0.5}, {"dry_friction", 0.6}};
  if (noise_only) cases.resize(1);
  const int entries_per_observable = static_cast<int>(rows.size());
  std::printf(
      "\nrule review: %zu rows (3 loads x 2 pressures x 2 hold times x 2 branches, %d x), "
      "2.5 %% noise, %d sets per case\n",
      rows.size(), copies, sets);
  std::printf("  gain needed on %d entries: z=0 (current) %.3f", entries_per_observable,
              discover::NamingRule{}.gain_needed(entries_per_observable));
  for (double z : zs) {
    if (z > 0)
      std::printf(", z=%g %.3f", z,
                  discover::NamingRule{10, 0.25, 0.1, z}.gain_needed(entries_per_observable));
  }
  std::printf("\n");
  for (const auto& cs : cases) {
    Design d{cs.effect, rows, noise};
    std::vector<std::vector<std::string>> firsts(sets);
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < sets; ++k) {
      auto data = make(d, cs.times, 7000 + k);
      discover::DiscoverOptions opt;
      opt.threads = 1;
      opt.detection_limits = false;
      opt.max_effects = 1;
      const auto r = discover::discover(contact::load_tyre_config(kConfig), data, opt);
      std::map<std::string, int> entries = {{"sinking_mm", 0}, {"length_mm", 0}};
      for (const auto& row : data.rows) {
        for (const auto& kv : row.observed) ++entries[kv.first];
      }
      for (double z : zs) firsts[k].push_back(first_named(r, {10, 0.25, 0.1, z}, entries));
    }
    std::printf("  %s%s:", cs.effect.empty() ? "noise only" : cs.effect.c_str(),
                cs.effect.empty() ? "" : (" at " + std::to_string(cs.times) + " x").c_str());
    for (std::size_t z = 0; z < zs.size(); ++z) {
      int hits = 0;
      for (const auto& f : firsts) hits += cs.effect.empty() ? !f[z].empty() : f[z] == cs.effect;
      std::printf("  z=%g: %d of %d (%.0f %%)", zs[z], hits, sets, 100.0 * hits / sets);
    }
    std::printf("\n");
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  const int draws = argc > 1 ? std::atoi(argv[1]) : 20;
  const int sets = argc > 2 ? std::atoi(argv[2]) : 50;
  const int review = argc > 3 ? std::atoi(argv[3]) : 0;
  const bool simulated = argc > 4 && std::atoi(argv[4]) > 0;
  // Bounded: 1..16 copies of the 24-row review design; a negative value: noise-only sets only.
  const int copies_arg = argc > 5 ? std::atoi(argv[5]) : 1;
  const int copies = std::clamp(std::abs(copies_arg), 1, 16);
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
  if (simulated) rule_review_simulated();
  if (review > 0) rule_review(review, copies, copies_arg < 0);
  return 0;
}

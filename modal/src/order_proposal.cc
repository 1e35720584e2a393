#include "modaltyre/modal/order_proposal.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "modaltyre/core/errors.h"
#include "modaltyre/modal/ring_model.h"

namespace modaltyre::modal {
namespace {

/// The scatter of a measured frequency about its ring (relative): a doublet's members differ by
/// up to 1.4 % in seed 001 Table 2, and an identification moves a frequency by a few tenths of
/// a percent (docs/ema.md); residuals below it are not evidence for one assignment over another.
constexpr double kFrequencyScatter = 0.005;
/// Score added for an implausible mass from the tension: an assignment whose belt would weigh
/// less than a bicycle tyre's or more than a truck's is ruled out by physics, not by fit.
constexpr double kImplausibleMassPenalty = 20;
/// A list without the family's lowest orders counts as this many choices per order left out:
/// orders 2 and 3 are the easiest to excite and resolve in a hammer test, so a list that lacks
/// them while it has higher ones is the exception (a prior, stated in docs/ring_model.md).
constexpr int kLowOrderMissingWeight = 3;
/// The ring's coefficients (ring_model.h).
constexpr int kCoefficientsFitted = 4;
/// The score of a family with no residual degree of freedom (it fits anything).
constexpr double kUntestedFamilyPenalty = 100;
/// Lists longer than this are refused (the enumeration grows with the square of the length).
constexpr std::size_t kMaxFrequencies = 40;
/// The breathing and order-1 modes are looked for among the lowest frequencies.
constexpr std::size_t kLowWindow = 4;

struct Scored {
  std::vector<int> sorted_orders;  // per sorted frequency
  double score = 0, rms = 0, mu = 0;
  int skips = 0;
};

// Scores one assignment (orders per sorted frequency; -1 = order 1 unscored).
Scored score(const std::vector<double>& f, const std::vector<int>& orders, int extra_params,
             const OrderProposalOptions& o) {
  const bool mass_check = o.pressure_Pa > 0 && o.belt_width_m > 0 && o.radius_m > 0;
  const bool move_free = !o.order1_in_fit && o.wheel_mass_kg > 0 && mass_check;
  std::vector<int> ks;
  std::vector<double> hz;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const int k = orders[i];
    if (k >= 2 || (k == 1 && o.order1_in_fit)) ks.push_back(k), hz.push_back(f[i]);
  }
  Scored s;
  s.sorted_orders = orders;
  RingFit fit = fit_ring(ks, hz);
  if (move_free && fit.valid && fit.coefficients.tension > 0) {
    // The free order 1 moved to the held wheel with the belt mass this family's tension implies.
    const double mu =
        mass_per_length_from_tension(fit.coefficients, o.pressure_Pa, o.belt_width_m, o.radius_m);
    const double belt = 2 * M_PI * o.radius_m * mu;
    bool added = false;
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (orders[i] != 1) continue;
      ks.push_back(1);
      hz.push_back(rim_held_frequency_hz(f[i], belt, o.wheel_mass_kg));
      added = true;
    }
    if (added) fit = fit_ring(ks, hz);
  }
  if (!fit.valid) {
    s.score = 1e300;
    return s;
  }
  const double m = static_cast<double>(ks.size());
  const double rss = fit.rms_rel_error * fit.rms_rel_error * m;
  s.rms = fit.rms_rel_error;
  // A frequency taken out of the family unscored (breathing, a free order 1 that cannot be
  // moved) is a discrete choice.
  int unscored = 0;
  for (int k : orders) unscored += k == 0 || (k == 1 && !o.order1_in_fit && !move_free);
  // One model for every assignment (the four coefficients, zero allowed), so the score
  // compares the evidence: chi^2 with the scatter known, plus 2 per discrete choice (Akaike).
  // A family with no residual degree of freedom fits anything and is no evidence.
  const double dof = m - kCoefficientsFitted;
  s.score = rss / (kFrequencyScatter * kFrequencyScatter) + 2.0 * (extra_params + unscored) +
            (dof > 0 ? 0.0 : kUntestedFamilyPenalty);
  if (mass_check) {
    if (fit.coefficients.tension > 0) {
      s.mu =
          mass_per_length_from_tension(fit.coefficients, o.pressure_Pa, o.belt_width_m, o.radius_m);
    }
    if (!(s.mu >= o.min_mass_kg_m && s.mu <= o.max_mass_kg_m)) s.score += kImplausibleMassPenalty;
  }
  return s;
}

}  // namespace

std::vector<OrderProposal> propose_orders(const std::vector<double>& freq_hz,
                                          const OrderProposalOptions& o) {
  if (freq_hz.size() < 3) return {};
  if (freq_hz.size() > kMaxFrequencies) {
    throw InputError("at most " + std::to_string(kMaxFrequencies) +
                     " frequencies can be given orders automatically; state --orders");
  }
  for (double f : freq_hz) {
    if (!(f > 0) || !std::isfinite(f)) throw InputError("frequencies must be positive");
  }
  std::vector<std::size_t> idx(freq_hz.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return freq_hz[a] < freq_hz[b]; });
  std::vector<double> f;
  for (auto i : idx) f.push_back(freq_hz[i]);
  const std::size_t n = f.size();

  std::vector<Scored> all;
  // Low modes set apart: none, one (order 0 or 1) or two (0 and 1, or a pair of order 1).
  struct Apart {
    std::vector<std::size_t> at;
    std::vector<int> order;
  };
  std::vector<Apart> aparts = {{}};
  const std::size_t low = std::min(n, kLowWindow);
  for (std::size_t i = 0; i < low; ++i) {
    aparts.push_back({{i}, {0}});
    aparts.push_back({{i}, {1}});
    for (std::size_t j = i + 1; j < low; ++j) {
      aparts.push_back({{i, j}, {0, 1}});
      aparts.push_back({{i, j}, {1, 0}});
      aparts.push_back({{i, j}, {1, 1}});
    }
  }
  // A doublet (two frequencies within the tolerance) is one order's pair: set apart together,
  // with one order, or not at all.
  auto splits_a_doublet = [&](const Apart& a) {
    auto order_of = [&](std::size_t i) {
      for (std::size_t k = 0; k < a.at.size(); ++k)
        if (a.at[k] == i) return a.order[k];
      return -2;
    };
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if (f[i + 1] / f[i] - 1 >= o.doublet_tolerance) continue;
      if (order_of(i) != order_of(i + 1) || order_of(i) == 0) return true;
    }
    return false;
  };
  for (const Apart& a : aparts) {
    if (splits_a_doublet(a)) continue;
    std::vector<int> orders(n, -2);
    bool has_order1 = false;
    for (std::size_t k = 0; k < a.at.size(); ++k) {
      orders[a.at[k]] = a.order[k];
      has_order1 = has_order1 || a.order[k] == 1;
    }
    std::vector<std::size_t> family;
    for (std::size_t i = 0; i < n; ++i)
      if (orders[i] == -2) family.push_back(i);
    if (family.size() < 2) continue;
    // Steps between family neighbours: 0 for a doublet (forced within the tolerance), else 1.
    std::vector<int> base_step(family.size(), 1);
    for (std::size_t k = 1; k < family.size(); ++k) {
      const bool close = f[family[k]] / f[family[k - 1]] - 1 < o.doublet_tolerance;
      const bool prev_doublet = k >= 2 && base_step[k - 1] == 0;
      base_step[k] = close && !prev_doublet ? 0 : 1;
    }
    // Skips: up to max_skipped extra orders placed before any family member after the first.
    std::vector<std::vector<int>> skip_sets = {{}};
    for (std::size_t k = 1; k < family.size(); ++k) {
      if (base_step[k] == 0) continue;
      if (o.max_skipped >= 1) skip_sets.push_back({int(k)});
      for (std::size_t l = k; l < family.size() && o.max_skipped >= 2; ++l) {
        if (base_step[l] == 0) continue;
        skip_sets.push_back({int(k), int(l)});
      }
    }
    for (int start = has_order1 ? 2 : 1; start <= 3; ++start) {
      for (const auto& skips : skip_sets) {
        std::vector<int> ord = orders;
        int k_now = start;
        for (std::size_t k = 0; k < family.size(); ++k) {
          if (k > 0) k_now += base_step[k];
          for (int s : skips)
            if (s == int(k)) ++k_now;
          ord[family[k]] = k_now;
        }
        // Choices: the skipped orders, and the family's orders below its start down to 2
        // (a list that leaves out the lowest family orders is as unusual as one with a gap).
        // A free test's list without order 1 misses its lowest in-plane mode as well: the belt
        // translating against the free wheel sits below order 2 (seed 001's 113 Hz under 134 Hz)
        // and has full radial amplitude at the driving point, so "the first N frequencies" of a
        // free tyre start with it: leaving it out is one more choice (a prior, docs/ring_model.md
        // section 6; one choice, not the lowest family orders' three: a free order 1 can sit
        // close to order 2 and be taken for it).
        const bool free_test = !o.order1_in_fit && o.wheel_mass_kg > 0;
        const int low_missing = std::max(0, start - 2);
        const int choices = static_cast<int>(skips.size()) + kLowOrderMissingWeight * low_missing +
                            (free_test && !has_order1 ? 1 : 0);
        Scored sc = score(f, ord, choices, o);
        sc.skips = static_cast<int>(skips.size());
        if (sc.score < 1e299) all.push_back(std::move(sc));
      }
    }
  }
  std::sort(all.begin(), all.end(),
            [](const Scored& a, const Scored& b) { return a.score < b.score; });
  std::vector<OrderProposal> out;
  for (const Scored& s : all) {
    OrderProposal p;
    p.orders.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) p.orders[idx[k]] = s.sorted_orders[k];
    if (std::any_of(out.begin(), out.end(),
                    [&](const OrderProposal& q) { return q.orders == p.orders; }))
      continue;
    p.score = s.score;
    p.rms_rel_error = s.rms;
    p.mass_per_length_kg_m = s.mu;
    // Orders 0 and 1 are other physics; the family's missing members are counted from 2.
    const int hi = *std::max_element(s.sorted_orders.begin(), s.sorted_orders.end());
    for (int k = 2; k <= hi; ++k)
      if (std::find(s.sorted_orders.begin(), s.sorted_orders.end(), k) == s.sorted_orders.end())
        p.missing.push_back(k);
    if (s.skips > 0) p.note = std::to_string(s.skips) + " order(s) missing from the list";
    out.push_back(std::move(p));
    if (static_cast<int>(out.size()) >= o.max_alternatives) break;
  }
  return out;
}

}  // namespace modaltyre::modal

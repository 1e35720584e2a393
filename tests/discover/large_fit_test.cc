// Discover on many rows (issue 16 item 3): the evenly spread search subset, the approximate fit
// and one-step cross-validation against the exact computation on the same rows, and the
// workflow on a data set above the exact limit (named effect, cost per row, progress phases).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>
#include <set>

#include "modaltyre/core/errors.h"
#include "modaltyre/discover/discover.h"
#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

// Rows of a test matrix in memory: loads x pressures x holds, load fastest.
studies::MeasurementSet matrix(int loads, int pressures, int holds) {
  studies::MeasurementSet set;
  set.observables = {"sinking_mm", "length_mm"};
  for (int h = 0; h < holds; ++h) {
    for (int p = 0; p < pressures; ++p) {
      for (int l = 0; l < loads; ++l) {
        studies::MeasuredRow r;
        r.row = static_cast<int>(set.rows.size()) + 1;
        r.conditions.load_N = 2000 + 300 * l;
        r.conditions.pressure_kPa = 180 + 20 * p;
        r.conditions.hold_s = h * h * 5.0;  // unevenly spaced levels
        r.observed = {{"sinking_mm", 20}, {"length_mm", 100}};
        set.rows.push_back(r);
      }
    }
  }
  return set;
}

std::vector<int> all_rows(const studies::MeasurementSet& s) {
  std::vector<int> rows(s.rows.size());
  std::iota(rows.begin(), rows.end(), 0);
  return rows;
}

TEST(SpreadSubset, CoversEveryLevelOfATestMatrixAndIsDeterministic) {
  const auto set = matrix(20, 5, 10);
  const auto subset = spread_subset(set, all_rows(set), 40);
  ASSERT_EQ(subset.size(), 40u);
  EXPECT_TRUE(std::is_sorted(subset.begin(), subset.end()));
  EXPECT_EQ(std::set<int>(subset.begin(), subset.end()).size(), 40u);
  std::set<double> loads, pressures, holds;
  for (int r : subset) {
    loads.insert(set.rows[r].conditions.load_N);
    pressures.insert(set.rows[r].conditions.pressure_kPa);
    holds.insert(set.rows[r].conditions.hold_s);
  }
  EXPECT_EQ(pressures.size(), 5u);
  EXPECT_EQ(holds.size(), 10u);  // rank scaling: the close short holds count as much as long ones
  EXPECT_EQ(*loads.begin(), 2000);
  EXPECT_EQ(*loads.rbegin(), 2000 + 300 * 19);
  EXPECT_GE(loads.size(), 10u);
  EXPECT_EQ(spread_subset(set, all_rows(set), 40), subset);
}

TEST(SpreadSubset, RepeatedConditionsStillGiveDistinctRowsAndSmallSetsStayWhole) {
  auto set = matrix(3, 1, 1);
  const auto three = set.rows;
  for (int i = 0; i < 30; ++i) set.rows.push_back(three[i % 3]);  // repeats of 3 conditions
  const auto subset = spread_subset(set, all_rows(set), 10);
  EXPECT_EQ(std::set<int>(subset.begin(), subset.end()).size(), 10u);
  std::set<double> loads;
  for (int r : subset) loads.insert(set.rows[r].conditions.load_N);
  EXPECT_EQ(loads.size(), 3u);
  EXPECT_EQ(spread_subset(set, {1, 4, 7}, 10), (std::vector<int>{1, 4, 7}));
}

// 4 holds x 18 loads of a creeping tread (72 rows): the approximations against the exact
// search, fit and refits on the same rows, for the variant with the planted effect and for the
// baseline that misses it.
class ManyRows : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    Planted p;
    p.truth = creeping_tread().truth;  // the same creeping tread, on 18 loads
    std::vector<double> loads;
    for (int i = 0; i < 18; ++i) loads.push_back(1800 + 400 * i);
    const double hold[] = {0, 20, 60, 180};
    p.rows = grid(
        loads, [&](auto& c, int l) { c.hold_s = hold[l]; }, 4);
    p.seed = 5;
    data_ = new studies::MeasurementSet(make_data(p, "many_rows"));
    config_ = new TyreConfig(contact::load_tyre_config(kConfig, {"contact.unit_length_mm=2"}));
    model_ = new contact::TyreModel(contact::build_tyre_model(*config_));
  }
  static void TearDownTestSuite() {
    delete model_;
    delete config_;
    delete data_;
  }

  // Runs both computations of one variant and compares them.
  static void compare(const Variant& v) {
    Evaluator ev(*model_, *data_);
    const auto rows = all_rows(*data_);
    const long before = ev.predictions();
    const FitResult exact = fit_variant(ev, *config_, v, rows, std::nullopt, true);
    const CrossValidation exact_cv = cross_validate(ev, *config_, v, exact);
    const long exact_cost = ev.predictions() - before;

    FitOptions opt;
    opt.subset_rows = 24;
    Eigen::MatrixXd J;
    const FitResult approx = fit_variant_many_rows(ev, *config_, v, rows, opt, &J);
    const CrossValidation approx_cv = cross_validate_one_step(ev, *config_, v, approx, J);
    const long approx_cost = ev.predictions() - before - exact_cost;

    ASSERT_EQ(approx.values.size(), exact.values.size());
    for (std::size_t i = 0; i < exact.values.size(); ++i) {
      const std::string& key = v.parameters[i].key;
      // The same optimum to a small fraction of its uncertainty, and the same uncertainty.
      EXPECT_NEAR(approx.values[i], exact.values[i], 0.1 * exact.standard_errors[i]) << key;
      EXPECT_NEAR(approx.standard_errors[i], exact.standard_errors[i],
                  0.02 * exact.standard_errors[i])
          << key;
    }
    EXPECT_NEAR(approx.bic, exact.bic, 0.5);
    EXPECT_TRUE(approx_cv.one_step);
    EXPECT_EQ(approx_cv.folds, exact_cv.folds);
    for (const auto& [obs, rms] : exact_cv.rms) {
      EXPECT_NEAR(approx_cv.rms.at(obs), rms, 0.02 * rms) << obs;
    }
    EXPECT_LT(approx_cost, exact_cost / 2)
        << "approximate " << approx_cost << ", exact " << exact_cost << " footprints";
  }

  static studies::MeasurementSet* data_;
  static TyreConfig* config_;
  static contact::TyreModel* model_;
};

studies::MeasurementSet* ManyRows::data_ = nullptr;
TyreConfig* ManyRows::config_ = nullptr;
contact::TyreModel* ManyRows::model_ = nullptr;

TEST_F(ManyRows, ApproximationsMatchTheExactFitAndRefitsWithThePlantedEffect) {
  compare(make_variant(*config_, {contact::EffectId::tread_relaxation}));
}

TEST_F(ManyRows, ApproximationsMatchTheExactFitAndRefitsOfTheBaselineThatMissesIt) {
  compare(make_variant(*config_, {}));
}

// 120 rows (above the exact limit of 64): the workflow names the planted effect, halves the
// cross-validated gap and recovers the planted values, with a cost per row far below the exact
// procedure's (~1800 footprints per row for six candidates); progress comes in phases.
TEST(DiscoverManyRows, NamesThePlantedEffectAtAFractionOfTheCost) {
  Planted p;
  p.truth = [](auto& e) {
    e.tread_relaxation.enabled = true;
    e.tread_relaxation.creep_ratio = 0.8;
    e.tread_relaxation.time_constant_s = 40;
  };
  const double hold[] = {0, 10, 30, 60, 120, 240};
  const double kpa[] = {190, 270};
  std::vector<double> loads;
  for (int i = 0; i < 10; ++i) loads.push_back(2000 + 650 * i);
  p.rows = grid(
      loads, [&](auto& c, int l) { c.hold_s = hold[l / 2], c.pressure_kPa = kpa[l % 2]; }, 12);
  p.seed = 9;
  const auto data = make_data(p, "discover_many_rows");
  ASSERT_EQ(data.rows.size(), 120u);

  std::mutex m;
  std::vector<std::tuple<std::string, int, int>> events;
  DiscoverOptions opt;
  opt.progress = [&](const std::string& phase, int done, int total) {
    std::lock_guard<std::mutex> lock(m);
    events.emplace_back(phase, done, total);
  };
  const DiscoverReport r = discover(contact::load_tyre_config(kConfig), data, opt);
  EXPECT_NE(r.method.find("approximate on 120 rows"), std::string::npos) << r.method;
  ASSERT_FALSE(r.effects.empty()) << r.conclusion;
  const NamedEffect& e = r.effects.front();
  EXPECT_EQ(e.name, "tread_relaxation") << r.conclusion;
  EXPECT_LE(e.cv_rms_after, 0.5 * e.cv_rms_before) << r.conclusion;
  EXPECT_NEAR(e.parameters.at("effects.tread_relaxation.creep_ratio"), 0.8,
              3 * e.standard_errors.at("effects.tread_relaxation.creep_ratio"));
  EXPECT_NEAR(e.parameters.at("effects.tread_relaxation.time_constant_s"), 40,
              3 * e.standard_errors.at("effects.tread_relaxation.time_constant_s"));
  EXPECT_LT(r.footprints, 500L * 120) << r.footprints << " footprints";

  // Phases: "baseline" (fit, cross-validation), then each round with two ticks per testable
  // candidate, then "detection limits" (one tick per candidate left unnamed); each opens with
  // done = 0 and ends at its total.
  ASSERT_GE(events.size(), 3u);
  EXPECT_EQ(events.front(), std::make_tuple(std::string("baseline"), 0, 2));
  std::map<std::string, std::pair<int, int>> last;  // phase -> (max done, total)
  for (const auto& [phase, done, total] : events) {
    auto& l = last[phase];
    l.first = std::max(l.first, done);
    l.second = total;
  }
  ASSERT_EQ(last.size(), 2 + r.rounds.size());
  int left = 0;
  for (const auto& c : r.rounds.back()) left += !c.limit.effect.empty();
  EXPECT_EQ(last.at("detection limits"), std::make_pair(left, left));
  EXPECT_EQ(last.at("baseline"), std::make_pair(2, 2));
  for (std::size_t k = 0; k < r.rounds.size(); ++k) {
    int testable = 0;
    for (const auto& c : r.rounds[k]) testable += c.testable;
    EXPECT_EQ(last.at("round " + std::to_string(k + 1)),
              std::make_pair(2 * testable, 2 * testable));
  }
}

TEST(DiscoverManyRows, MoreThanTheRowLimitIsRefusedBeforeAnyWork) {
  auto set = matrix(101, 10, 10);  // 10100 rows
  set.path = "big.csv";
  try {
    discover(contact::load_tyre_config(kConfig), set, {});
    FAIL() << "10100 rows accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("big.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 10000 measured rows (10100 given)"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace modaltyre::discover

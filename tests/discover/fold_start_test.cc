// The fit on all rows is never left worse than a start it already has (large_fit.h,
// refit_from_folds): the cross-validation folds' optima are scored on all rows and the fit is
// refined from the best when it fits all rows better. A creeping tread hidden in 12 footprints
// of the 2D SF-350 (as large_fit_test.cc's, fewer rows).
#include <gtest/gtest.h>

#include <numeric>

#include "modaltyre/discover/large_fit.h"
#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

double sum_of_squares(const FitResult& f) {
  return std::inner_product(f.residuals.begin(), f.residuals.end(), f.residuals.begin(), 0.0);
}

class FoldStart : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    Planted p;
    p.truth = [](auto& e) {
      e.tread_relaxation.enabled = true;
      e.tread_relaxation.creep_ratio = 0.8;
      e.tread_relaxation.time_constant_s = 40;
    };
    const double hold[] = {0, 60};
    p.rows = grid(
        {2000, 3200, 4400, 5600, 6800, 8000}, [&](auto& c, int l) { c.hold_s = hold[l]; }, 2);
    p.seed = 3;
    data_ = new studies::MeasurementSet(make_data(p, "fold_start"));
    config_ = new TyreConfig(contact::load_tyre_config(kConfig, {"contact.unit_length_mm=2"}));
    model_ = new contact::TyreModel(contact::build_tyre_model(*config_));
  }
  static void TearDownTestSuite() {
    delete model_;
    delete config_;
    delete data_;
  }
  static studies::MeasurementSet* data_;
  static TyreConfig* config_;
  static contact::TyreModel* model_;
};

studies::MeasurementSet* FoldStart::data_ = nullptr;
TyreConfig* FoldStart::config_ = nullptr;
contact::TyreModel* FoldStart::model_ = nullptr;

TEST_F(FoldStart, AFitLeftWorseThanItsFoldsIsRefinedFromTheBestFold) {
  const Evaluator ev(*model_, *data_);
  const Variant v = make_variant(*config_, {contact::EffectId::tread_relaxation});
  const FitAndCv good = fit_and_cross_validate(ev, *config_, v);
  ASSERT_EQ(good.cv.fold_values.size(), static_cast<std::size_t>(good.cv.folds));
  // The same fit stopped where its search started: the config's baseline scalars and the
  // effect's catalogue defaults (creep ratio and time constant far from the planted 0.8 and
  // 40 s), a point the search can stop at when the cost is flat around it (model_fit.cc). Its
  // folds' optima, each a re-fit on 5/6 of the rows, lie in the planted basin.
  std::vector<double> start;
  for (const auto& p : v.parameters)
    start.push_back(p.of_effect ? p.catalogue_default : p.get(*config_));
  FitAndCv stuck = good;
  stuck.fit = evaluate_fit(ev, *config_, v, start, good.fit.entries);
  ASSERT_GT(sum_of_squares(stuck.fit), 2 * sum_of_squares(good.fit));
  EXPECT_TRUE(refit_from_folds(ev, *config_, v, stuck));
  // Refined from the best fold it reaches the planted basin: the fit from the default start's,
  // to a fraction of its standard errors, with its standard errors and cross-validation.
  EXPECT_NEAR(sum_of_squares(stuck.fit), sum_of_squares(good.fit), 1e-3 * sum_of_squares(good.fit));
  ASSERT_EQ(stuck.fit.standard_errors.size(), v.parameters.size());
  for (std::size_t i = 0; i < v.parameters.size(); ++i)
    EXPECT_NEAR(stuck.fit.values[i], good.fit.values[i], 0.1 * good.fit.standard_errors[i])
        << v.parameters[i].key;
  EXPECT_NEAR(stuck.cv.rms_all, good.cv.rms_all, 0.01 * good.cv.rms_all);
}

TEST_F(FoldStart, AFitNoFoldImprovesIsLeftAsItIs) {
  // Where the search's own start was the best (every existing discover answer), the guard costs
  // one evaluation a fold and changes nothing.
  const Evaluator ev(*model_, *data_);
  const Variant v = make_variant(*config_, {contact::EffectId::tread_relaxation});
  const FitAndCv fc = fit_and_cross_validate(ev, *config_, v);
  FitAndCv again = fc;
  const int evaluations = again.cv.evaluations;
  EXPECT_FALSE(refit_from_folds(ev, *config_, v, again));
  EXPECT_EQ(again.fit.values, fc.fit.values);
  EXPECT_EQ(again.cv.residuals, fc.cv.residuals);
  EXPECT_EQ(again.cv.evaluations, evaluations + fc.cv.folds);
}

}  // namespace
}  // namespace modaltyre::discover

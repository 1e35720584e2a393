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

// The rows, the config, its model and the creeping tread's fit from its default start with its
// cross-validation, made once for both tests.
struct Rows {
  studies::MeasurementSet data;
  TyreConfig config;
  contact::TyreModel model;
  Variant v;
  FitAndCv good;
};

const Rows& creeping_tread_rows() {
  static const Rows rows = [] {
    const Planted p = creeping_tread();
    TyreConfig c = contact::load_tyre_config(kConfig, {"contact.unit_length_mm=2"});
    contact::TyreModel m = contact::build_tyre_model(c);
    Variant v = make_variant(c, {contact::EffectId::tread_relaxation});
    studies::MeasurementSet data = make_data(p, "fold_start");
    FitAndCv good = fit_and_cross_validate(Evaluator(m, data), c, v);  // holds no reference
    return Rows{std::move(data), std::move(c), std::move(m), std::move(v), std::move(good)};
  }();
  return rows;
}

TEST(FoldStart, AFitLeftWorseThanItsFoldsIsRefinedFromTheBestFold) {
  const Rows& rows = creeping_tread_rows();
  const TyreConfig& config = rows.config;
  const Variant& v = rows.v;
  const FitAndCv& good = rows.good;
  const Evaluator ev(rows.model, rows.data);
  ASSERT_EQ(good.cv.fold_values.size(), static_cast<std::size_t>(good.cv.folds));
  // The same fit stopped where its search started: the config's baseline scalars and the
  // effect's catalogue defaults (creep ratio and time constant far from the planted 0.8 and
  // 40 s), a point the search can stop at when the cost is flat around it (model_fit.cc). Its
  // folds' optima, each a re-fit on 5/6 of the rows, lie in the planted basin.
  std::vector<double> start;
  for (const auto& p : v.parameters)
    start.push_back(p.of_effect ? p.catalogue_default : p.get(config));
  FitAndCv stuck = good;
  stuck.fit = evaluate_fit(ev, config, v, start, good.fit.entries);
  ASSERT_GT(sum_of_squares(stuck.fit), 2 * sum_of_squares(good.fit));
  EXPECT_TRUE(refit_from_folds(ev, config, v, stuck));
  // Refined from the best fold it reaches the planted basin: the fit from the default start's,
  // to a fraction of its standard errors, with its standard errors and cross-validation.
  EXPECT_NEAR(sum_of_squares(stuck.fit), sum_of_squares(good.fit), 1e-3 * sum_of_squares(good.fit));
  ASSERT_EQ(stuck.fit.standard_errors.size(), v.parameters.size());
  for (std::size_t i = 0; i < v.parameters.size(); ++i)
    EXPECT_NEAR(stuck.fit.values[i], good.fit.values[i], 0.1 * good.fit.standard_errors[i])
        << v.parameters[i].key;
  EXPECT_NEAR(stuck.cv.rms_all, good.cv.rms_all, 0.01 * good.cv.rms_all);
}

TEST(FoldStart, AFitNoFoldImprovesIsLeftAsItIs) {
  // Where the search's own start was the best (every existing discover answer), the fit matches
  // its rows better than its folds predict them, and the guard neither evaluates nor changes.
  const Rows& rows = creeping_tread_rows();
  const FitAndCv& fc = rows.good;
  ASSERT_LT(fc.fit.rms_all, fc.cv.rms_all);
  FitAndCv again = fc;
  const int evaluations = again.cv.evaluations;
  EXPECT_FALSE(refit_from_folds(Evaluator(rows.model, rows.data), rows.config, rows.v, again));
  EXPECT_EQ(again.fit.values, fc.fit.values);
  EXPECT_EQ(again.cv.residuals, fc.cv.residuals);
  EXPECT_EQ(again.cv.evaluations, evaluations);
}

}  // namespace
}  // namespace modaltyre::discover

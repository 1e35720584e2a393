// A candidate's fit whose search ends with a re-fitted tyre scalar at a bound of its range also
// fits the new effect alone on the tyre as the user's config has it, then releases the scalars
// from there (model_fit.cc, fit_variant; docs/discover.md). The situation it is for: the
// current model's fit (the base a candidate starts from) has bent the tyre to a bound, where the
// bounded search variable is flat, so a search from it cannot bring the tyre back. A creeping
// tread hidden in 12 footprints of the 2D SF-350 (fold_start_test.cc's rows).
#include <gtest/gtest.h>

#include "modaltyre/discover/model_fit.h"
#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

TEST(ConfiguredStart, ACandidateStartedFromATyreBentToItsBoundFindsThePlantedTyreAndEffect) {
  const Planted p = creeping_tread();
  const TyreConfig config = contact::load_tyre_config(kConfig, {"contact.unit_length_mm=2"});
  const contact::TyreModel model = contact::build_tyre_model(config);
  const Variant v = make_variant(config, {contact::EffectId::tread_relaxation});
  const studies::MeasurementSet data = make_data(p, "configured_start");
  const Evaluator ev(model, data);
  std::vector<int> rows(data.rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = static_cast<int>(r);

  // The fit from the configured tyre: the planted basin.
  const FitResult good = fit_variant(ev, config, v, rows, std::nullopt, true);
  ASSERT_EQ(good.standard_errors.size(), v.parameters.size());
  // The base a previous round left: the compliance scale at the lower bound of its range (a
  // carcass far too stiff; its search variable's slope there is 1e-6 of the mid-range's).
  const FreeParameter& compliance = v.parameters.front();
  ASSERT_EQ(compliance.key, "modal.compliance_scale");
  ASSERT_FALSE(compliance.of_effect);
  TyreConfig bent = config;
  compliance.set(bent, compliance.min);
  const FitResult from_bent = fit_variant(ev, bent, v, rows, std::nullopt, false);
  // The configured tyre's start reaches the planted basin: every value within a tenth of its
  // standard error of the fit from the configured tyre, nothing left at the bound.
  for (std::size_t i = 0; i < v.parameters.size(); ++i)
    EXPECT_NEAR(from_bent.values[i], good.values[i], 0.1 * good.standard_errors[i])
        << v.parameters[i].key;
  EXPECT_GT(from_bent.values.front(), 2 * compliance.min);
  EXPECT_NEAR(from_bent.rms_all, good.rms_all, 1e-3 * good.rms_all);
}

}  // namespace
}  // namespace modaltyre::discover

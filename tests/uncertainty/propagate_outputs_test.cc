// propagate_outputs, the propagation for any outputs (tir export's coefficients, issue 35), on
// outputs whose law is known in closed form: the stated tread-modulus uncertainty sigma moves
// E to E (1 + x), so E's band is E0 sigma exactly (linear), E^2's is 2 E0^2 sigma to first
// order and its sampled mean E0^2 (1 + sigma^2); malformed evaluators are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::uncertainty {
namespace {

using modaltyre_test::kConfig2d;
constexpr double kSigma = 0.05;  // tread.modulus_std_percent: 5
// 2000 samples: the sample std's relative standard error is 1/sqrt(2 m) = 1.6 %; 4 of them.
constexpr int kSamples = 2000;
constexpr double kSampledRel = 0.064;

struct PropagateOutputs : ::testing::Test {
  contact::TyreConfig config =
      contact::load_tyre_config(kConfig2d, {"tread.modulus_std_percent=5"});
  modal::ModeIdentification modes;  // no mode inputs: only the stated modulus is uncertain
  const Evaluator modulus = [](const contact::TyreConfig& c, const modal::ModeIdentification&,
                               const std::string&) {
    const double e = c.tread.modulus_Pa * 1e-6;
    return std::vector<std::vector<double>>{{e, e * e}, {2 * e, -e}};
  };
  OutputSet outputs{{"E_MPa", "E2_MPa2"}, {}, {"a", "b"}, {}};
};

TEST_F(PropagateOutputs, LinearBandsAreTheClosedForm) {
  const double e0 = config.tread.modulus_Pa * 1e-6;
  PropagationOptions o;
  o.method = Method::linear;
  const PropagationResult r = propagate_outputs(config, modes, modulus, outputs, o);
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.inputs[0].input.kind, InputKind::tread_modulus);
  ASSERT_EQ(r.cases.size(), 2u);
  EXPECT_NEAR(r.cases[0].bands[0].std, e0 * kSigma, 1e-12 * e0);
  EXPECT_NEAR(r.cases[0].bands[1].std, 2 * e0 * e0 * kSigma, 1e-12 * e0 * e0);
  EXPECT_NEAR(r.cases[1].bands[0].std, 2 * e0 * kSigma, 1e-12 * e0);
  EXPECT_NEAR(r.cases[1].bands[1].std, e0 * kSigma, 1e-12 * e0);
  EXPECT_NEAR(r.cases[0].bands[0].p975 - r.cases[0].bands[0].p025, 2 * 1.959964 * e0 * kSigma,
              1e-5 * e0);
  EXPECT_EQ(r.method, "linear");
}

// A caller's own nominal run is taken, not repeated: the same bands, one evaluation fewer.
TEST_F(PropagateOutputs, ASuppliedNominalIsNotEvaluatedAgain) {
  PropagationOptions o;
  o.method = Method::linear;
  const PropagationResult own = propagate_outputs(config, modes, modulus, outputs, o);
  OutputSet given = outputs;
  given.nominal = modulus(config, modes, "the caller's run");
  const PropagationResult r = propagate_outputs(config, modes, modulus, given, o);
  EXPECT_EQ(r.evaluations, own.evaluations - 1);
  for (std::size_t c = 0; c < 2; ++c) {
    for (std::size_t q = 0; q < 2; ++q) {
      EXPECT_EQ(r.cases[c].bands[q].value, own.cases[c].bands[q].value);
      EXPECT_EQ(r.cases[c].bands[q].std, own.cases[c].bands[q].std);
    }
  }
}

TEST_F(PropagateOutputs, SampledMeanAndStdMatchTheMoments) {
  const double e0 = config.tread.modulus_Pa * 1e-6;
  PropagationOptions o;
  o.method = Method::sampled;
  o.samples = kSamples;
  const PropagationResult r = propagate_outputs(config, modes, modulus, outputs, o);
  EXPECT_EQ(r.method, "sampled");
  // E (1 + x), x ~ N(0, sigma^2): mean E0, std E0 sigma; E^2: mean E0^2 (1 + sigma^2),
  // std E0^2 sqrt(4 sigma^2 + 2 sigma^4).
  EXPECT_NEAR(r.cases[0].bands[0].std / (e0 * kSigma), 1, kSampledRel);
  EXPECT_NEAR(r.cases[0].bands[0].value / e0, 1, 4 * kSigma / std::sqrt(kSamples));
  const double s2 = e0 * e0 * std::sqrt(4 * kSigma * kSigma + 2 * std::pow(kSigma, 4));
  EXPECT_NEAR(r.cases[0].bands[1].std / s2, 1, kSampledRel);
  EXPECT_NEAR(r.cases[0].bands[1].value / (e0 * e0 * (1 + kSigma * kSigma)), 1,
              8 * kSigma / std::sqrt(kSamples));
}

TEST_F(PropagateOutputs, MalformedOutputsAreRefused) {
  const Evaluator ragged = [](const contact::TyreConfig& c, const modal::ModeIdentification&,
                              const std::string&) {
    // One output more away from the nominal modulus: a band of unlike things.
    std::vector<double> row = {c.tread.modulus_Pa};
    if (c.tread.modulus_Pa != 3e6) row.push_back(1.0);
    return std::vector<std::vector<double>>{row};
  };
  OutputSet one{{"E"}, {}, {}, {}};
  config.tread.modulus_Pa = 3e6;
  EXPECT_THROW(propagate_outputs(config, modes, ragged, one), ComputationError);
  const Evaluator nan = [](const contact::TyreConfig&, const modal::ModeIdentification&,
                           const std::string&) {
    return std::vector<std::vector<double>>{{std::nan("")}};
  };
  EXPECT_THROW(propagate_outputs(config, modes, nan, one), ComputationError);
  OutputSet wrong{{"E"}, {true, false}, {}, {}};
  EXPECT_THROW(propagate_outputs(config, modes, modulus, wrong), std::invalid_argument);
}

}  // namespace
}  // namespace modaltyre::uncertainty

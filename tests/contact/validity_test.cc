// The validity range of the linearised contact model (contact/validity.h, issue 16 item 6):
// its limits at their stated values, and the SF-350's Table 3 loads inside it while the load of
// the issue (30 kN, 79.8 mm of sinking) lies outside.
#include "modaltyre/contact/validity.h"

#include <gtest/gtest.h>

#include "modaltyre/contact/predictor.h"

namespace modaltyre::contact {
namespace {

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";

TEST(Validity, LimitsAreTwelvePercentOfR0InSinkingAndR0InContactLength) {
  TyreConfig c;
  c.outer_radius_m = 0.3;
  EXPECT_TRUE(validity(c, 0.12 * 0.3, 0.3).valid);
  const Validity deep = validity(c, 0.0361, 0.1);
  EXPECT_FALSE(deep.valid);
  EXPECT_NE(deep.reason.find("sinking 36.1 mm is 12 % of the free radius R0 = 300 mm"),
            std::string::npos)
      << deep.reason;
  EXPECT_NE(deep.reason.find("up to 12 % (36 mm)"), std::string::npos) << deep.reason;
  const Validity long_patch = validity(c, 0.01, 0.301);
  EXPECT_FALSE(long_patch.valid);
  EXPECT_NE(long_patch.reason.find("contact length 301 mm exceeds 1 R0 = 300 mm"),
            std::string::npos)
      << long_patch.reason;
  const Validity both = validity(c, 0.05, 0.4);
  EXPECT_NE(both.reason.find("; contact length"), std::string::npos) << both.reason;
}

TEST(Validity, Table3LoadsAreInsideAndThirtyKilonewtonsOutside) {
  const TyreConfig cfg = load_tyre_config(kConfig, {"contact.unit_length_mm=2"});
  const TyreModel model = build_tyre_model(cfg);
  for (double load : {2131.0, 8321.0}) {
    const Prediction p = predict(model, cfg.default_conditions(load));
    ASSERT_TRUE(p.ok()) << p.message;
    EXPECT_TRUE(validity(cfg, p.footprint.sinking_m, p.footprint.contact_length_m).valid) << load;
  }
  const Prediction p = predict(model, cfg.default_conditions(30000));
  ASSERT_TRUE(p.ok()) << p.message;
  EXPECT_GT(p.sinking_mm, 70);
  const Validity v = validity(cfg, p.footprint.sinking_m, p.footprint.contact_length_m);
  EXPECT_FALSE(v.valid);
  EXPECT_NE(v.reason.find("of the free radius R0 = 295 mm"), std::string::npos) << v.reason;
}

}  // namespace
}  // namespace modaltyre::contact

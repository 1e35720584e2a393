// set_keys_in_text: overrides applied to a config's text keep its comments and layout, and the
// result reads as the same overrides applied by ConfigTree.
#include "modaltyre/core/config_edit.h"

#include <gtest/gtest.h>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

const std::string kText =
    "# a tyre\n"
    "tyre:\n"
    "  # the radius\n"
    "  outer_radius_mm: 294.8   # nominal\n"
    "  name: \"SF # 350\"\n"
    "modal:\n"
    "  compliance_scale: 0.97678\n"
    "  load_hold: {load_N: 4000, hold_s: 120}\n"
    "validation:\n"
    "  calibrate: [modal.compliance_scale, tread.modulus_MPa]\n"
    "  rows:\n"
    "    - 1\n"
    "    - 6\n"
    "# the end\n";

std::string dump_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return ConfigTree::from_string(text, "t.yaml", overrides).dump();
}

TEST(core_SetKeysInText, ValuesOnTheirLinesKeepCommentsAndMarkTheRest) {
  const std::vector<std::string> ov = {"modal.compliance_scale=1.4655", "tyre.outer_radius_mm=300",
                                       "tyre.name='X # 1'",
                                       "validation.calibrate=[tread.modulus_MPa]"};
  const auto out = set_keys_in_text(kText, "t.yaml", ov, "set here");
  ASSERT_TRUE(out) << "every key is on one line";
  EXPECT_EQ(*out,
            "# a tyre\n"
            "tyre:\n"
            "  # the radius\n"
            "  outer_radius_mm: 300   # nominal\n"
            "  name: 'X # 1'  # set here\n"
            "modal:\n"
            "  compliance_scale: 1.4655  # set here\n"
            "  load_hold: {load_N: 4000, hold_s: 120}\n"
            "validation:\n"
            "  calibrate: [tread.modulus_MPa]  # set here\n"
            "  rows:\n"
            "    - 1\n"
            "    - 6\n"
            "# the end\n");
  EXPECT_EQ(dump_of(*out), dump_of(kText, ov));
}

TEST(core_SetKeysInText, MissingKeysGoAtTheEndOfTheirSectionOrTheDocument) {
  const std::vector<std::string> ov = {"modal.extend_orders=false",
                                       "effects.dry_friction.enabled=true",
                                       "effects.dry_friction.friction_force_N=635"};
  const auto out = set_keys_in_text(kText, "t.yaml", ov);
  ASSERT_TRUE(out);
  EXPECT_NE(out->find("  load_hold: {load_N: 4000, hold_s: 120}\n  extend_orders: false\n"),
            std::string::npos)
      << *out;
  EXPECT_NE(out->find("    - 6\neffects:\n  dry_friction:\n    enabled: true\n"
                      "    friction_force_N: 635\n# the end\n"),
            std::string::npos)
      << *out;
  EXPECT_EQ(dump_of(*out), dump_of(kText, ov));
}

TEST(core_SetKeysInText, WhatCannotBeSetInPlaceIsNulloptNotAWrongText) {
  // Inside a flow mapping, and a value spanning lines (a block sequence).
  EXPECT_FALSE(set_keys_in_text(kText, "t.yaml", {"modal.load_hold.hold_s=60"}));
  EXPECT_FALSE(set_keys_in_text(kText, "t.yaml", {"validation.rows=[2]"}));
  EXPECT_FALSE(set_keys_in_text("a: 1\r\nb: 2\r\n", "t.yaml", {"a=3"}));
  EXPECT_THROW(set_keys_in_text(kText, "t.yaml", {"modal.compliance_scale"}), InputError);
  EXPECT_THROW(set_keys_in_text("a: [1\n", "t.yaml", {"a=3"}), InputError);
}

}  // namespace
}  // namespace modaltyre

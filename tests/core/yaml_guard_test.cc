// Issue 16 items 2 and 3: a key given twice is an error naming both lines, aliases are refused
// before anything expands them, and the size of a YAML input is bounded.
#include "modaltyre/core/yaml_guard.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

// The InputError thrown by parsing `yaml`, or a failure when none is thrown.
InputError error_of(const std::string& yaml) {
  try {
    (void)parse_yaml(yaml, "c.yaml");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << yaml;
  return InputError({"", 0, ""}, "");
}

TEST(YamlGuard, KeyTwiceInASectionNamesBothLines) {
  const InputError e = error_of("tread:\n  modulus_MPa: 1.0\n  thickness_mm: 8\n  modulus_MPa: 9\n");
  EXPECT_EQ(e.where().file, "c.yaml");
  EXPECT_EQ(e.where().line, 4);
  EXPECT_EQ(e.where().key, "tread.modulus_MPa");
  EXPECT_NE(std::string(e.what()).find("first at line 2, again at line 4"), std::string::npos)
      << e.what();
}

TEST(YamlGuard, SectionTwiceNamesBothLines) {
  const InputError e = error_of("tread:\n  a: 1\nmodal:\n  b: 2\ntread:\n  c: 3\n");
  EXPECT_EQ(e.where().line, 5);
  EXPECT_EQ(e.where().key, "tread");
  EXPECT_NE(std::string(e.what()).find("first at line 1"), std::string::npos) << e.what();
}

TEST(YamlGuard, KeyTwiceInAFlowMapping) {
  const InputError e = error_of("grid: {load_N: [1], load_N: [2]}\n");
  EXPECT_EQ(e.where().key, "grid.load_N");
}

// The same key in two different sections, or in list items, is fine.
TEST(YamlGuard, SameKeyInDifferentMappingsIsFine) {
  EXPECT_NO_THROW(parse_yaml("a:\n  x: 1\nb:\n  x: 2\nl:\n  - {x: 1}\n  - {x: 2}\n", "c.yaml"));
}

// A "billion laughs" bomb is refused at its first alias, long before anything expands.
TEST(YamlGuard, AliasBombIsRefusedAtTheFirstAlias) {
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 12; ++i) {
    const std::string p = "*a" + std::to_string(i - 1);
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + p + ", " + p + ", " + p +
            ", " + p + ", " + p + ", " + p + ", " + p + ", " + p + ", " + p + ", " + p + "]\n";
  }
  const auto t0 = std::chrono::steady_clock::now();
  const InputError e = error_of(bomb);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.where().key, "a1");
  EXPECT_NE(std::string(e.what()).find("aliases"), std::string::npos) << e.what();
}

TEST(YamlGuard, MergeKeyIsAnAlias) {
  const InputError e = error_of("base: &b {x: 1}\nother:\n  <<: *b\n");
  EXPECT_EQ(e.where().line, 3);
}

TEST(YamlGuard, SecondDocumentIsRefused) {
  const InputError e = error_of("a: 1\n---\na: 2\n");
  EXPECT_EQ(e.where().line, 2);
}

TEST(YamlGuard, NodeCountIsBounded) {
  std::string big = "x: [";
  for (long i = 0; i <= kMaxYamlNodes; ++i) big += "0,";
  big += "0]\n";
  const InputError e = error_of(big);
  EXPECT_NE(std::string(e.what()).find("YAML nodes"), std::string::npos) << e.what();
}

// --set values get the same checks, named by their key.
TEST(YamlGuard, SetValueWithAliasesIsRefused) {
  try {
    (void)parse_set_value("[&a [1, 2], *a, *a]", "modal.loads_N");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "--set");
    EXPECT_EQ(e.where().key, "modal.loads_N");
  }
}

// The tree loader refuses duplicates too (it used to keep the first value silently).
TEST(YamlGuard, ConfigTreeRefusesDuplicates) {
  EXPECT_THROW(ConfigTree::from_string("tread:\n  modulus_MPa: 1\n  modulus_MPa: 2\n", "c.yaml"),
               InputError);
}

}  // namespace
}  // namespace modaltyre

// Issue 16 items 2 and 3: a key given twice is an error naming both lines, aliases are refused
// before anything expands them, and the size of a YAML input is bounded.
#include "modaltyre/core/yaml_guard.h"

#include <gtest/gtest.h>

#include <chrono>
#include <ostream>
#include <string>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

// The InputError thrown by parsing `yaml`, or a failure when none is thrown.
InputError guard_error_of(const std::string& yaml) {
  try {
    (void)parse_yaml(yaml, "c.yaml");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << yaml;
  return InputError({"", 0, ""}, "");
}

TEST(YamlGuard, KeyTwiceInASectionNamesBothLines) {
  const InputError e =
      guard_error_of("tread:\n  modulus_MPa: 1.0\n  thickness_mm: 8\n  modulus_MPa: 9\n");
  EXPECT_EQ(e.where().file, "c.yaml");
  EXPECT_EQ(e.where().line, 4);
  EXPECT_EQ(e.where().key, "tread.modulus_MPa");
  EXPECT_NE(std::string(e.what()).find("first at line 2, again at line 4"), std::string::npos)
      << e.what();
}

TEST(YamlGuard, SectionTwiceNamesBothLines) {
  const InputError e = guard_error_of("tread:\n  a: 1\nmodal:\n  b: 2\ntread:\n  c: 3\n");
  EXPECT_EQ(e.where().line, 5);
  EXPECT_EQ(e.where().key, "tread");
  EXPECT_NE(std::string(e.what()).find("first at line 1"), std::string::npos) << e.what();
}

TEST(YamlGuard, KeyTwiceInAFlowMapping) {
  const InputError e = guard_error_of("grid: {load_N: [1], load_N: [2]}\n");
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
  const InputError e = guard_error_of(bomb);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.where().key, "a1");
  EXPECT_NE(std::string(e.what()).find("aliases"), std::string::npos) << e.what();
}

TEST(YamlGuard, MergeKeyIsAnAlias) {
  const InputError e = guard_error_of("base: &b {x: 1}\nother:\n  <<: *b\n");
  EXPECT_EQ(e.where().line, 3);
}

TEST(YamlGuard, SecondDocumentIsRefused) {
  const InputError e = guard_error_of("a: 1\n---\na: 2\n");
  EXPECT_EQ(e.where().line, 2);
}

TEST(YamlGuard, NodeCountIsBounded) {
  std::string big = "x: [";
  for (long i = 0; i <= kMaxYamlNodes; ++i) big += "0,";
  big += "0]\n";
  const InputError e = guard_error_of(big);
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

// Deep nesting (issue 16): 10 000 nested lists or mappings, flow or block, are refused naming
// the line and the depth limit, before yaml-cpp's parser gives up with "bad file" (or its
// recursion exhausts the stack); the limit itself is accepted.
struct Nesting {
  std::string name;
  std::string open, close;  // one level
  bool block = false;       // a block value starts on the next line
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const Nesting& n, std::ostream* os) { *os << n.name; }

// The value nested `depth` levels deep.
std::string nested_value(const Nesting& n, int depth) {
  std::string text;
  for (int i = 0; i < depth; ++i) text += n.open;
  text += "1";
  for (int i = 0; i < depth; ++i) text += n.close;
  return text;
}

// A config with that value at tread.x (line 2, or 3 for a block value).
std::string nested_config(const Nesting& n, int depth) {
  return "tread:\n  x:" + std::string(n.block ? "\n    " : " ") + nested_value(n, depth) + "\n";
}

class YamlNesting : public ::testing::TestWithParam<Nesting> {};

TEST_P(YamlNesting, TenThousandLevelsAreRefusedAtTheirLine) {
  const InputError e = guard_error_of(nested_config(GetParam(), 10000));
  EXPECT_EQ(e.where().file, "c.yaml");
  EXPECT_EQ(e.where().line, GetParam().block ? 3 : 2);
  EXPECT_NE(std::string(e.what()).find("nesting deeper than 64 levels"), std::string::npos)
      << e.what();
  // In a --set value too.
  try {
    (void)parse_set_value(nested_value(GetParam(), 10000), "tread.x");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& s) {
    EXPECT_EQ(s.where().file, "--set");
    EXPECT_NE(std::string(s.what()).find("nesting deeper than 64"), std::string::npos) << s.what();
  }
}

TEST_P(YamlNesting, TheLimitItselfIsAccepted) {
  // The root mapping and tread: are two levels.
  EXPECT_NO_THROW(parse_yaml(nested_config(GetParam(), kMaxYamlDepth - 2), "c.yaml"));
  EXPECT_THROW(parse_yaml(nested_config(GetParam(), kMaxYamlDepth - 1), "c.yaml"), InputError);
}

INSTANTIATE_TEST_SUITE_P(Styles, YamlNesting,
                         ::testing::Values(Nesting{"FlowLists", "[", "]"},
                                           Nesting{"FlowMappings", "{a: ", "}"},
                                           Nesting{"BlockLists", "- ", "", true}),
                         [](const ::testing::TestParamInfo<Nesting>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace modaltyre

// Strict YAML configuration: unknown keys, wrong types and out-of-range values are errors that
// name file, line and dotted key; --set overrides are applied and reported as "--set".
#include "modaltyre/core/config_tree.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

const char* kYaml =
    "tread:\n"                  // line 1
    "  modulus_MPa: 6.0\n"      // line 2
    "  tan_delta: 0.15\n"       // line 3
    "solver:\n"                 // line 4
    "  max_iterations: 200\n"   // line 5
    "loads_N: [1000, 2000]\n";  // line 6

template <class F>
InputError error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("none");
}

/// Reads every key of kYaml as a program would.
void read_all(const ConfigTree& tree) {
  const auto root = tree.root();
  const auto tread = root.section("tread");
  tread.positive("modulus_MPa", 6.0, 1e4);
  tread.number("tan_delta", 0.1, 0.0, 2.0);
  root.section("solver").integer("max_iterations", 100, 1, 100000);
  root.numbers("loads_N", {}, 0.0, 1e6);
}

// Values are read, missing keys keep their defaults and a fully read tree has no unknown keys.
TEST(ConfigTree, ReadsValuesAndDefaults) {
  const auto tree = ConfigTree::from_string(kYaml, "cfg.yaml");
  const auto root = tree.root();
  EXPECT_DOUBLE_EQ(root.section("tread").number("modulus_MPa", 1.0, 0.0, 100.0), 6.0);
  EXPECT_DOUBLE_EQ(root.section("tread").number("absent", 3.5, 0.0, 100.0), 3.5);
  EXPECT_EQ(root.section("solver").integer("max_iterations", 1, 1, 1000), 200);
  EXPECT_EQ(root.numbers("loads_N", {}, 0, 1e6), (std::vector<double>{1000, 2000}));
  root.section("tread").number("tan_delta", 0.1, 0.0, 2.0);
  EXPECT_NO_THROW(tree.reject_unknown_keys());
}

// A misspelt key that nobody reads is reported with file, its own line and the dotted key.
TEST(ConfigTree, UnknownKeyNamesFileLineAndKey) {
  const std::string yaml = std::string(kYaml) + "tread2:\n  modolus_MPa: 3\n";
  const auto tree = ConfigTree::from_string(yaml, "cfg.yaml");
  read_all(tree);
  const auto e = error_of([&] { tree.reject_unknown_keys(); });
  EXPECT_EQ(e.where().file, "cfg.yaml");
  EXPECT_EQ(e.where().line, 8);
  EXPECT_EQ(e.where().key, "tread2.modolus_MPa");
  EXPECT_NE(std::string(e.what()).find("cfg.yaml:8: tread2.modolus_MPa"), std::string::npos)
      << e.what();
}

// A misspelt key inside a known section is found too (line 3 here).
TEST(ConfigTree, UnknownKeyInsideKnownSection) {
  const auto tree =
      ConfigTree::from_string("tread:\n  modulus_MPa: 6\n  modolus_MPa: 3\n", "t.yaml");
  tree.root().section("tread").number("modulus_MPa", 1, 0, 100);
  const auto e = error_of([&] { tree.reject_unknown_keys(); });
  EXPECT_EQ(e.where().line, 3);
  EXPECT_EQ(e.where().key, "tread.modolus_MPa");
}

// Text where a number is expected is a wrong-type error at the key's line.
TEST(ConfigTree, WrongType) {
  const auto tree = ConfigTree::from_string("tread:\n  modulus_MPa: soft\n", "t.yaml");
  const auto e = error_of([&] { tree.root().section("tread").number("modulus_MPa", 1, 0, 100); });
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.where().key, "tread.modulus_MPa");
  const auto e2 = error_of([&] { tree.root().section("tread").integer("modulus_MPa", 1, 0, 9); });
  EXPECT_EQ(e2.where().key, "tread.modulus_MPa");
  // A mapping where a list is expected.
  const auto t2 = ConfigTree::from_string("loads_N:\n  a: 1\n", "t.yaml");
  EXPECT_EQ(error_of([&] { t2.root().numbers("loads_N", {}, 0, 1); }).where().key, "loads_N");
  // A scalar where a section is expected.
  const auto t3 = ConfigTree::from_string("tread: 5\n", "t.yaml");
  EXPECT_EQ(error_of([&] { t3.root().section("tread"); }).where().key, "tread");
}

// Out-of-range values (negative modulus, non-positive for positive(), non-integer count) fail.
TEST(ConfigTree, OutOfRange) {
  const auto tree = ConfigTree::from_string(
      "tread:\n  modulus_MPa: -3\n  tan_delta: 5\nsolver:\n  max_iterations: 2.5\n", "t.yaml");
  const auto tread = tree.root().section("tread");
  const auto e = error_of([&] { tread.positive("modulus_MPa", 6.0, 1e4); });
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.where().key, "tread.modulus_MPa");
  EXPECT_EQ(error_of([&] { tread.number("modulus_MPa", 6.0, 1e-3, 1e4); }).where().line, 2);
  EXPECT_EQ(error_of([&] { tread.number("tan_delta", 0.1, 0.0, 2.0); }).where().line, 3);
  EXPECT_EQ(error_of([&] { tree.root().section("solver").integer("max_iterations", 1, 1, 9); })
                .where()
                .line,
            5);
}

// An integer list's value beyond long long's range is named as read (fuzz_config found the
// message's integer conversion undefined there).
TEST(ConfigTree, IntegerListValueBeyondAnyIntegerIsNamedAsRead) {
  const auto tree = ConfigTree::from_string("modal:\n  alt: [[1, 2], [3, 1e300]]\n", "t.yaml");
  const auto e = error_of([&] { tree.root().section("modal").integer_lists("alt", 0, 1000, 10); });
  EXPECT_EQ(e.where().key, "modal.alt");
  EXPECT_NE(std::string(e.what()).find("list value 1e+300 is out of range [0, 1000]"),
            std::string::npos)
      << e.what();
  const auto small = ConfigTree::from_string("modal:\n  alt: [[1001]]\n", "t.yaml");
  EXPECT_NE(std::string(error_of([&] {
                          small.root().section("modal").integer_lists("alt", 0, 1000, 10);
                        }).what())
                .find("list value 1001 is out of range"),
            std::string::npos);
}

// --set replaces a value; a bad value given by --set is blamed on --set, not the file.
TEST(ConfigTree, SetOverrides) {
  const auto tree = ConfigTree::from_string(kYaml, "cfg.yaml",
                                            {"tread.modulus_MPa=8.5", "solver.new_section.x=1"});
  EXPECT_DOUBLE_EQ(tree.root().section("tread").number("modulus_MPa", 1, 0, 100), 8.5);

  const auto bad = ConfigTree::from_string(kYaml, "cfg.yaml", {"tread.modulus_MPa=-1"});
  const auto e = error_of([&] { bad.root().section("tread").positive("modulus_MPa", 6.0); });
  EXPECT_EQ(e.where().file, "--set");
  EXPECT_EQ(e.where().key, "tread.modulus_MPa");
}

// An unknown key introduced by --set (a typo on the command line) is reported as --set.
TEST(ConfigTree, UnknownSetKeyReportedAsSet) {
  const auto tree = ConfigTree::from_string(kYaml, "cfg.yaml", {"tread.modolus_MPa=3"});
  read_all(tree);
  const auto e = error_of([&] { tree.reject_unknown_keys(); });
  EXPECT_EQ(e.where().file, "--set");
  EXPECT_EQ(e.where().key, "tread.modolus_MPa");
  EXPECT_NE(std::string(e.what()).find("--set: tread.modolus_MPa"), std::string::npos) << e.what();
}

// Malformed --set arguments are rejected with the assignment named.
TEST(ConfigTree, MalformedSet) {
  EXPECT_EQ(error_of([] { ConfigTree::from_string(kYaml, "c", {"novalue"}); }).where().file,
            "--set");
  EXPECT_EQ(error_of([] { ConfigTree::from_string(kYaml, "c", {"a..b=1"}); }).where().file,
            "--set");
  // Descending into a scalar is not possible.
  EXPECT_EQ(error_of([] { ConfigTree::from_string(kYaml, "c", {"loads_N.x=1"}); }).where().key,
            "loads_N.x");
}

// YAML syntax errors and missing files are InputErrors naming the file.
TEST(ConfigTree, SyntaxErrorAndMissingFile) {
  const auto e = error_of([] { ConfigTree::from_string("a: [1, 2\nb: 3\n", "broken.yaml"); });
  EXPECT_EQ(e.where().file, "broken.yaml");
  EXPECT_GT(e.where().line, 0);
  const auto e2 = error_of([] { ConfigTree::load("/nonexistent/dir/cfg.yaml"); });
  EXPECT_EQ(e2.where().file, "/nonexistent/dir/cfg.yaml");
}

// Relative paths in a config resolve against the config's folder; load() reads files.
TEST(ConfigTree, LoadAndResolvePath) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("modaltyre_config_tree_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "c.yaml";
  std::ofstream(file) << "a:\n  b: 2\n  bb: 3\n";
  const auto tree = ConfigTree::load(file.string());
  EXPECT_EQ(tree.root().section("a").integer("b", 0, 0, 10), 2);
  EXPECT_EQ(tree.resolve_path("data/x.csv"), dir / "data/x.csv");
  EXPECT_EQ(tree.resolve_path("/abs/x.csv"), fs::path("/abs/x.csv"));
  const auto e = error_of([&] { tree.reject_unknown_keys(); });
  EXPECT_EQ(e.where().file, file.string());
  EXPECT_EQ(e.where().line, 3);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace modaltyre

namespace modaltyre {
namespace {

// A list or mapping used as a key (found by fuzz_config: it escaped as a yaml-cpp exception and
// aborted) is an InputError naming the file and line, both when unknown keys are rejected and
// when a missing key's location is looked up among such keys.
TEST(ConfigTree, NonScalarKeysAreInputErrors) {
  const ConfigTree t = ConfigTree::from_string("tread:\n  modulus_MPa: 6\n[a]: 1\n", "k.yaml");
  t.root().section("tread").number("modulus_MPa", 6, 0, 100);
  const InputError e = error_of([&] { t.reject_unknown_keys(); });
  EXPECT_EQ(e.where().file, "k.yaml");
  EXPECT_EQ(e.where().line, 3);
  EXPECT_NE(std::string(e.what()).find("plain names"), std::string::npos);

  const ConfigTree u = ConfigTree::from_string("modal: {[a]: 1}\n", "m.yaml");
  const InputLocation where = u.root().section("modal").where("hammer_csv");
  EXPECT_EQ(where.file, "m.yaml");
  EXPECT_EQ(where.key, "modal.hammer_csv");
}

// A pipe would block the read forever and a huge file would be parsed into memory: both are
// refused before anything is read, naming the file.
TEST(ConfigTree, PipeAndHugeFileAreRefusedBeforeReading) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("modaltyre_config_hostile_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string fifo = (dir / "config.yaml").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const InputError e = error_of([&] { ConfigTree::load(fifo); });
  EXPECT_EQ(e.where().file, fifo);
  EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();

  const std::string big = (dir / "big.yaml").string();
  { std::ofstream(big) << "tread:\n"; }
  std::filesystem::resize_file(big, 64u << 20);  // sparse: no disk used
  const InputError h = error_of([&] { ConfigTree::load(big); });
  EXPECT_EQ(h.where().file, big);
  EXPECT_NE(std::string(h.what()).find("over 16 MB"), std::string::npos) << h.what();
  std::filesystem::remove_all(dir);
}

// Issue 16: the same --set key twice is refused naming both values; different keys, and a key
// inside a section set whole (not the same key), pass.
TEST(ConfigTree, RepeatedOverrideIsRefusedNamingBothValues) {
  const InputError e = error_of([] {
    refuse_repeated_overrides({"tread.modulus_MPa=3", "a=1", "tread.modulus_MPa=4"});
  });
  EXPECT_EQ(e.where().file, "--set");
  EXPECT_EQ(e.where().key, "tread.modulus_MPa");
  EXPECT_NE(std::string(e.what()).find("given twice ('3' and '4')"), std::string::npos) << e.what();
  EXPECT_NO_THROW(refuse_repeated_overrides({"tread.modulus_MPa=3", "tread.tan_delta=0.1"}));
  EXPECT_NO_THROW(refuse_repeated_overrides({"tread={modulus_MPa: 3}", "tread.tan_delta=0.1"}));
}

}  // namespace
}  // namespace modaltyre

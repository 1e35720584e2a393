// Text that is not UTF-8 text, and thread counts from the environment (issue 38): each refusal
// says what is wrong and where, before a reader or OpenMP acts on it.
#include <gtest/gtest.h>

#include <string>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/input_file.h"
#include "modaltyre/core/thread_env.h"

namespace {

using modaltyre::InputError;
using modaltyre::text_problem;

TEST(TextProblem, CleanTextAndCrlfAndBomPass) {
  EXPECT_FALSE(text_problem("a: 1\nb: caf\xC3\xA9\n").has_value());
  EXPECT_FALSE(text_problem("a: 1\r\nb: 2\r\n").has_value());
  EXPECT_FALSE(text_problem("\xEF\xBB\xBF"
                            "a: 1\n")
                   .has_value());
  EXPECT_FALSE(text_problem("").has_value());
}

TEST(TextProblem, NulLatin1AndCrOnlyAreFoundAtTheirLine) {
  const auto nul = text_problem(std::string("a: 1\nb: x\0y\n", 12));
  ASSERT_TRUE(nul.has_value());
  EXPECT_EQ(nul->line, 2);
  EXPECT_NE(nul->message.find("NUL"), std::string::npos);
  const auto latin1 = text_problem("a: 1\nb: 2\nname: caf\xE9\n");
  ASSERT_TRUE(latin1.has_value());
  EXPECT_EQ(latin1->line, 3);
  EXPECT_NE(latin1->message.find("\\xE9 is not UTF-8"), std::string::npos) << latin1->message;
  const auto cr = text_problem("a: 1\rb: 2\r");
  ASSERT_TRUE(cr.has_value());
  EXPECT_EQ(cr->line, 1);
  EXPECT_NE(cr->message.find("carriage return"), std::string::npos);
}

InputError yaml_refusal(const std::string& text) {
  try {
    modaltyre::ConfigTree::from_string(text, "c.yaml");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return InputError("");
}

// The Latin-1 byte of issue 38 (tyre.name) is named with its file, line and dotted key.
TEST(TextProblem, YamlNamesTheKeyWhoseValueIsNotUtf8) {
  const InputError e = yaml_refusal("tyre:\n  outer_radius_mm: 290\n  name: Pneu caf\xE9\n");
  EXPECT_EQ(e.where().file, "c.yaml");
  EXPECT_EQ(e.where().line, 3);
  EXPECT_EQ(e.where().key, "tyre.name");
  EXPECT_NE(std::string(e.what()).find("not UTF-8"), std::string::npos) << e.what();
}

TEST(TextProblem, YamlNulAndCrOnlyLineEndsAreNamed) {
  const InputError nul = yaml_refusal(std::string("tyre:\n  name: a\0b\n", 18));
  EXPECT_EQ(nul.where().line, 2);
  EXPECT_NE(std::string(nul.what()).find("NUL byte"), std::string::npos) << nul.what();
  const InputError cr = yaml_refusal("tyre:\r  name: a\r");
  EXPECT_NE(std::string(cr.what()).find("carriage return"), std::string::npos) << cr.what();
}

// YAML 1.1 reads 0x1 as 1 for a typed read; the config reader refuses it (decimal only).
TEST(TextProblem, YamlHexadecimalNumberIsRefused) {
  const auto tree = modaltyre::ConfigTree::from_string("a: 0x1\n", "c.yaml");
  try {
    (void)tree.root().number("a", 0, -1e9, 1e9);
    ADD_FAILURE() << "0x1 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.where().key, "a");
    EXPECT_NE(std::string(e.what()).find("hexadecimal"), std::string::npos) << e.what();
  }
}

TEST(ThreadEnvironment, OmpNumThreadsIsBoundedLikeThreads) {
  for (const char* ok : {"1", "2", "4096", "4,2"}) {
    EXPECT_NO_THROW(modaltyre::check_omp_num_threads_value(ok)) << ok;
  }
  for (const char* bad : {"100000", "0", "-1", "0x10", "two", "2.5", "4,", "4097"}) {
    try {
      modaltyre::check_omp_num_threads_value(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().key, "OMP_NUM_THREADS") << bad;
    }
  }
}

}  // namespace

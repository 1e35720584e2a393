// The one status type of the library's results: only `converged` is ok, and every status has
// its own words for messages.
#include "modaltyre/core/solve_status.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

using modaltyre::SolveStatus;

TEST(SolveStatus, OnlyConvergedIsOk) {
  EXPECT_TRUE(modaltyre::ok(SolveStatus::converged));
  for (SolveStatus s : {SolveStatus::max_iterations, SolveStatus::singular, SolveStatus::aborted,
                        SolveStatus::failed}) {
    EXPECT_FALSE(modaltyre::ok(s)) << modaltyre::to_string(s);
  }
}

TEST(SolveStatus, EveryStatusHasItsOwnWords) {
  std::set<std::string> words;
  for (SolveStatus s : {SolveStatus::converged, SolveStatus::max_iterations, SolveStatus::singular,
                        SolveStatus::aborted, SolveStatus::failed}) {
    const std::string w = modaltyre::to_string(s);
    EXPECT_FALSE(w.empty());
    EXPECT_NE(w, "unknown");
    words.insert(w);
  }
  EXPECT_EQ(words.size(), 5u);
  EXPECT_STREQ(modaltyre::to_string(SolveStatus::converged), "converged");
}

}  // namespace

// DiscoverOptions validate themselves: a value discover() cannot use is an InputError naming the
// option, before any file is read or any model is built.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "modaltyre/core/errors.h"
#include "modaltyre/discover/discover.h"

namespace {

using modaltyre::discover::DiscoverOptions;

// The message of the InputError validate() throws after `change`, or "" when it accepts.
std::string refusal(const std::function<void(DiscoverOptions&)>& change) {
  DiscoverOptions o;
  change(o);
  try {
    o.validate();
  } catch (const modaltyre::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DiscoverOptions, TheDefaultsAndTheRangeEndsAreAccepted) {
  EXPECT_EQ(refusal([](DiscoverOptions&) {}), "");
  EXPECT_EQ(refusal([](DiscoverOptions& o) { o.unit_length_mm = 0; }), "");  // the config's mesh
  EXPECT_EQ(refusal([](DiscoverOptions& o) { o.unit_length_mm = 50; }), "");
  EXPECT_EQ(refusal([](DiscoverOptions& o) { o.max_effects = 9; }), "");
  EXPECT_EQ(refusal([](DiscoverOptions& o) { o.threads = 4096; }), "");
  EXPECT_EQ(refusal([](DiscoverOptions& o) { o.fit.exact_rows = 4; }), "");
}

TEST(DiscoverOptions, EachUnusableValueNamesItsOption) {
  const struct {
    std::function<void(DiscoverOptions&)> change;
    const char* option;
  } cases[] = {
      {[](DiscoverOptions& o) { o.unit_length_mm = std::nan(""); }, "--unit-length-mm"},
      {[](DiscoverOptions& o) { o.unit_length_mm = -1; }, "--unit-length-mm"},
      {[](DiscoverOptions& o) { o.unit_length_mm = 50.5; }, "--unit-length-mm"},
      {[](DiscoverOptions& o) { o.max_effects = 0; }, "--max-effects"},
      {[](DiscoverOptions& o) { o.max_effects = 10; }, "--max-effects"},
      {[](DiscoverOptions& o) { o.threads = -1; }, "--threads"},
      {[](DiscoverOptions& o) { o.fit.exact_rows = 3; }, "--exact-rows"},
  };
  for (const auto& c : cases) {
    const std::string why = refusal(c.change);
    EXPECT_NE(why.find(c.option), std::string::npos) << c.option << ": '" << why << "'";
  }
  EXPECT_NE(refusal([](DiscoverOptions& o) {
              o.unit_length_mm = INFINITY;
            }).find("must be a finite number"),
            std::string::npos);
}

}  // namespace

// The operating-condition catalogue (core/conditions.h) is the one place a condition's range and
// words are declared: the measurement reader, the sweep file and rheology's static loop accept
// exactly its values and refuse the rest with its message.
#include "modaltyre/core/conditions.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "../support/data_paths.h"
#include "../support/table3_tyre.h"
#include "modaltyre/contact/operating_conditions.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/rheology/three_element.h"
#include "modaltyre/studies/measurements.h"
#include "modaltyre/studies/sweep_spec.h"

namespace {

namespace fs = std::filesystem;
using namespace modaltyre;

using modaltyre_test::kSweepName;

using modaltyre_test::table3_tyre;

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() /
         ("modaltyre_conditions_" + std::to_string(::getpid()) + "_" + name);
}

// The message read_measurements() gives for `cell` in the column of `c` (empty: accepted), and
// the condition it read.
std::string measured(const ConditionInfo& c, const std::string& cell, double* value = nullptr) {
  const fs::path p = scratch(c.name + ".csv");
  // A slip makes a traction row (studies/traction_rows.h), with a traction observable.
  std::string header = c.name == "slip" ? "drawbar_pull_N" : "sinking_mm", row = "15";
  if (c.id != ConditionId::load_N) header += ",load_N", row += ",4000";
  std::ofstream(p) << header << "," << c.name << "\n" << row << "," << cell << "\n";
  try {
    const auto set = studies::read_measurements(p.string(), table3_tyre());
    if (value) *value = contact::condition_value(set.rows.at(0).conditions, c.id);
    fs::remove(p);
    return "";
  } catch (const InputError& e) {
    fs::remove(p);
    return e.what();
  }
}

// The message parse_sweep_spec() gives for `cell` as a grid value of `c` (empty: accepted).
std::string swept(const ConditionInfo& c, const std::string& cell) {
  std::string yaml = "base: ../sf350_2d_table3.yaml\ngrid:\n  " + c.name + ": [" + cell + "]\n";
  if (c.id != ConditionId::load_N) yaml += "  load_N: [4000]\n";
  try {
    studies::parse_sweep_spec(yaml, kSweepName);
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

TEST(ConditionCatalogue, NamesAreUniqueInIdOrderAndAreTheMeasurementColumns) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < condition_catalogue().size(); ++i) {
    const ConditionInfo& c = condition_catalogue()[i];
    EXPECT_EQ(static_cast<std::size_t>(c.id), i) << c.name;
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_EQ(find_condition(c.name), &c);
    EXPECT_TRUE(studies::is_sweep_condition(c.name));
    EXPECT_EQ(studies::condition_names().at(i), c.name);
  }
  EXPECT_EQ(find_condition("loads_N"), nullptr);
  EXPECT_EQ(condition_info(ConditionId::hold_s).range_text(), "[0, 1e7] s");
  EXPECT_EQ(condition_info(ConditionId::horizontal_force_N).range_text(), "[-1e7, 1e7] N");
  EXPECT_EQ(condition_info(ConditionId::pressure_kPa).range_text(), "(0, 2000] kPa");
  EXPECT_EQ(condition_info(ConditionId::branch).range_text(), "load, unload");
  EXPECT_EQ(condition_info(ConditionId::load_N).range_text(), "[1e-6, 1e7] N");
}

// A traction row's slip: no footprint row states it (a footprint is standing or free-rolling).
TEST(ConditionCatalogue, SlipIsRefusedByFootprintMeasurementsAndSweeps) {
  const ConditionInfo& slip = condition_info(ConditionId::slip);
  EXPECT_EQ(slip.range_text(), "[-1, 1]");
  // A footprint row (sinking_mm) with a slip is refused naming the slip; a traction row takes it.
  const fs::path p = scratch("footprint_slip.csv");
  std::ofstream(p) << "sinking_mm,load_N,slip\n15,4000,0.2\n";
  std::string why;
  try {
    studies::read_measurements(p.string(), table3_tyre());
  } catch (const InputError& e) {
    why = e.what();
  }
  fs::remove(p);
  EXPECT_NE(why.find("slip"), std::string::npos) << why;
  EXPECT_EQ(measured(slip, "0.2"), "");
  EXPECT_NE(swept(slip, "0.2").find(footprint_refusal(ConditionId::slip)), std::string::npos)
      << swept(slip, "0.2");
  for (const ConditionInfo& c : condition_catalogue())
    EXPECT_EQ(footprint_refusal(c.id).empty(), c.id != ConditionId::slip) << c.name;
}

TEST(ConditionCatalogue, MeasurementsAndSweepsAcceptTheRangeAndRefuseBeyondWithOneMessage) {
  for (const ConditionInfo& c : condition_catalogue()) {
    if (c.is_text() || !footprint_refusal(c.id).empty()) continue;
    SCOPED_TRACE(c.name);
    const std::string max = number_text(c.max);
    double read = 0;
    EXPECT_EQ(measured(c, max, &read), "");
    EXPECT_EQ(read, c.max);
    EXPECT_EQ(swept(c, max), "");
    // Just beyond either end: refused by both with the catalogue's words.
    const double step = 1e-6 * std::max(1.0, std::abs(c.min));
    for (const double beyond : {c.max * (1 + 1e-9), c.min_open ? c.min : c.min - step}) {
      const std::string text = number_text(beyond);
      const std::string why = c.refusal(text);
      EXPECT_NE(measured(c, text).find(why), std::string::npos) << measured(c, text);
      EXPECT_NE(swept(c, text).find(why), std::string::npos) << swept(c, text);
    }
  }
}

TEST(ConditionCatalogue, EveryWordIsReadAsItsValueAndOtherWordsAreRefused) {
  for (const ConditionInfo& c : condition_catalogue()) {
    if (!c.is_text()) continue;
    for (std::size_t v = 0; v < c.words.size(); ++v) {
      for (const std::string& word : c.words[v]) {
        double read = -1;
        EXPECT_EQ(measured(c, word, &read), "") << word;
        EXPECT_EQ(read, static_cast<double>(v)) << word;
        EXPECT_EQ(swept(c, word), "") << word;
      }
    }
    const std::string why = c.refusal("sand");
    EXPECT_NE(why.find("'sand' is not one of: " + c.range_text()), std::string::npos) << why;
    EXPECT_NE(measured(c, "sand").find(why), std::string::npos);
    EXPECT_NE(swept(c, "sand").find(why), std::string::npos);
  }
  EXPECT_EQ(contact::branch_named("unloading"), contact::Branch::unloading);
  EXPECT_EQ(std::string(contact::branch_name(contact::Branch::unloading)), "unload");
  EXPECT_EQ(contact::surface_named("soil"), contact::Surface::soil);
}

TEST(ConditionCatalogue, TheStaticLoopReadsTheBranchWordsOfTheCatalogue) {
  const fs::path p = scratch("loop.csv");
  std::ofstream(p) << "load_N,deflection_mm,branch\n1000,10,load\n2000,20,loading\n"
                   << "1500,18,unload\n500,8,unloading\n";
  const rheology::StaticLoop loop = rheology::read_static_loop_csv(p.string());
  fs::remove(p);
  ASSERT_EQ(loop.rows.size(), 4u);
  EXPECT_TRUE(loop.rows[0].loading);
  EXPECT_TRUE(loop.rows[1].loading);
  EXPECT_FALSE(loop.rows[2].loading);
  EXPECT_FALSE(loop.rows[3].loading);
}

}  // namespace

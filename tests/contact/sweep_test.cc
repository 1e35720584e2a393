// The sweep engine: sweep-file parsing and its errors (file, line, key), grid expansion order,
// model sharing, rows equal to individual footprint solves, thread-count independence of the
// CSV, failed cases as rows, every shipped sweep file, and the progress bar's frames.
#include "modaltyre/contact/sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "modaltyre/core/progress.h"

namespace {

using namespace modaltyre::contact;
using modaltyre::InputError;
using modaltyre::ProgressBar;
namespace fs = std::filesystem;

const std::string kSource = MODALTYRE_SOURCE_DIR;
const std::string kConfig = kSource + "/configs/sf350.yaml";
// A sweep "file" placed (by name only) in configs/sweeps, so that base: ../sf350.yaml resolves.
const std::string kSweepName = kSource + "/configs/sweeps/in_memory_test.yaml";

SweepSpec spec_of(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  return parse_sweep_spec(yaml, kSweepName, overrides);
}

// Runs `fn`, expecting an InputError at the sweep file's `line` that names `key`.
template <typename Fn>
void expect_input_error(Fn fn, int line, const std::string& key, const std::string& file = kSweepName) {
  try {
    fn();
    ADD_FAILURE() << "expected an InputError for key " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, file) << e.what();
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(e.where().key.find(key), std::string::npos) << e.what();
  }
}

TEST(Sweep, GridExpandsInWrittenOrderWithTheLastKeyFastest) {
  const auto plan = plan_sweep(spec_of(
      "base: ../sf350.yaml\n"
      "grid:\n"
      "  tread.modulus_MPa: [5, 7]\n"
      "  load_N: [2000, 4000, 6000]\n"
      "output: x.csv\n"));
  ASSERT_EQ(plan.cases.size(), 6u);
  ASSERT_EQ(plan.models.size(), 2u);  // one model per modulus, shared by its three loads
  EXPECT_EQ(plan.columns, (std::vector<std::string>{"tread.modulus_MPa", "load_N"}));
  const double loads[] = {2000, 4000, 6000};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(plan.cases[i].value_index, (std::vector<std::size_t>{i / 3, i % 3}));
    EXPECT_EQ(plan.cases[i].model, i / 3);
    EXPECT_EQ(plan.cases[i].load.load_N, loads[i % 3]);
  }
  EXPECT_DOUBLE_EQ(plan.models[0].tread.modulus_Pa, 5e6);
  EXPECT_DOUBLE_EQ(plan.models[1].tread.modulus_Pa, 7e6);
  EXPECT_EQ(plan.cells(4), (std::vector<std::string>{"7", "4000"}));

  // Swapping the keys swaps the order: the modulus now varies fastest.
  const auto swapped = plan_sweep(spec_of(
      "base: ../sf350.yaml\n"
      "grid:\n"
      "  load_N: [2000, 4000, 6000]\n"
      "  tread.modulus_MPa: [5, 7]\n"
      "output: x.csv\n"));
  ASSERT_EQ(swapped.cases.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(swapped.cases[i].model, i % 2);
    EXPECT_EQ(swapped.cases[i].load.load_N, loads[i / 2]);
  }
}

TEST(Sweep, SetAppliesToEveryCaseAndLoadFromSetBecomesAColumn) {
  const auto plan = plan_sweep(spec_of(
      "base: ../sf350.yaml\n"
      "set:\n"
      "  tread:\n"
      "    thickness_mm: 10\n"
      "  load_N: 5000\n"
      "  horizontal_force_N: 300\n"
      "grid:\n"
      "  modal.compliance_scale: [0.8, 1.2]\n"
      "output: x.csv\n",
      {"tread.modulus_MPa=7"}));
  ASSERT_EQ(plan.cases.size(), 2u);
  EXPECT_EQ(plan.columns, (std::vector<std::string>{"load_N", "modal.compliance_scale"}));
  for (const auto& m : plan.models) {
    EXPECT_DOUBLE_EQ(m.tread.thickness_m, 0.010);
    EXPECT_DOUBLE_EQ(m.tread.modulus_Pa, 7e6);  // from the command-line overrides
  }
  EXPECT_DOUBLE_EQ(plan.models[1].compliance_scale, 1.2);
  for (const auto& c : plan.cases) {
    EXPECT_EQ(c.load.load_N, 5000);
    EXPECT_EQ(c.load.horizontal_force_N, 300);
  }
  EXPECT_EQ(plan.cells(1), (std::vector<std::string>{"5000", "1.2"}));
}

TEST(Sweep, RowsEqualIndividualFootprintSolves) {
  const auto plan = plan_sweep(spec_of(
      "base: ../sf350.yaml\n"
      "grid:\n"
      "  tread.modulus_MPa: [5, 7]\n"
      "  horizontal_force_N: [0, 600]\n"
      "  load_N: [2131, 5478, 8321]\n"
      "output: x.csv\n"));
  SweepOptions cold;
  cold.threads = 2;
  cold.warm_start = false;
  SweepOptions warm = cold;
  warm.warm_start = true;
  const auto rc = run_sweep(plan, cold);
  const auto rw = run_sweep(plan, warm);
  ASSERT_EQ(rc.rows.size(), 12u);
  ASSERT_EQ(rc.failed, 0u);
  ASSERT_EQ(rw.failed, 0u);
  for (std::size_t mi = 0; mi < 2; ++mi) {
    const TyreModel model =
        build_tyre_model(load_tyre_config(kConfig, {mi == 0 ? "tread.modulus_MPa=5" : "tread.modulus_MPa=7"}));
    for (std::size_t i = 6 * mi; i < 6 * mi + 6; ++i) {
      const auto ref = solve_footprint(model, plan.cases[i].load);
      ASSERT_TRUE(ref.converged);
      double peak = 0;
      for (const auto& u : ref.units) peak = std::max(peak, u.pressure_Pa);
      // Cold starts follow the very same path as solve_footprint: bit for bit.
      const SweepRow& c = rc.rows[i];
      EXPECT_TRUE(c.ok);
      EXPECT_EQ(c.sinking_mm, ref.sinking_m * 1e3);
      EXPECT_EQ(c.length_mm, ref.contact_length_m * 1e3);
      EXPECT_EQ(c.vertical_stiffness_N_mm, ref.load.load_N / (ref.sinking_m * 1e3));
      EXPECT_EQ(c.peak_pressure_kPa, peak * 1e-3);
      EXPECT_EQ(c.iterations, ref.iterations);
      // A warm start reaches the same contact set (the solution is unique): same values.
      const SweepRow& w = rw.rows[i];
      EXPECT_NEAR(w.sinking_mm, c.sinking_mm, 1e-9 * c.sinking_mm);
      EXPECT_NEAR(w.length_mm, c.length_mm, 1e-9 * c.length_mm);
      EXPECT_NEAR(w.peak_pressure_kPa, c.peak_pressure_kPa, 1e-9 * c.peak_pressure_kPa);
      EXPECT_LE(w.iterations, c.iterations + 2);
    }
  }
}

TEST(Sweep, CsvIsByteIdenticalForOneAndTwoThreads) {
  const auto plan = plan_sweep(spec_of(
      "base: ../sf350.yaml\n"
      "grid:\n"
      "  tread.modulus_MPa: [4, 6, 9]\n"
      "  load_N: [1500, 2500, 3500, 4500, 5500, 6500, 7500]\n"
      "output: x.csv\n"));
  std::atomic<std::size_t> ticks{0};
  SweepOptions one;
  one.threads = 1;
  one.progress = [&](std::size_t n) { ticks += n; };
  SweepOptions two = one;
  two.threads = 2;
  const std::string a = sweep_csv(plan, run_sweep(plan, one));
  const std::string b = sweep_csv(plan, run_sweep(plan, two));
  EXPECT_EQ(a, b);
  EXPECT_EQ(ticks.load(), 2 * plan.cases.size());
  // Warm starts from a fixed per-model reference are just as independent of the thread count.
  one.warm_start = two.warm_start = true;
  EXPECT_EQ(sweep_csv(plan, run_sweep(plan, one)), sweep_csv(plan, run_sweep(plan, two)));
  EXPECT_EQ(a.substr(0, a.find('\n')),
            "tread.modulus_MPa,load_N,sinking_mm,length_mm,vertical_stiffness_N_mm,"
            "peak_pressure_kPa,iterations,status,message");
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 22);
}

TEST(Sweep, AFailedCaseIsARowWithItsReason) {
  const auto plan = plan_sweep(spec_of(
      "base: ../sf350.yaml\n"
      "grid:\n"
      "  solver.max_iterations: [1, 200]\n"
      "  load_N: [3000, 6000]\n"
      "output: x.csv\n"));
  SweepOptions opt;
  opt.threads = 2;
  opt.warm_start = false;
  const auto res = run_sweep(plan, opt);
  ASSERT_EQ(res.rows.size(), 4u);
  EXPECT_EQ(res.failed, 2u);
  EXPECT_FALSE(res.rows[0].ok);
  EXPECT_FALSE(res.rows[1].ok);
  EXPECT_NE(res.rows[0].message.find("did not settle"), std::string::npos) << res.rows[0].message;
  EXPECT_TRUE(res.rows[2].ok);
  EXPECT_TRUE(res.rows[3].ok);
  const std::string csv = sweep_csv(plan, res);
  EXPECT_NE(csv.find("\n1,3000,,,,,,failed,active set did not settle"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n200,6000,"), std::string::npos);
}

TEST(Sweep, BadSweepFilesNameFileLineAndKey) {
  // Unknown top-level key.
  expect_input_error([] { spec_of("base: ../sf350.yaml\ngrids:\n  load_N: [1]\n"); }, 2, "grids");
  // Missing base, and a base that does not exist.
  expect_input_error([] { spec_of("grid:\n  load_N: [1000]\noutput: x.csv\n"); }, 1, "base");
  expect_input_error([] { spec_of("base: nowhere.yaml\ngrid:\n  load_N: [1000]\n"); }, 1, "base");
  // Empty list, and a scalar where a list belongs.
  expect_input_error([] { spec_of("base: ../sf350.yaml\ngrid:\n  load_N: [1000]\n  tread.modulus_MPa: []\n"); },
                     4, "tread.modulus_MPa");
  expect_input_error([] { spec_of("base: ../sf350.yaml\ngrid:\n  load_N: 1000\n"); }, 3, "load_N");
  // A non-positive load, on the line of the item.
  expect_input_error([] { spec_of("base: ../sf350.yaml\ngrid:\n  load_N:\n    - 1000\n    - -5\n"); }, 5,
                     "load_N");
  // A key that is set and swept.
  expect_input_error(
      [] { spec_of("base: ../sf350.yaml\nset:\n  tread.modulus_MPa: 5\ngrid:\n  tread.modulus_MPa: [6]\n  load_N: [1000]\n"); },
      3, "tread.modulus_MPa");
  // No load anywhere.
  expect_input_error([] { plan_sweep(spec_of("base: ../sf350.yaml\ngrid:\n  tread.modulus_MPa: [6]\n")); }, 3,
                     "load_N");
  // A grid key that is not a config key, and a value the config rejects: found while planning.
  expect_input_error(
      [] { plan_sweep(spec_of("base: ../sf350.yaml\ngrid:\n  load_N: [1000]\n  tread.modulus_mpa: [6, 7]\n")); },
      4, "tread.modulus_mpa");
  expect_input_error(
      [] {
        plan_sweep(spec_of("base: ../sf350.yaml\ngrid:\n  load_N: [1000]\n  tread.modulus_MPa:\n    - 6\n    - -1\n"));
      },
      6, "tread.modulus_MPa");
  expect_input_error([] { plan_sweep(spec_of("base: ../sf350.yaml\nset:\n  solver.max_iter: 5\ngrid:\n  load_N: [1]\n")); },
                     3, "solver.max_iter");
  // Command-line overrides are named as such.
  expect_input_error(
      [] { plan_sweep(spec_of("base: ../sf350.yaml\ngrid:\n  load_N: [1000]\n", {"tread.bogus=1"})); }, 0,
      "tread.bogus", "--set");
}

TEST(Sweep, EveryShippedSweepFileParsesAndPlans) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kSource + "/configs/sweeps")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    const auto spec = read_sweep_spec(entry.path().string());
    EXPECT_FALSE(spec.output.empty());
    const auto plan = plan_sweep(spec);
    EXPECT_GT(plan.cases.size(), 0u);
    EXPECT_GT(plan.models.size(), 0u);
  }
  EXPECT_GE(files, 2);
  const auto t3 = plan_sweep(read_sweep_spec(kSource + "/configs/sweeps/table3_loads.yaml"));
  EXPECT_EQ(t3.cases.size(), 6u);
  EXPECT_EQ(t3.models.size(), 1u);
}

TEST(Sweep, CsvFieldsAreQuotedWhenNeeded) {
  EXPECT_EQ(csv_field("plain text"), "plain text");
  EXPECT_EQ(csv_field("a, b"), "\"a, b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "two lines");
  EXPECT_EQ(sweep_number(0.1), "0.1");
  EXPECT_EQ(sweep_number(1.0 / 3.0), "0.3333333333");
}

TEST(SweepProgress, FramesShowCountRateAndTimeLeft) {
  const std::string f = ProgressBar::render("sweep", 250, 1000, 2.0, 20);
  EXPECT_EQ(f, "sweep [#####---------------]  25% 250/1000  125.0/s  left 6.0 s");
  EXPECT_NE(ProgressBar::render("", 1000, 1000, 4.0, 10).find("took 4.0 s"), std::string::npos);
  EXPECT_EQ(ProgressBar::format_duration(185), "3 min 05 s");
  // Quiet when the stream is not a terminal; tick is safe from many threads.
  std::FILE* f_null = std::fopen("/dev/null", "w");
  ASSERT_NE(f_null, nullptr);
  {
    ProgressBar bar(4000, "x", ProgressBar::Mode::automatic, f_null);
    EXPECT_FALSE(bar.enabled());
#pragma omp parallel for num_threads(2)
    for (int i = 0; i < 4000; ++i) bar.tick();
    EXPECT_EQ(bar.done(), 4000u);
  }
  {
    ProgressBar bar(100, "x", ProgressBar::Mode::always, f_null, std::chrono::milliseconds(0));
    EXPECT_TRUE(bar.enabled());
#pragma omp parallel for num_threads(2)
    for (int i = 0; i < 100; ++i) bar.tick();
    bar.finish();
    EXPECT_EQ(bar.done(), 100u);
  }
  std::fclose(f_null);
}

}  // namespace

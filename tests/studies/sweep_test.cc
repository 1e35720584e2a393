// The sweep engine: sweep-file parsing and its errors (file, line, key), grid expansion order,
// model sharing, rows equal to individual footprint solves, thread-count independence of the
// CSV, failed cases as rows, every shipped sweep file, and the progress bar's frames.
#include "modaltyre/studies/sweep.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/progress.h"
#include "modaltyre/studies/measurements.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::studies;
using modaltyre::InputError;
using modaltyre::ProgressBar;
namespace fs = std::filesystem;

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;
using modaltyre_test::kSweepName;
// A sweep "file" placed (by name only) in configs/sweeps, so that base: ../sf350_2d_table3.yaml
// resolves.

SweepSpec spec_of(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  return parse_sweep_spec(yaml, kSweepName, overrides);
}

// Runs `fn`, expecting an InputError at the sweep file's `line` that names `key`.
template <typename Fn>
void expect_input_error(Fn fn, int line, const std::string& key,
                        const std::string& file = kSweepName) {
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
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
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
  const auto swapped =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
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

TEST(Sweep, SetAppliesToEveryCaseAndItsConditionsBecomeColumns) {
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
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
  // Every condition given is a column (so that the CSV states what each row was computed at),
  // set: ones first in the order written, then the grid keys.
  EXPECT_EQ(plan.columns,
            (std::vector<std::string>{"load_N", "horizontal_force_N", "modal.compliance_scale"}));
  for (const auto& m : plan.models) {
    EXPECT_DOUBLE_EQ(m.tread.thickness_m, 0.010);
    EXPECT_DOUBLE_EQ(m.tread.modulus_Pa, 7e6);  // from the command-line overrides
  }
  EXPECT_DOUBLE_EQ(plan.models[1].compliance_scale, 1.2);
  for (const auto& c : plan.cases) {
    EXPECT_EQ(c.load.load_N, 5000);
    EXPECT_EQ(c.load.horizontal_force_N, 300);
  }
  EXPECT_EQ(plan.cells(1), (std::vector<std::string>{"5000", "300", "1.2"}));
}

TEST(Sweep, RowsEqualIndividualFootprintSolves) {
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
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
    const TyreModel model = build_tyre_model(
        load_tyre_config(kConfig2d, {mi == 0 ? "tread.modulus_MPa=5" : "tread.modulus_MPa=7"}));
    for (std::size_t i = 6 * mi; i < 6 * mi + 6; ++i) {
      const auto ref = solve_footprint(model, plan.cases[i].load);
      ASSERT_TRUE(ref.ok());
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
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
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
            "tread.modulus_MPa,load_N,sinking_mm,length_mm,width_mm,rolling_resistance_N,"
            "vertical_stiffness_N_mm,peak_pressure_kPa,iterations,status,message,valid");
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 22);
}

TEST(Sweep, AFailedCaseIsARowWithItsReason) {
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
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
  EXPECT_NE(csv.find("\n1,3000,,,,,,,,failed,active set did not settle"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n200,6000,"), std::string::npos);
}

// Issue 16 item 6: a case outside the model's validity range is an ok row (the solver
// converges) marked valid = false with the reason as its message; the CSV still reads back as
// measured data (the column is ignored there).
TEST(Sweep, ACaseOutsideTheValidityRangeIsMarked) {
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
                         "set:\n"
                         "  contact.unit_length_mm: 2\n"
                         "grid:\n"
                         "  load_N: [5000, 30000]\n"
                         "output: x.csv\n"));
  const auto res = run_sweep(plan, {});
  ASSERT_EQ(res.rows.size(), 2u);
  EXPECT_EQ(res.failed, 0u);
  EXPECT_EQ(res.invalid, 1u);
  EXPECT_TRUE(res.rows[0].valid);
  EXPECT_FALSE(res.rows[1].valid);
  EXPECT_EQ(res.rows[1].message.rfind("outside the validity range: sinking", 0), 0u)
      << res.rows[1].message;
  const std::string csv = sweep_csv(plan, res);
  EXPECT_NE(csv.find(",ok,converged in"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",true\n30000,"), std::string::npos) << csv;
  EXPECT_EQ(csv.substr(csv.size() - 7), ",false\n") << csv;
  const fs::path path =
      fs::temp_directory_path() / ("modaltyre_valid_" + std::to_string(getpid()) + ".csv");
  std::ofstream(path) << csv;
  const auto back = read_measurements(path.string(), load_tyre_config(kConfig2d));
  fs::remove(path);
  ASSERT_EQ(back.rows.size(), 2u);
  EXPECT_EQ(back.rows[1].conditions.load_N, 30000);
}

// Distributed sweeps (MPI) run each rank's share with only_cases; rank 0 puts the rows back in
// plan order. Shares must partition the plan, be balanced, touch few models, and give the rows
// of the whole run, warm starts included (the reference case comes from the whole model).
TEST(SweepShare, SharesPartitionThePlanAndReassembleToTheSingleProcessCsv) {
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
                         "grid:\n"
                         "  load_N: [1500, 3000, 4500, 6000, 7500]\n"
                         "  tread.modulus_MPa: [4, 6, 9]\n"
                         "output: x.csv\n"));
  ASSERT_EQ(plan.models.size(), 3u);
  for (bool warm : {false, true}) {
    SweepOptions whole;
    whole.threads = 1;
    whole.warm_start = warm;
    const SweepResult all = run_sweep(plan, whole);
    for (int ranks : {1, 2, 4, 7, 20}) {
      std::vector<int> owner(plan.cases.size(), -1);
      std::vector<std::string> line(plan.cases.size());
      for (int r = 0; r < ranks; ++r) {
        const auto share = sweep_share(plan, r, ranks);
        EXPECT_TRUE(std::is_sorted(share.begin(), share.end()));
        // Balanced: 15 cases over `ranks` chunks differ by at most one.
        EXPECT_LE(share.size(), (plan.cases.size() + ranks - 1) / ranks);
        EXPECT_GE(share.size(), plan.cases.size() / ranks);
        // Contiguous in model order: a share of 5 cases or fewer touches at most two models.
        std::vector<std::size_t> models;
        for (auto i : share) models.push_back(plan.cases[i].model);
        std::sort(models.begin(), models.end());
        models.erase(std::unique(models.begin(), models.end()), models.end());
        if (share.size() <= 5) {
          EXPECT_LE(models.size(), 2u);
        }

        SweepOptions part = whole;
        part.only_cases = share;
        const SweepResult mine = run_sweep(plan, part);
        EXPECT_EQ(mine.failed, 0u);
        for (auto i : share) {
          EXPECT_EQ(owner[i], -1) << "case " << i << " in two shares";
          owner[i] = r;
          line[i] = sweep_csv_row(plan, mine.rows[i], i);
        }
      }
      std::string csv = sweep_csv_header(plan);
      for (std::size_t i = 0; i < plan.cases.size(); ++i) {
        EXPECT_NE(owner[i], -1) << "case " << i << " in no share";
        csv += line[i];
      }
      EXPECT_EQ(csv, sweep_csv(plan, all)) << ranks << " ranks, warm start " << warm;
    }
  }
}

std::string full_precision(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// Observable `column` of every row of a sweep, in plan order (all rows must have succeeded).
std::vector<double> column_of(const SweepResult& r, double SweepRow::*column) {
  std::vector<double> out;
  for (const auto& row : r.rows) {
    EXPECT_TRUE(row.ok) << row.message;
    out.push_back(row.*column);
  }
  return out;
}

TEST(SweepConditions, ConditionsAreColumnsAndTakeTheBaseConfigsValuesWhenNotGiven) {
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
                         "set:\n"
                         "  surface: soil\n"
                         "  speed_kmh: 30\n"
                         "grid:\n"
                         "  branch: [load, unload]\n"
                         "  pressure_kPa: [200, 260]\n"
                         "  load_N: [3000]\n"
                         "output: x.csv\n"));
  EXPECT_EQ(plan.columns,
            (std::vector<std::string>{"surface", "speed_kmh", "branch", "pressure_kPa", "load_N"}));
  ASSERT_EQ(plan.cases.size(), 4u);
  EXPECT_EQ(plan.models.size(), 1u);  // conditions do not make models
  const OperatingConditions& c = plan.cases[3].conditions;
  EXPECT_EQ(c.branch, Branch::unloading);
  EXPECT_EQ(c.surface, Surface::soil);
  EXPECT_EQ(c.pressure_kPa, 260);
  EXPECT_EQ(c.speed_kmh, 30);
  EXPECT_EQ(c.load_N, 3000);
  EXPECT_EQ(c.hold_s, 0);              // not given: the base config's (no hold)
  EXPECT_EQ(c.horizontal_force_N, 0);  // the base config's horizontal_force_N
  EXPECT_EQ(plan.cells(3), (std::vector<std::string>{"soil", "30", "unload", "260", "3000"}));
  // Without pressure_kPa the case takes the config's inflation pressure.
  const auto plain =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [3000]\n  "
                         "tyre.inflation_pressure_kPa: [180]\n"));
  EXPECT_EQ(plain.cases[0].conditions.pressure_kPa, 180);
}

TEST(SweepEffects, NoEffectAndDefaultConditionsGiveTheEffectFreeFootprints) {
  // A hold or a branch acts only through effects: with none on, they change nothing, and the
  // rows are the effect-free footprints. (A pressure other than the config's acts always, by
  // the ring's pressure terms: tests/contact/carcass_source_test.cc.)
  const auto with_conditions =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
                         "set:\n  hold_s: 120\n  branch: unload\n"
                         "grid:\n  pressure_kPa: [230, 230]\n  load_N: [2131, 8321]\n"));
  const auto plain =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [2131, 8321]\n"));
  SweepOptions opt;
  opt.threads = 2;
  const auto rc = run_sweep(with_conditions, opt);
  const auto rp = run_sweep(plain, opt);
  for (std::size_t i = 0; i < rc.rows.size(); ++i) {
    EXPECT_EQ(rc.rows[i].sinking_mm, rp.rows[i % 2].sinking_mm);
    EXPECT_EQ(rc.rows[i].length_mm, rp.rows[i % 2].length_mm);
    EXPECT_DOUBLE_EQ(rc.rows[i].width_mm, 130);  // the config's contact width
    EXPECT_EQ(rc.rows[i].rolling_resistance_N, 0);
  }
}

TEST(SweepEffects, InflationPressureStiffensTheCarcassAndIsNeutralAtTheModalTestPressure) {
  const auto on =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
                         "set:\n  effects.inflation_pressure.enabled: true\n"
                         "grid:\n  pressure_kPa: [180, 230, 280]\n  load_N: [4000]\n"));
  const auto off = plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [4000]\n"));
  SweepOptions opt;
  opt.threads = 2;
  const auto s = column_of(run_sweep(on, opt), &SweepRow::sinking_mm);
  const double s_off = column_of(run_sweep(off, opt), &SweepRow::sinking_mm).at(0);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_GT(s[0], s[1]);  // a softer tyre at lower pressure
  EXPECT_GT(s[1], s[2]);
  // At the hammer test's pressure (230 kPa) the factor is 1: the effect-free footprint, up to
  // the rounding of a differently assembled (same) operator.
  EXPECT_NEAR(s[1], s_off, 1e-9 * s_off);
}

TEST(SweepEffects, TreadRelaxationCreepsMonotonicallyToTheRelaxedTread) {
  // Kelvin-Voigt creep of the tread under a held load: sinking grows with the hold time,
  // ever more slowly, towards the tread of compliance x (1 + creep_ratio) (defaults 0.5, 30 s).
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
                         "set:\n  effects.tread_relaxation.enabled: true\n  load_N: 4000\n"
                         "grid:\n  hold_s: [0, 15, 30, 45, 60, 120, 10000]\n"));
  SweepOptions opt;
  opt.threads = 2;
  const auto s = column_of(run_sweep(plan, opt), &SweepRow::sinking_mm);
  ASSERT_EQ(s.size(), 7u);
  for (std::size_t i = 1; i < s.size(); ++i) EXPECT_GT(s[i], s[i - 1]) << "hold " << i;
  for (std::size_t i = 2; i < 5; ++i) {
    EXPECT_LT(s[i] - s[i - 1], s[i - 1] - s[i - 2]) << "creep must slow down (equal 15 s steps)";
  }
  // hold 0: the instantaneous tread, i.e. the effect-free footprint.
  const auto off = run_sweep(
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [4000]\n")), opt);
  EXPECT_NEAR(s[0], off.rows.at(0).sinking_mm, 1e-9 * s[0]);
  // Fully relaxed (exp(-10000 / 30) = 0): a tread 1.5 times softer, tread.modulus_MPa / 1.5.
  const double modulus_MPa = load_tyre_config(kConfig2d).tread.modulus_Pa * 1e-6;
  const auto relaxed =
      run_sweep(plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [4000]\n",
                                   {"tread.modulus_MPa=" + full_precision(modulus_MPa / 1.5)})),
                opt);
  EXPECT_NEAR(s.back(), relaxed.rows.at(0).sinking_mm, 1e-6 * s.back());
}

TEST(SweepEffects, CsvIsByteIdenticalForOneAndTwoThreadsWithAnEffectOn) {
  const auto plan = plan_sweep(spec_of(
      "base: ../sf350_2d_table3.yaml\n"
      "set:\n  effects.dry_friction.enabled: true\n  effects.tread_relaxation.enabled: true\n"
      "grid:\n  tread.modulus_MPa: [2, 3]\n  branch: [load, unload]\n  hold_s: [0, 60]\n"
      "  load_N: [150, 3000, 6000]\n"));
  SweepOptions one;
  one.threads = 1;
  SweepOptions two = one;
  two.threads = 2;
  const auto r1 = run_sweep(plan, one);
  const std::string a = sweep_csv(plan, r1);
  EXPECT_EQ(a, sweep_csv(plan, run_sweep(plan, two)));
  one.warm_start = two.warm_start = true;
  EXPECT_EQ(sweep_csv(plan, run_sweep(plan, one)), sweep_csv(plan, run_sweep(plan, two)));
  // 150 N does not overcome the 200 N friction on the loading branch: a failed row with the
  // reason; on the unloading branch the elastic tyre carries 350 N and the case succeeds.
  EXPECT_EQ(r1.failed, 4u);
  EXPECT_NE(a.find("\n2,load,0,150,,,,,,,,failed,load 150 N does not exceed"), std::string::npos)
      << a;
  EXPECT_NE(a.find("\n2,unload,0,150,"), std::string::npos) << a;
}

TEST(SweepEffects, CsvReadsBackAsMeasuredDataThatThePredictorReproduces) {
  // The discrepancy workflow's data path: a sweep with an effect on writes a CSV that
  // read_measurements() reads unchanged, with every row's conditions, and predicting those rows
  // with the same effect reproduces the written values (to their 10 digits).
  const auto plan =
      plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\n"
                         "set:\n  effects.inflation_pressure.enabled: true\n"
                         "  effects.tread_relaxation.enabled: true\n  hold_s: 45\n"
                         "grid:\n  tread.modulus_MPa: [2.329, 3]\n  surface: [rigid, soil]\n"
                         "  pressure_kPa: [200, 260]\n  load_N: [3000, 6000]\n"));
  SweepOptions opt;
  opt.threads = 2;
  const auto res = run_sweep(plan, opt);
  ASSERT_EQ(res.failed, 0u);
  const fs::path csv =
      fs::temp_directory_path() / ("sweep_roundtrip_" + std::to_string(::getpid()) + ".csv");
  { std::ofstream(csv, std::ios::binary) << sweep_csv(plan, res); }
  const TyreConfig base = load_tyre_config(kConfig2d);
  const MeasurementSet set = read_measurements(csv.string(), base);
  fs::remove(csv);
  ASSERT_EQ(set.rows.size(), plan.cases.size());
  EXPECT_EQ(set.observables, observable_names());
  EXPECT_EQ(set.conditions,
            (std::vector<std::string>{"load_N", "pressure_kPa", "hold_s", "surface"}));
  auto as_written = [](double v) { return std::stod(sweep_number(v)); };
  for (std::size_t i = 0; i < plan.cases.size(); ++i) {
    SCOPED_TRACE(i);
    const OperatingConditions& want = plan.cases[i].conditions;
    const OperatingConditions& got = set.rows[i].conditions;
    EXPECT_EQ(got.load_N, want.load_N);
    EXPECT_EQ(got.pressure_kPa, want.pressure_kPa);
    EXPECT_EQ(got.hold_s, 45);
    EXPECT_EQ(got.surface, want.surface);
    EXPECT_EQ(got.branch, Branch::loading);
    const SweepRow& r = res.rows[i];
    EXPECT_EQ(set.rows[i].observed.at("sinking_mm"), as_written(r.sinking_mm));
    EXPECT_EQ(set.rows[i].observed.at("length_mm"), as_written(r.length_mm));
    EXPECT_EQ(set.rows[i].observed.at("width_mm"), as_written(r.width_mm));
    EXPECT_EQ(set.rows[i].observed.at("rolling_resistance_N"), as_written(r.rolling_resistance_N));
  }
  // The effects act: pressure and (effect off here, so rigid = soil) surface as expected.
  EXPECT_GT(res.rows[0].sinking_mm, res.rows[2].sinking_mm);  // 200 kPa sinks more than 260
  EXPECT_EQ(res.rows[0].sinking_mm, res.rows[4].sinking_mm);  // soil_compliance is off
  // Predicting a read row at its conditions with the sweep's model gives the written values.
  const TyreModel model = build_tyre_model(plan.models[1]);
  for (std::size_t i = 8; i < 16; i += 3) {
    const Prediction p = predict(model, parameters_of(plan.models[1]), set.rows[i].conditions);
    ASSERT_TRUE(p.ok()) << p.message;
    EXPECT_NEAR(p.sinking_mm, set.rows[i].observed.at("sinking_mm"), 1e-9 * p.sinking_mm);
    EXPECT_NEAR(p.length_mm, set.rows[i].observed.at("length_mm"), 1e-9 * p.length_mm);
  }
}

TEST(Sweep, BadSweepFilesNameFileLineAndKey) {
  // Unknown top-level key.
  expect_input_error([] { spec_of("base: ../sf350_2d_table3.yaml\ngrids:\n  load_N: [1]\n"); }, 2,
                     "grids");
  // Missing base, and a base that does not exist.
  expect_input_error([] { spec_of("grid:\n  load_N: [1000]\noutput: x.csv\n"); }, 1, "base");
  expect_input_error([] { spec_of("base: nowhere.yaml\ngrid:\n  load_N: [1000]\n"); }, 1, "base");
  // Empty list, and a scalar where a list belongs.
  expect_input_error(
      [] {
        spec_of(
            "base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n  tread.modulus_MPa: []\n");
      },
      4, "tread.modulus_MPa");
  expect_input_error([] { spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: 1000\n"); }, 3,
                     "load_N");
  // A non-positive load, on the line of the item.
  expect_input_error(
      [] { spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N:\n    - 1000\n    - -5\n"); }, 5,
      "load_N");
  // A key that is set and swept.
  expect_input_error(
      [] {
        spec_of(
            "base: ../sf350_2d_table3.yaml\nset:\n  tread.modulus_MPa: 5\ngrid:\n  "
            "tread.modulus_MPa: [6]\n  "
            "load_N: [1000]\n");
      },
      3, "tread.modulus_MPa");
  // No load anywhere.
  expect_input_error(
      [] {
        plan_sweep(spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  tread.modulus_MPa: [6]\n"));
      },
      3, "load_N");
  // A grid key that is not a config key, and a value the config rejects: found while planning.
  expect_input_error(
      [] {
        plan_sweep(
            spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n  tread.modulus_mpa: "
                    "[6, 7]\n"));
      },
      4, "tread.modulus_mpa");
  expect_input_error(
      [] {
        plan_sweep(
            spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n  "
                    "tread.modulus_MPa:\n    - 6\n "
                    "   - -1\n"));
      },
      6, "tread.modulus_MPa");
  expect_input_error(
      [] {
        plan_sweep(spec_of(
            "base: ../sf350_2d_table3.yaml\nset:\n  solver.max_iter: 5\ngrid:\n  load_N: [1]\n"));
      },
      3, "solver.max_iter");
  // Condition values outside their ranges or lists, on the line of the item.
  expect_input_error(
      [] {
        spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n  branch: [load, up]\n");
      },
      4, "grid.branch");
  expect_input_error(
      [] {
        spec_of("base: ../sf350_2d_table3.yaml\nset:\n  surface: sand\ngrid:\n  load_N: [1]\n");
      },
      3, "set.surface");
  expect_input_error(
      [] {
        spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n  pressure_kPa: [2001]\n");
      },
      4, "grid.pressure_kPa");
  expect_input_error(
      [] {
        spec_of(
            "base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n  speed_kmh:\n    - 10\n    - "
            "-1\n");
      },
      6, "grid.speed_kmh");
  expect_input_error(
      [] { spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n  hold_s: [fast]\n"); },
      4, "grid.hold_s");
  expect_input_error(
      [] { spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n", {"branch=down"}); },
      0, "branch", "--set");
  // Command-line overrides are named as such.
  expect_input_error(
      [] {
        plan_sweep(
            spec_of("base: ../sf350_2d_table3.yaml\ngrid:\n  load_N: [1000]\n", {"tread.bogus=1"}));
      },
      0, "tread.bogus", "--set");
}

TEST(Sweep, EveryShippedSweepFileParsesAndPlans) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kSrc + "/configs/sweeps")) {
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
  const auto t3 = plan_sweep(read_sweep_spec(kSrc + "/configs/sweeps/table3_loads.yaml"));
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

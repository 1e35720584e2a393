// What the plots show (issue 16 item 9): each command's figure is checked in the gnuplot script
// it sends, captured by a stand-in `gnuplot` first on the PATH (it answers with an empty SVG).
// Transient panels do not stretch numerical noise into a signal, fit-modes panels are symmetric
// about zero, validate draws width when it is measured, and discover's panels label their %
// axis and leave out an observable the model reproduces exactly.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::quote;

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;
using modaltyre_test::kTable3;

struct Panel {
  std::string title, ylabel;
  bool fixed_y = false;
  double ymin = 0, ymax = 0;
};

class PlotCli : public modaltyre_test::CliFixture {
 protected:
  // Runs the CLI with the stand-in gnuplot; returns the panels of the script it received.
  std::vector<Panel> plot(const std::vector<std::string>& args, CliRun* run_out = nullptr) {
    const fs::path bin = dir_ / "bin", script = dir_ / "script.gp";
    fs::create_directories(bin);
    const fs::path fake = bin / "gnuplot";
    std::ofstream(fake) << "#!/bin/sh\ncat > " << quote(script.string())
                        << "\nprintf '<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>\\n'\n";
    fs::permissions(fake, fs::perms::owner_all);
    std::string cmd = "PATH=" + quote(bin.string()) + ":\"$PATH\" " + quote(MODALTYRE_CLI);
    for (const auto& a : args) cmd += " " + quote(a);
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    cmd += " >" + quote(out.string()) + " 2>" + quote(err.string());
    const int status = std::system(cmd.c_str());
    CliRun r;
    if (status != -1 && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    r.out = modaltyre_test::slurp(out);
    r.err = modaltyre_test::slurp(err);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    if (run_out) *run_out = r;
    std::vector<Panel> panels;
    std::ifstream in(script);
    std::string line;
    auto quoted = [](const std::string& l) {
      const auto a = l.find('\''), b = l.rfind('\'');
      return a == std::string::npos || b <= a ? std::string() : l.substr(a + 1, b - a - 1);
    };
    while (std::getline(in, line)) {
      if (line.rfind("set title ", 0) == 0) {
        panels.emplace_back();
        panels.back().title = quoted(line);
      }
      if (panels.empty()) continue;
      if (line.rfind("set ylabel ", 0) == 0) panels.back().ylabel = quoted(line);
      if (line.rfind("set yrange [", 0) == 0) {
        panels.back().fixed_y = true;
        const auto colon = line.find(':');
        panels.back().ymin = std::stod(line.substr(12, colon - 12));
        panels.back().ymax = std::stod(line.substr(colon + 1));
      }
    }
    return panels;
  }
};

// While the load is held the longitudinal force is 0 up to solver noise (~1e-11 N): not a
// panel of its own (issue 44: a dead panel whose axis zoomed the noise into a signal) but named
// with its value in the first title, which names the tyre and the scenario's load.
TEST_F(PlotCli, TransientConstantsAreNamedNotDrawn) {
  const auto panels = plot({"transient", kConfig2d, "--scenario", "load-hold", "--set",
                            "transient.load_hold.hold_s=1", "--plot", (dir_ / "t.svg").string()});
  ASSERT_EQ(panels.size(), 3u);  // load, sinking, contact length
  for (const Panel& p : panels)
    EXPECT_EQ(p.title.find("longitudinal force:"), std::string::npos) << p.title;
  EXPECT_NE(panels[0].title.find("constant: longitudinal force 0 N"), std::string::npos)
      << panels[0].title;
  EXPECT_NE(panels[0].title.find("load-hold 4000 N"), std::string::npos) << panels[0].title;
  // The load varies (ramp, hold): auto-scaled; a varying panel spans at least 1 % of its scale.
  EXPECT_FALSE(panels[0].fixed_y);
}

// Rolling on the 3D patch at a held load: the load stays constant (named, not drawn), the
// longitudinal force and the contact width vary as the speed ramps up (drawn).
TEST_F(PlotCli, TransientRollingDrawsForceNamesConstantLoad) {
  const auto panels = plot({"transient", kSrc + "/configs/sf350.yaml", "--scenario", "rolling",
                            "--set", "transient.rolling.duration_s=0.6", "--set",
                            "transient.rolling.ramp_s=0.3", "--plot", (dir_ / "r.svg").string()});
  bool fx = false, width = false;
  for (const Panel& p : panels) {
    fx = fx || p.title.ends_with("longitudinal force");
    width = width || p.title.ends_with("contact width");
    EXPECT_FALSE(p.title.ends_with("vertical load")) << p.title;
  }
  EXPECT_TRUE(fx);
  EXPECT_TRUE(width);
  EXPECT_NE(panels[0].title.find("(constant: vertical load 3999 N"), std::string::npos)
      << panels[0].title;
}

TEST_F(PlotCli, FitModesPanelsAreSymmetricAboutZero) {
  const auto panels = plot({"fit-modes", kSrc + "/configs/data/sf350_hammer_12pt.csv", "--plot",
                            (dir_ / "m.svg").string()});
  ASSERT_GE(panels.size(), 3u);
  for (const auto& p : panels) {
    ASSERT_TRUE(p.fixed_y) << p.title;
    EXPECT_GT(p.ymax, 0) << p.title;
    EXPECT_DOUBLE_EQ(p.ymin, -p.ymax) << p.title;
  }
}

TEST_F(PlotCli, ValidateDrawsWidthWhenItIsMeasured) {
  auto panels = plot({"validate", kConfig2d, kTable3, "--plot", (dir_ / "v.svg").string()});
  ASSERT_EQ(panels.size(), 3u);
  EXPECT_EQ(panels[2].title,
            "SF-350 195/60R14 at 230 kPa (2D, Table 3 fitted): contact width "
            "versus load");
  EXPECT_EQ(panels[2].ylabel, "contact width [mm]");
  const std::string no_width = (dir_ / "no_width.csv").string();
  std::ofstream(no_width) << "load_N,sinking_mm,length_mm\n2131,8,86\n5478,20,117\n8321,29,135\n";
  panels = plot({"validate", kConfig2d, no_width, "--set", "validation.calibrate=[]", "--plot",
                 (dir_ / "v2.svg").string()});
  ASSERT_EQ(panels.size(), 2u);
  for (const auto& p : panels) EXPECT_EQ(p.title.find("width"), std::string::npos) << p.title;
}

// The model's curve in validate's plot is drawn at the conditions stated with --set, as the
// rows are predicted (issue 16): held 60 s, the relaxed tread (seed 001 eq. (10)) sinks deeper
// at every load of the curve, and the titles state the condition.
TEST_F(PlotCli, ValidateDrawsTheModelAtTheConditionsStatedWithSet) {
  // The first data block of the script: the model's sinking curve (load kN, sinking mm).
  auto model_curve = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"validate",
                                     kConfig2d,
                                     kTable3,
                                     "--set",
                                     "validation.calibrate=[]",
                                     "--set",
                                     "contact.unit_length_mm=2",
                                     "--set",
                                     "effects.tread_relaxation.enabled=true",
                                     "--plot",
                                     (dir_ / "v.svg").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto panels = plot(args);
    std::ifstream in(dir_ / "script.gp");
    std::string line;
    while (std::getline(in, line) && line != "$d0 << EOD") {
    }
    std::vector<std::pair<double, double>> xy;
    while (std::getline(in, line) && line != "EOD") {
      const auto space = line.find(' ');
      xy.emplace_back(std::stod(line.substr(0, space)), std::stod(line.substr(space + 1)));
    }
    return std::make_pair(panels, xy);
  };
  const auto [base_panels, base] = model_curve({});
  const auto [held_panels, held] = model_curve({"--set", "hold_s=60"});
  ASSERT_EQ(base.size(), 25u);
  ASSERT_EQ(held.size(), base.size());
  for (std::size_t i = 0; i < base.size(); ++i) {
    EXPECT_DOUBLE_EQ(held[i].first, base[i].first);
    EXPECT_GT(held[i].second, base[i].second * 1.01) << "load " << base[i].first << " kN";
  }
  ASSERT_FALSE(held_panels.empty());
  // The title names the tyre (issue 44 item 4) and the stated conditions.
  const std::string tyre = "SF-350 195/60R14 at 230 kPa (2D, Table 3 fitted)";
  EXPECT_EQ(base_panels[0].title, tyre + ": sinking versus load");
  EXPECT_EQ(held_panels[0].title, tyre + ": sinking versus load (hold_s=60)");
}

// discover's panels show relative residuals in %: the title names the observable without a
// unit, and a width equal to the config's on every row (a residual of 0) gets no panel. Its
// candidate table says what its CV column is.
TEST_F(PlotCli, DiscoverPanelsLabelThePercentAxisAndSkipAnAllZeroObservable) {
  const std::string data = (dir_ / "same_width.csv").string();
  std::ofstream(data) << "load_N,sinking_mm,width_mm\n2131,8,130\n3261,12,130\n5478,20,130\n"
                         "6502,23,130\n7322,26,130\n8321,29,130\n";
  CliRun r;
  const auto panels = plot({"discover", kConfig2d, data, "--plot", (dir_ / "d.svg").string()}, &r);
  ASSERT_EQ(panels.size(), 1u);
  EXPECT_EQ(panels[0].title.rfind("sinking: ", 0), 0u) << panels[0].title;
  EXPECT_EQ(panels[0].title.find("[mm]"), std::string::npos) << panels[0].title;
  EXPECT_NE(panels[0].ylabel.find("[%]"), std::string::npos) << panels[0].ylabel;
  EXPECT_NE(r.out.find("CV = cross-validated RMS of the relative residual, pooled over "
                       "sinking_mm and width_mm"),
            std::string::npos)
      << r.out;
}

// Issue 38: plots that hid or invented. Each is checked in the script gnuplot receives.
class HonestPlots : public PlotCli {
 protected:
  std::string script() const { return modaltyre_test::slurp(dir_ / "script.gp"); }

  /// Every "set key" line of the script.
  std::vector<std::string> keys() const {
    std::vector<std::string> out;
    std::istringstream in(script());
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("set key ", 0) == 0) out.push_back(line.substr(8));
    }
    return out;
  }
};

// A legend inside the plot area covered data (validate's width panel, the 2D footprint) or,
// below short panels, ran into the x label (fit-modes): every legend is outside the data.
TEST_F(HonestPlots, LegendsAreOutsideTheData) {
  const auto outside = [&](const std::string& what) {
    const auto k = keys();
    ASSERT_FALSE(k.empty()) << what;
    for (const auto& key : k) {
      EXPECT_TRUE(key == "off" || key.rfind("below", 0) == 0 || key.rfind("outside", 0) == 0)
          << what << ": set key " << key;
    }
  };
  plot({"validate", kSrc + "/configs/sf350.yaml", kTable3, "--plot", (dir_ / "v.svg").string()});
  outside("validate");
  plot({"footprint", kConfig2d, "--plot", (dir_ / "f.svg").string()});
  outside("footprint 2D");
  plot({"footprint", kSrc + "/configs/sf350.yaml", "--load", "2131", "--load", "8321", "--plot",
        (dir_ / "f3.svg").string()});
  outside("footprint 3D");
  plot({"fit-modes", kSrc + "/configs/data/sf350_hammer_12pt.csv", "--plot",
        (dir_ / "m.svg").string()});
  outside("fit-modes");
  for (const auto& key : keys()) EXPECT_NE(key.find("outside right"), std::string::npos) << key;
}

// The 3D footprint's 2.1 kN map is about 100 mm long: gnuplot's default ticks every 10 mm
// collided ("-50-40-30..."). At most four intervals per map.
TEST_F(HonestPlots, FootprintMapTicksDoNotCollide) {
  plot({"footprint", kSrc + "/configs/sf350.yaml", "--load", "2131", "--load", "8321", "--plot",
        (dir_ / "f3.svg").string()});
  std::istringstream in(script());
  std::vector<double> steps;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("set xtics ", 0) == 0 && line != "set xtics autofreq") {
      steps.push_back(std::stod(line.substr(10)));
    }
  }
  ASSERT_EQ(steps.size(), 2u);  // the two maps; the centre-line panel keeps gnuplot's choice
  EXPECT_GE(steps[0], 25.0);    // an 83 mm patch on a map of about 100 mm: 4 intervals at most
  EXPECT_GE(steps[1], 40.0);
}

// discover's residuals at one value of the regime variable belong to rows of other loads: a line
// through them drew a sawtooth. They are points.
TEST_F(HonestPlots, DiscoverResidualsArePointsNotASawtooth) {
  const std::string data = (dir_ / "grid.csv").string();
  std::ofstream(data) << "load_N,hold_s,sinking_mm\n3000,0,11\n6000,0,21\n3000,60,12\n"
                         "6000,60,22.5\n3000,600,12.5\n6000,600,23.5\n";
  plot({"discover", kConfig2d, data, "--plot", (dir_ / "d.svg").string()});
  const std::string s = script();
  EXPECT_EQ(s.find("with linespoints"), std::string::npos) << s.substr(s.find("plot $"));
  EXPECT_NE(s.find("with points"), std::string::npos);
}

// tir compare of another tyre size draws the .tir law scaled to the model's size: the legend
// says how.
TEST_F(HonestPlots, TirCompareSaysTheLawIsScaled) {
  plot({"tir", "compare", kSrc + "/configs/sf350.yaml",
        kSrc + "/tests/data/tir/tyredyn_car205_60R19_mf62.tir", "--plot",
        (dir_ / "t.svg").string()});
  const std::string s = script();
  EXPECT_NE(s.find(".tir law scaled to the model''s size: load/FNOMIN x the model''s FNOMIN"),
            std::string::npos)
      << s.substr(s.find("plot $"));
  EXPECT_NE(s.find("2a/R0 x the model''s R0"), std::string::npos);
}

// The static loop's unloading branch of eq. (14) went to -100 N near h = 0: a tyre cannot pull
// the road, so the fitted curves start at zero load.
TEST_F(HonestPlots, StaticLoopFitStaysAtOrAboveZeroLoad) {
  const std::string rheo = kSrc + "/tests/data/rheology/";
  plot({"identify", "free-vibration", rheo + "free_vibration.csv", "--mass-kg", "350",
        "--section-height-mm", "117", "--static", rheo + "static_loop.csv", "--config", kConfig2d,
        "--plot", (dir_ / "s.svg").string()});
  // The static panel's data blocks: the last two (fitted loading, unloading).
  std::istringstream in(script());
  std::vector<std::vector<double>> blocks;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("$d", 0) == 0) {
      blocks.emplace_back();
      inside = true;
      continue;
    }
    if (line == "EOD") {
      inside = false;
      continue;
    }
    if (inside) blocks.back().push_back(std::stod(line.substr(line.find(' ') + 1)));
  }
  ASSERT_GE(blocks.size(), 4u);
  for (std::size_t b = blocks.size() - 2; b < blocks.size(); ++b) {
    ASSERT_FALSE(blocks[b].empty());
    for (double load : blocks[b]) EXPECT_GE(load, 0.0) << "block " << b;
  }
}

// Issue 44 item 4: a footprint plot's titles name the tyre, the ground and the load(s).
TEST_F(HonestPlots, FootprintTitlesNameTheTyreTheGroundAndTheLoad) {
  auto titles =
      plot({"footprint", kConfig2d, "--load", "3000", "--plot", (dir_ / "f.svg").string()});
  ASSERT_EQ(titles.size(), 1u);
  EXPECT_EQ(titles[0].title,
            "SF-350 195/60R14 at 230 kPa (2D, Table 3 fitted) on the rigid road, 3.00 kN: contact "
            "pressure along the patch");
  titles = plot({"footprint", kSrc + "/configs/sf350.yaml", "--ground",
                 kSrc + "/configs/soils/lete_sand.yaml", "--load", "2000", "--load", "4000",
                 "--plot", (dir_ / "f3.svg").string()});
  ASSERT_EQ(titles.size(), 3u);  // two maps, the centre line
  EXPECT_NE(titles[0].title.find("2.00 kN"), std::string::npos) << titles[0].title;
  const std::string& centre = titles[2].title;
  EXPECT_EQ(centre.rfind("SF-350", 0), 0u) << centre;
  EXPECT_NE(centre.find("on LETE sand (bekker), 2.00-4.00 kN"), std::string::npos) << centre;
}

// Issue 44 item 2: validate --uncertainty draws the model's band at the rows as two lines, its
// 2.5 and 97.5 % points in load order, equal to the JSON's p025 and p975.
TEST_F(HonestPlots, ValidateDrawsTheJsonsBandAsTwoLines) {
  const std::vector<std::string> args = {"validate",      kConfig2d, kTable3,
                                         "--uncertainty", "--set",   "contact.unit_length_mm=2"};
  auto with_plot = args;
  with_plot.insert(with_plot.end(), {"--plot", (dir_ / "v.svg").string()});
  plot(with_plot);
  const std::string gp = script();
  CliRun json_run;
  auto json_args = args;
  json_args.push_back("--json");
  json_run = run(json_args);
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  const auto j = nlohmann::json::parse(json_run.out);
  // The data blocks in order; the sinking panel's series: model, measured (prediction rows),
  // calibration rows, band 2.5 %, band 97.5 %.
  std::vector<std::vector<std::pair<double, double>>> blocks;
  std::istringstream in(gp);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("$d", 0) == 0 && line.find("<< EOD") != std::string::npos) {
      blocks.emplace_back();
      while (std::getline(in, line) && line != "EOD") {
        const auto space = line.find(' ');
        blocks.back().emplace_back(std::stod(line.substr(0, space)),
                                   std::stod(line.substr(space + 1)));
      }
    }
  }
  ASSERT_NE(gp.find("model band, 2.5 % (at the rows)"), std::string::npos);
  ASSERT_NE(gp.find("model band, 97.5 % (at the rows)"), std::string::npos);
  ASSERT_GE(blocks.size(), 5u);
  const auto& lo = blocks[3];
  const auto& hi = blocks[4];
  ASSERT_EQ(lo.size(), j["rows"].size());
  for (std::size_t i = 0; i < lo.size(); ++i) {
    const auto& b = j["rows"][i]["uncertainty"]["sinking_mm"];  // Table 3's rows rise in load
    EXPECT_NEAR(lo[i].second, b["p025"].get<double>(), 1e-5 * b["p025"].get<double>());
    EXPECT_NEAR(hi[i].second, b["p975"].get<double>(), 1e-5 * b["p975"].get<double>());
    if (i) {
      EXPECT_GT(lo[i].first, lo[i - 1].first) << "in load order";
    }
  }
}

// Issue 48 item 7 and issue 44 item 4: the soil plots a soil-bin engineer reads.
class SoilPlots : public HonestPlots {
 protected:
  /// The script's plot line for the panel whose title holds `title`.
  std::string plot_line_after(const std::string& title) const {
    const std::string s = script();
    const auto t = s.find(title);
    if (t == std::string::npos) return "";
    const auto p = s.find("\nplot ", t);
    return p == std::string::npos ? "" : s.substr(p + 1, s.find('\n', p + 1) - p - 1);
  }
};

TEST_F(SoilPlots, TractionNamesTyreSoilAndLoadAndMarksTheTowedAndSelfPropelledPoints) {
  const auto panels =
      plot({"traction", kConfig2d, "--ground", kSrc + "/configs/soils/lete_sand.yaml", "--load",
            "3000", "--slip", "-0.1", "0", "0.1", "0.3", "--set", "contact.unit_length_mm=2",
            "--plot", (dir_ / "dp.svg").string()});
  ASSERT_EQ(panels.size(), 3u);
  EXPECT_NE(panels[0].title.find("SF-350"), std::string::npos) << panels[0].title;
  EXPECT_NE(panels[0].title.find("LETE sand"), std::string::npos) << panels[0].title;
  EXPECT_NE(panels[1].title.find("3000 N"), std::string::npos) << panels[1].title;
  EXPECT_NE(panels[1].ylabel.find("sinkage"), std::string::npos);
  EXPECT_NE(panels[2].ylabel.find("efficiency"), std::string::npos);
  const std::string dp = plot_line_after(panels[0].title);
  EXPECT_NE(dp.find("towed (T = 0)"), std::string::npos) << dp;
  EXPECT_NE(dp.find("self-propelled (DP = 0)"), std::string::npos) << dp;
  // The curve and its marks share one colour; the braked side and zero are on the axis.
  EXPECT_NE(dp.find("linespoints pt 7 lc 1"), std::string::npos) << dp;
  EXPECT_NE(dp.find("points pt 9 ps 2 lc 1"), std::string::npos) << dp;
  const std::string s = script();
  const auto xr = s.find("set xrange [");
  ASSERT_NE(xr, std::string::npos);
  EXPECT_LT(std::stod(s.substr(xr + 12)), -0.1);
}

TEST_F(SoilPlots, TheBevameterTitleWritesKPhiAndTheCyclesGetTheirLines) {
  const auto panels = plot({"identify", "bevameter", kSrc + "/tests/data/soil/plate_sinkage.csv",
                            "--plot", (dir_ / "b.svg").string()});
  ASSERT_EQ(panels.size(), 1u);
  // Enhanced text: "k_phi" rendered as k subscript p followed by "hi"; "k_{phi}" is k_phi.
  EXPECT_NE(panels[0].title.find("k_{phi}"), std::string::npos) << panels[0].title;
  EXPECT_EQ(panels[0].title.find("k_phi"), std::string::npos) << panels[0].title;
  const std::string line = plot_line_after(panels[0].title);
  for (const char* cycle : {"Wong''s unloading, cycle 1", "Wong''s unloading, cycle 3"})
    EXPECT_NE(line.find(cycle), std::string::npos) << line;
}

TEST_F(SoilPlots, EachShearDataSetSharesItsColourWithItsOwnFit) {
  const auto panels = plot({"identify", "shear", kSrc + "/tests/data/soil/shear.csv", "--plot",
                            (dir_ / "s.svg").string()});
  ASSERT_EQ(panels.size(), 1u);
  const std::string line = plot_line_after(panels[0].title);
  auto colour_of = [&](const std::string& title) {
    const auto t = line.find("title '" + title + "'");
    if (t == std::string::npos) return std::string("?");
    const auto lc = line.rfind(" lc ", t);
    return line.substr(lc, line.find(' ', lc + 4) - lc);
  };
  for (const char* s : {"2.5", "20.0", "40.0"})
    EXPECT_EQ(colour_of(std::string("sigma = ") + s + " kPa"),
              colour_of(std::string("fit, ") + s + " kPa"))
        << s;
  EXPECT_NE(colour_of("sigma = 20.0 kPa"), colour_of("fit, 40.0 kPa"));
}

}  // namespace

// Plots are drawn by gnuplot without a shell: no file name or text of the figure can run a
// command, and a failed or refused plot leaves nothing behind (issue 16 items 1 and 4).
#include "modaltyre/core/gnuplot.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

namespace fs = std::filesystem;

class Gnuplot : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("modaltyre_gnuplot_") + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
  }
  // A figure whose every text tries to run `touch <marker>` through gnuplot or a shell.
  PlotFigure hostile_figure(const fs::path& marker) const {
    const std::string m = marker.string();
    PlotPanel p;
    p.title = "a`touch " + m + "`b";
    p.xlabel = "x\nsystem('touch " + m + "')";
    p.ylabel = "y' . system(\"touch " + m + "\") . '";
    p.series.push_back({"s$(touch " + m + ")", {0, 1, 2}, {0, 1, 4}, "lines"});
    return PlotFigure{{p}};
  }
  fs::path dir_;
};

TEST(GnuplotQuote, SingleQuotedWithQuotesDoubledAndNoLineBreaks) {
  EXPECT_EQ(gnuplot_quote("plain"), "'plain'");
  EXPECT_EQ(gnuplot_quote("it's"), "'it''s'");
  EXPECT_EQ(gnuplot_quote("a\nb\rc"), "'a b c'");
  EXPECT_EQ(gnuplot_quote("`cmd` $(x) \"q\" \\"), "'`cmd` $(x) \"q\" \\'");
}

// The script names no file at all: data are inline datablocks, the image goes to stdout.
TEST(GnuplotScript, HasNoFileNamesAndNoOutputCommand) {
  PlotPanel p;
  p.series.push_back({"s", {1, 2}, {3, 4}, "lines"});
  const std::string gp = gnuplot_script(PlotFigure{{p, p}}, "svg");
  EXPECT_EQ(gp.find("set output"), std::string::npos) << gp;
  EXPECT_NE(gp.find("$d0 << EOD\n1 3\n2 4\nEOD\n"), std::string::npos) << gp;
  EXPECT_NE(gp.find("plot $d1 with lines"), std::string::npos) << gp;
}

// A file name full of shell syntax is only a file name; no text of the figure runs anything.
TEST_F(Gnuplot, HostileNamesAndTextsRunNothing) {
  // The name holds no '/', so a shell would create the marker in the working folder.
  const std::string marker = "modaltyre_pwned_" + std::to_string(::getpid());
  const fs::path out = dir_ / ("a$(touch " + marker + ")`touch " + marker + "`;b.svg");
  render_plot(hostile_figure(dir_ / marker), out.string());
  EXPECT_FALSE(fs::exists(marker));
  EXPECT_FALSE(fs::exists(dir_ / marker));
  ASSERT_TRUE(fs::is_regular_file(out));
  std::ifstream in(out);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_NE(s.str().find("</svg>"), std::string::npos);
  EXPECT_EQ(entries(), 1u);  // the plot only: no script, data or temporary file
}

TEST_F(Gnuplot, PngIsComplete) {
  const fs::path out = dir_ / "p.png";
  PlotPanel p;
  p.series.push_back({"s", {0, 1}, {0, 1}, "points"});
  render_plot(PlotFigure{{p}}, out.string());
  std::ifstream in(out, std::ios::binary);
  std::string head(8, '\0');
  in.read(head.data(), 8);
  EXPECT_EQ(head, std::string("\x89PNG\r\n\x1a\n", 8));
}

// A directory as target is refused before gnuplot runs; nothing is left in it.
TEST_F(Gnuplot, DirectoryTargetLeavesNothing) {
  const fs::path d = dir_ / "plots.svg";
  fs::create_directories(d);
  PlotPanel p;
  EXPECT_THROW(render_plot(PlotFigure{{p}}, d.string()), InputError);
  EXPECT_TRUE(fs::is_empty(d));
  EXPECT_EQ(entries(), 1u);
}

TEST_F(Gnuplot, UnknownExtensionIsAnInputError) {
  EXPECT_THROW(render_plot(PlotFigure{}, (dir_ / "p.pdf").string()), InputError);
  EXPECT_EQ(entries(), 0u);
}

// An image panel: its grid is an inline datablock, one scan line per y (blank line between),
// drawn `with image` under the series; gnuplot renders it to a complete SVG.
TEST_F(Gnuplot, ImagePanelIsAScanLineDatablockDrawnUnderTheSeries) {
  PlotPanel p;
  p.image.x = {0, 1, 2};
  p.image.y = {-1, 1};
  p.image.values = {{0, 5, 0}, {1, 9, 1}};
  p.image.cblabel = "pressure [kPa]";
  p.image.cbmax = 10;
  p.equal_axes = true;
  p.series.push_back({"contour", {0, 2, 2, 0, 0}, {-1, -1, 1, 1, -1}, "lines"});
  const std::string gp = gnuplot_script(PlotFigure{{p}}, "svg");
  EXPECT_NE(gp.find("$m0 << EOD\n0 -1 0\n1 -1 5\n2 -1 0\n\n0 1 1\n1 1 9\n2 1 1\n\nEOD\n"),
            std::string::npos)
      << gp;
  EXPECT_NE(gp.find("plot $m0 with image notitle, $d0 with lines"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set cbrange [0:10]"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set size ratio -1"), std::string::npos) << gp;
  const fs::path out = dir_ / "map.svg";
  render_plot(PlotFigure{{p}}, out.string());
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("</svg>"), std::string::npos);
  EXPECT_NE(text.str().find("<image"), std::string::npos);  // the map as a raster image
}

}  // namespace
}  // namespace modaltyre

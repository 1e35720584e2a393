// core/command_files.h: file identity through links and spellings, and the refusals' words.
#include "modaltyre/core/command_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "modaltyre/core/errors.h"

namespace {

namespace fs = std::filesystem;
using modaltyre::CommandFiles;
using modaltyre::InputError;
using modaltyre::same_file;

class CommandFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("modaltyre_cmdfiles_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub");
    std::ofstream(dir_ / "a.csv") << "x\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string p(const std::string& rel) const { return (dir_ / rel).string(); }
  fs::path dir_;
};

TEST_F(CommandFilesTest, SameFileSeesThroughSpellingsAndLinks) {
  EXPECT_TRUE(same_file(p("a.csv"), p("sub/../a.csv")));
  EXPECT_TRUE(same_file(p("a.csv"), p("./a.csv")));
  fs::create_symlink(p("a.csv"), p("sym.csv"));
  EXPECT_TRUE(same_file(p("a.csv"), p("sym.csv")));
  fs::create_hard_link(p("a.csv"), p("hard.csv"));
  EXPECT_TRUE(same_file(p("hard.csv"), p("a.csv")));
  // Paths that do not exist yet compare by their normal form.
  EXPECT_TRUE(same_file(p("new.csv"), p("sub/../new.csv")));
  fs::create_directory_symlink(dir_ / "sub", dir_ / "subln");
  EXPECT_TRUE(same_file(p("sub/new.csv"), p("subln/new.csv")));
  EXPECT_FALSE(same_file(p("a.csv"), p("new.csv")));
  EXPECT_FALSE(same_file(p("a.csv"), ""));
}

TEST_F(CommandFilesTest, RefusesAnOutputOverAnInputNamingBoth) {
  CommandFiles f;
  f.input(p("a.csv"), "MEASURED");
  f.output(p("sub/../a.csv"), "--plot");
  try {
    f.check();
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "--plot");
    const std::string m = e.what();
    EXPECT_NE(m.find("MEASURED"), std::string::npos) << m;
    EXPECT_NE(m.find("over an input"), std::string::npos) << m;
  }
}

TEST_F(CommandFilesTest, RefusesTwoOutputsToOneFileAndAnEmptyPath) {
  CommandFiles two;
  two.output(p("x.svg"), "--plot");
  two.output(p("./x.svg"), "--map-csv");
  EXPECT_THROW(two.check(), InputError);
  CommandFiles empty;
  empty.output("", "--output");
  EXPECT_THROW(empty.check(), InputError);
  CommandFiles folder;
  folder.output(p("sub"), "--output");
  EXPECT_THROW(folder.check(), InputError);
  CommandFiles missing;
  missing.output(p("nodir/x.csv"), "--output");
  EXPECT_THROW(missing.check(), InputError);
}

TEST_F(CommandFilesTest, AcceptsDistinctFilesAndStreams) {
  CommandFiles f;
  f.input(p("a.csv"), "MEASURED");
  f.input("", "--static");  // an optional input not given
  f.output(p("b.csv"), "--output");
  f.output(p("c.svg"), "--plot");
  f.output("/dev/null", "--csv");
  f.output("/dev/null", "--map-csv");
  EXPECT_NO_THROW(f.check());
}

// Issue 44 item 5: a dangling link names the file that writing through it creates, so an output
// linked to another output not yet written is that output (transient --plot p.svg -> o.csv
// wrote the SVG over the CSV written just before). Relative targets, chains and a loop.
TEST_F(CommandFilesTest, ADanglingLinkIsTheFileItWillCreate) {
  fs::create_symlink("o.csv", p("p.svg"));  // relative, dangling
  EXPECT_TRUE(same_file(p("p.svg"), p("o.csv")));
  EXPECT_EQ(modaltyre::final_target(p("p.svg")), (dir_ / "o.csv").lexically_normal().string());
  fs::create_symlink(p("p.svg"), p("q.png"));  // a chain ending dangling
  EXPECT_TRUE(same_file(p("q.png"), p("o.csv")));
  fs::create_symlink("sub/../deep.csv", p("r.csv"));
  EXPECT_TRUE(same_file(p("r.csv"), p("deep.csv")));
  EXPECT_FALSE(same_file(p("p.svg"), p("a.csv")));
  CommandFiles two;
  two.output(p("o.csv"), "--csv");
  two.output(p("p.svg"), "--plot");
  try {
    two.check();
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "--plot");
    EXPECT_NE(std::string(e.what()).find("--csv"), std::string::npos) << e.what();
  }
  // A loop of links ends the walk (at 40 links) instead of hanging.
  fs::create_symlink("loop2", p("loop1"));
  fs::create_symlink("loop1", p("loop2"));
  EXPECT_FALSE(same_file(p("loop1"), p("a.csv")));
}

}  // namespace

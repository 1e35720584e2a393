// init's input checks (init/src/init_checks.h, issue 44 item 5): a range the config reader
// refuses on the text init wrote is named by the option that set the key, never by the output
// file (not yet written); an error of a real input file (the hammer CSV) keeps its file and line;
// a ring of tonnes per metre is refused at the frequencies.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "modaltyre/core/errors.h"
#include "modaltyre/init/init_tyre.h"

namespace modaltyre::init {
namespace {

namespace fs = std::filesystem;

InitInputs list_205_55() {
  InitInputs in;
  in.size = "205/55R16";
  in.test_pressure_kPa = 200;
  in.frequencies_hz = {90, 105, 124, 146, 170, 195};
  in.two_d = true;
  in.output_path = "out.yaml";
  return in;
}

InputError error_of(const InitInputs& in) {
  try {
    init_tyre(in);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("none");
}

TEST(InitChecks, ARangeTheReaderRefusesIsNamedByItsOption) {
  InitInputs in = list_205_55();
  in.tread_depth_mm = 0.05;  // the reader's tread.thickness_mm range is [0.1, 200]
  const InputError e = error_of(in);
  EXPECT_EQ(e.where().file, "--tread-depth-mm");
  EXPECT_EQ(std::string(e.what()).find("out.yaml"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("tread.thickness_mm"), std::string::npos) << e.what();
  in = list_205_55();
  in.wheel_mass_kg = 2e4;  // above the reader's 1e4 kg
  EXPECT_EQ(error_of(in).where().file, "--wheel-mass-kg");
}

TEST(InitChecks, AHammerFileKeepsItsOwnFileAndLine) {
  const fs::path dir = fs::temp_directory_path() / "modaltyre_init_checks";
  fs::create_directories(dir);
  const fs::path hammer = dir / "h.csv";
  std::ofstream(hammer) << "mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential\n"
                        << "1,100,0.03,1,0,abc,0\n";
  InitInputs in = list_205_55();
  in.frequencies_hz.clear();
  in.hammer_csv = hammer.string();
  in.output_path = (dir / "out.yaml").string();
  const InputError e = error_of(in);
  EXPECT_EQ(e.where().file, hammer.string()) << e.what();
  EXPECT_EQ(e.where().line, 2);
  fs::remove_all(dir);
}

// Frequencies of 1-1.5 Hz make a ring of about 18 t/m (a 34 t belt): refused at --frequencies,
// with stated and with proposed orders; the usual 90-195 Hz list gives 0.5-3 kg/m and passes.
TEST(InitChecks, ARingOfTonnesPerMetreIsRefusedAtTheFrequencies) {
  InitInputs in = list_205_55();
  in.frequencies_hz = {1, 1.1, 1.2, 1.3, 1.4, 1.5};
  in.orders = {1, 2, 3, 4, 5, 6};
  const InputError e = error_of(in);
  EXPECT_EQ(e.where().file, "--frequencies");
  EXPECT_NE(std::string(e.what()).find("kg/m"), std::string::npos) << e.what();
  in.orders.clear();
  EXPECT_EQ(error_of(in).where().file, "--frequencies");
  const InitResult ok = init_tyre(list_205_55());
  EXPECT_GT(ok.carcass.mass_per_length_kg_m, 0.2);
  EXPECT_LT(ok.carcass.mass_per_length_kg_m, 5);
}

// The free-test warning compares the ring's mass with a passenger belt's in the right words.
TEST(InitChecks, TheBeltMassWarningSaysLighterOnlyWhenItIs) {
  const InitResult r = init_tyre(list_205_55());
  bool lighter = false;
  for (const auto& w : r.warnings) lighter = lighter || w.find("lighter than") != std::string::npos;
  EXPECT_TRUE(lighter);
  InitInputs heavy = list_205_55();
  heavy.frequencies_hz = {30, 35, 41, 49, 57, 65};  // a ring nine times heavier
  heavy.orders = {1, 2, 3, 4, 5, 6};
  const InitResult h = init_tyre(heavy);
  bool says_heavier = false;
  for (const auto& w : h.warnings)
    says_heavier = says_heavier || w.find("heavier than") != std::string::npos;
  EXPECT_TRUE(says_heavier) << "ring mass " << h.carcass.mass_per_length_kg_m << " kg/m";
}

}  // namespace
}  // namespace modaltyre::init

// The Magic Formula laws (Pacejka 2012 App. 3) and their reading from .tir files: (A3.4) makes
// the tangent stiffness at FNOMIN equal VERTICAL_STIFFNESS, (A3.3) inverts exactly, a file in
// mm/kN/bar gives the same SI laws as its SI twin, and what is not a Magic Formula file is
// refused with what it is.
#include "modaltyre/tir/mf_tyre.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "modaltyre/core/errors.h"

namespace {

using modaltyre::InputError;
using namespace modaltyre::tir;

const std::string kTirData = std::string(MODALTYRE_SOURCE_DIR) + "/tests/data/tir/";

MfVerticalLaw law(double q_fz2) {
  MfVerticalLaw v;
  v.unloaded_radius_m = 0.3;
  v.fnomin_N = 4000;
  v.vertical_stiffness_N_m = 2.2e5;
  v.q_fz2 = q_fz2;
  v.q_fz1 = *q_fz1_from_stiffness(v.vertical_stiffness_N_m, 0.3, 4000, q_fz2);
  return v;
}

class VerticalLaw : public ::testing::TestWithParam<double> {};

TEST_P(VerticalLaw, TangentStiffnessAtFnominIsVerticalStiffness) {
  const MfVerticalLaw v = law(GetParam());
  const double rho0 = *mf_deflection_m(v, v.fnomin_N);
  EXPECT_NEAR(mf_load_N(v, rho0), v.fnomin_N, 1e-9 * v.fnomin_N);
  const double h = 1e-7;
  const double tangent = (mf_load_N(v, rho0 + h) - mf_load_N(v, rho0 - h)) / (2 * h);
  EXPECT_NEAR(tangent / v.vertical_stiffness_N_m, 1, 1e-6);
  // (A3.4) and its inverse are one map.
  EXPECT_NEAR(*stiffness_from_q_fz(v.q_fz1, v.q_fz2, 0.3, 4000), v.vertical_stiffness_N_m, 1e-6);
}

TEST_P(VerticalLaw, DeflectionInvertsLoad) {
  const MfVerticalLaw v = law(GetParam());
  for (double f : {100.0, 2000.0, 4000.0, 8000.0}) {
    const auto rho = mf_deflection_m(v, f);
    ASSERT_TRUE(rho);
    EXPECT_NEAR(mf_load_N(v, *rho), f, 1e-9 * f);
  }
}

INSTANTIATE_TEST_SUITE_P(QFz2, VerticalLaw, ::testing::Values(0.0, 15.0, -5.0),
                         [](const auto& info) {
                           return info.param == 0  ? std::string("Linear")
                                  : info.param > 0 ? std::string("Stiffening")
                                                   : std::string("Softening");
                         });

TEST(MfFormulas, PressureScalesLoadAndStiffness) {
  MfVerticalLaw v = law(0);
  v.pfz1 = 0.7;
  v.nominal_pressure_Pa = 2.2e5;
  // (A3.5): dp_i = 0.2/2.2; the load at any deflection scales by 1 + p_Fz1 dp_i.
  const double scale = 1 + 0.7 * (0.2 / 2.2);
  EXPECT_NEAR(mf_vertical_stiffness(v, 2.4e5), 2.2e5 * scale, 1e-6);
  EXPECT_NEAR(mf_load_N(v, 0.01, 2.4e5), mf_load_N(v, 0.01) * scale, 1e-9);
}

TEST(MfFormulas, PatchLawsAtKnownDeflection) {
  // rho/R0 = 0.064: sqrt = 0.25298, cube root = 0.4
  EXPECT_NEAR(mf_half_length_m(0.3, 0.6, 0.8, 0.0192), 0.3 * (0.8 * 0.064 + 0.6 * std::sqrt(0.064)),
              1e-15);
  EXPECT_NEAR(mf_half_width_m(0.3, 0.2, 1.0, -1.0, 0.0192), 0.2 * (0.4 - 0.064), 1e-12);
}

TEST(MfTyreFile, NonSiUnitsGiveSiLaws) {
  // tests/data/tir/mfswift62_mm_kN.tir: R0 310 mm, W 205 mm, FNOMIN 4.2 kN, C_z 0.21 kN/mm,
  // INFLPRES 2.4 bar, NOMPRES 2.2 bar, PFZ1 0.7, Q_RA1/2 0.65/0.75, Q_RB1/2 1.05/-1.2.
  const MfTyre t = read_mf_tyre(kTirData + "mfswift62_mm_kN.tir");
  EXPECT_EQ(t.fittyp, 62);
  EXPECT_DOUBLE_EQ(t.unloaded_radius_m, 0.31);
  EXPECT_DOUBLE_EQ(*t.width_m, 0.205);
  EXPECT_DOUBLE_EQ(t.vertical.fnomin_N, 4200);
  EXPECT_NEAR(t.vertical.vertical_stiffness_N_m, 2.1e5, 1e-6);
  EXPECT_NEAR(t.inflation_pressure_Pa, 2.4e5, 1e-6);
  const double cz = 2.1e5 * (1 + 0.7 * (0.2 / 2.2));
  EXPECT_NEAR(t.vertical_stiffness_N_m(), cz, 1e-6);
  EXPECT_NEAR(*t.load_N(0.01), cz * 0.01, 1e-6);  // Q_FZ2 = 0: linear at INFLPRES
  const double x = 3000 / cz / 0.31;
  EXPECT_NEAR(*t.length_m(3000), 2 * 0.31 * (0.75 * x + 0.65 * std::sqrt(x)), 1e-12);
  EXPECT_NEAR(*t.width_at_m(3000), 2 * 0.205 * (-1.2 * x + 1.05 * std::cbrt(x)), 1e-12);
}

TEST(MfTyreFile, OlderFileUsesItsDeflectionLoadTable) {
  const MfTyre t = read_mf_tyre(kTirData + "mf52_load_curve_table.tir");
  EXPECT_TRUE(t.table_law);
  EXPECT_NEAR(*t.load_N(0.0125), 2700, 1e-9);  // between (0.010, 2100) and (0.015, 3300)
  EXPECT_FALSE(t.load_N(0.031));               // beyond the table
  EXPECT_TRUE(t.length_m(3000));
  EXPECT_FALSE(t.width_at_m(3000));
  EXPECT_NE(t.width_reason.find("Q_RB1"), std::string::npos);
}

TEST(MfTyreFile, Pac2002WithoutContactPatchSaysWhy) {
  const MfTyre t = read_mf_tyre(kTirData + "pac2002_mf52.tir");
  EXPECT_FALSE(t.table_law);
  EXPECT_NEAR(*t.load_N(0.02), 2e5 * 0.02, 1e-9);  // VERTICAL_STIFFNESS 2.0D+05, no Q_FZ2
  EXPECT_FALSE(t.length_m(4000));
  EXPECT_NE(t.length_reason.find("Q_RA1"), std::string::npos);
}

TEST(MfTyreFile, FtireIsRefusedWithWhatItIs) {
  try {
    read_mf_tyre(kTirData + "ftire_model.tir");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is an FTire tyre model file"), std::string::npos)
        << e.what();
  }
}

// A public MF 5.2 file (an FSAE tyre's, obfuscated) states ASPECT_RATIO = 470: no law uses the
// aspect ratio or the rim radius, so such values are left out with a note naming file, line and
// key, and the file's laws are still read (issue 20: unused keys are kept, not rejected).
TEST(MfTyreFile, UnusedDimensionKeysOutOfRangeAreNotedNotRefused) {
  const MfTyre t = interpret_tir(
      parse_tir("[MODEL]\nFITTYP = 6\n[DIMENSION]\nUNLOADED_RADIUS = 0.254\nWIDTH = 0.2\n"
                "ASPECT_RATIO = 470\nRIM_RADIUS = rim\n[VERTICAL]\nFNOMIN = 2700\n"
                "VERTICAL_STIFFNESS = 125000\n[CONTACT_PATCH]\nQ_RA1 = 0.5\nQ_RA2 = 1\n",
                "unused.tir"));
  EXPECT_FALSE(t.aspect_ratio);
  EXPECT_FALSE(t.rim_radius_m);
  ASSERT_EQ(t.notes.size(), 2u);
  EXPECT_NE(t.notes[0].find("unused.tir:7: DIMENSION.RIM_RADIUS: 'rim' is not a number"),
            std::string::npos)
      << t.notes[0];
  EXPECT_NE(t.notes[1].find("unused.tir:6: DIMENSION.ASPECT_RATIO: 470 is outside 0.01 .. 5; "),
            std::string::npos)
      << t.notes[1];
  // the laws are read as stated: linear (no Q_FZ2), A3.7 at rho = F/C_z
  EXPECT_NEAR(*t.load_N(0.01), 1250, 1e-9);
  const double x = 2700.0 / 125000 / 0.254;
  EXPECT_NEAR(*t.length_m(2700), 2 * 0.254 * (1.0 * x + 0.5 * std::sqrt(x)), 1e-12);
}

struct BadMf {
  const char* name;
  const char* text;
  int line;
  const char* key;
  const char* says;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const BadMf& c, std::ostream* os) { *os << c.name; }

class MfTyreRefuses : public ::testing::TestWithParam<BadMf> {};

TEST_P(MfTyreRefuses, NamingLineAndKey) {
  const BadMf& c = GetParam();
  try {
    interpret_tir(parse_tir(c.text, "bad.tir"));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, c.line) << e.what();
    EXPECT_EQ(e.where().key, c.key) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
}

#define MF_HEAD "[MODEL]\nFITTYP = 62\n[DIMENSION]\nUNLOADED_RADIUS = 0.3\n"
INSTANTIATE_TEST_SUITE_P(
    Cases, MfTyreRefuses,
    ::testing::Values(
        BadMf{"NoModel", "[DIMENSION]\nUNLOADED_RADIUS = 0.3\n", 0, "MODEL.FITTYP",
              "not an MF-Tyre"},
        BadMf{"OtherModel", "[MODEL]\nPROPERTY_FILE_FORMAT = 'FIALA'\n", 2,
              "MODEL.PROPERTY_FILE_FORMAT", "'FIALA' tyre model"},
        BadMf{"FittypText", "[MODEL]\nFITTYP = six\n", 2, "MODEL.FITTYP", "version number"},
        BadMf{"NoRadius", "[MODEL]\nFITTYP = 62\n", 0, "DIMENSION.UNLOADED_RADIUS", "missing"},
        BadMf{"RadiusOutOfRange", "[MODEL]\nFITTYP = 62\n[DIMENSION]\nUNLOADED_RADIUS = 310\n", 4,
              "DIMENSION.UNLOADED_RADIUS", "outside"},
        BadMf{"NoFnomin", MF_HEAD "[VERTICAL]\nVERTICAL_STIFFNESS = 2e5\n", 0, "VERTICAL.FNOMIN",
              "missing"},
        BadMf{"NoVerticalLaw", MF_HEAD "[VERTICAL]\nFNOMIN = 4000\n", 0,
              "VERTICAL.VERTICAL_STIFFNESS", "no vertical law"},
        BadMf{"StiffnessText", MF_HEAD "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = soft\n", 7,
              "VERTICAL.VERTICAL_STIFFNESS", "not a number"},
        BadMf{"QFz2NoRealQFz1",
              MF_HEAD "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = 2e5\nQ_FZ2 = 1e6\n", 8,
              "VERTICAL.Q_FZ2", "A3.4"},
        BadMf{"TableNotIncreasing",
              "[MODEL]\nFITTYP = 21\n[DIMENSION]\nUNLOADED_RADIUS = 0.3\n[VERTICAL]\nFNOMIN = "
              "4000\n[DEFLECTION_LOAD_CURVE]\n0 0\n0.01 2000\n0.01 2500\n",
              10, "DEFLECTION_LOAD_CURVE", "strictly increasing"},
        // Issue 38: a version number no Magic Formula writer states, and contact-patch laws
        // that start negative (Q_RA1 < 0 gave negative contact lengths).
        BadMf{"FittypUnknown", "[MODEL]\nFITTYP = 999\n", 2, "MODEL.FITTYP",
              "not a Magic Formula version this reader knows"},
        BadMf{"NegativeQRa1",
              MF_HEAD "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = 2e5\n[CONTACT_PATCH]\n"
                      "Q_RA1 = -0.5\nQ_RA2 = 0.7\n",
              9, "CONTACT_PATCH.Q_RA1", "outside 1e-09 .. 1000"},
        BadMf{"NegativeQRb1",
              MF_HEAD "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = 2e5\n[CONTACT_PATCH]\n"
                      "Q_RB1 = -1\nQ_RB2 = 0.7\n",
              9, "CONTACT_PATCH.Q_RB1", "outside 1e-09 .. 1000"}),
    [](const ::testing::TestParamInfo<BadMf>& info) { return info.param.name; });

}  // namespace

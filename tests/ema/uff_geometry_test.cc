// UFF test geometry (issue 38): nodes of dataset 15 / 2411 and coordinate systems of 2420 turn
// the directions a modal software writes (1, 2, 3 of each node's displacement system) into the
// tyre's radial and tangential directions, and give each point its angle from its position.
// Node numbers need not be 1 ... N.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "ema_test_support.h"
#include "modaltyre/ema/ema.h"
#include "modaltyre/ema/uff58.h"
#include "planted_models.h"
#include "uff_writer.h"

namespace modaltyre::ema {
namespace {

using modaltyre_test::fmt;
using modaltyre_test::UffOptions;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius_m = 0.29;

// A cylindrical system 5 about the axle (global -Y), theta = 0 along X, theta = 90 deg along Z.
std::string cylindrical_system() {
  return "    -1\n  2420\n         1\nTYRE\n         5         1         8\nAXLE\n" +
         fmt("%25.16e%25.16e%25.16e\n", 1.0, 0.0, 0.0) +
         fmt("%25.16e%25.16e%25.16e\n", 0.0, 0.0, 1.0) +
         fmt("%25.16e%25.16e%25.16e\n", 0.0, -1.0, 0.0) +
         fmt("%25.16e%25.16e%25.16e\n", 0.0, 0.0, 0.0) + "    -1\n";
}

// Nodes 101 ... 112 on a circle in the X-Z plane (global Cartesian coordinates), the first at
// `start_deg`, numbered in the direction of theta; each moves in `displacement_cs`. Dataset
// 2411 (double precision) or 15.
std::string nodes(double start_deg, long displacement_cs, bool dataset2411,
                  double shift_node_105_deg = 0) {
  std::string s = dataset2411 ? "    -1\n  2411\n" : "    -1\n    15\n";
  for (int i = 0; i < 12; ++i) {
    const double a = (start_deg + 30.0 * i + (i == 4 ? shift_node_105_deg : 0)) * kPi / 180;
    const double x = kRadius_m * std::cos(a), z = kRadius_m * std::sin(a);
    if (dataset2411) {
      s += fmt("%10d%10d%10ld%10d\n", 101 + i, 0, displacement_cs, 1);
      s += fmt("%25.16e%25.16e%25.16e\n", x, 0.0, z);
    } else {
      s += fmt("%10d%10d%10ld%10d%13.5e%13.5e%13.5e\n", 101 + i, 0, displacement_cs, 1, x, 0.0, z);
    }
  }
  return s + "    -1\n";
}

// The ring model's FRFs with points renumbered 101 ... 112.
FrfSet ring_frfs() {
  modaltyre_test::PlantedModel model = modaltyre_test::ring_model();
  for (int i = 0; i < 12; ++i) model.point_numbers.push_back(101 + i);
  modaltyre_test::SynthOptions so;
  so.reference = {101, Direction::radial};
  so.noise = 0.001;
  return modaltyre_test::synthesise(model, so);
}

class UffGeometry : public modaltyre_test::ScratchDir {};

// An InputError naming `path` whose key contains `field`; its message.
std::string expect_input_error_any(const std::function<void()>& read, const std::string& path,
                                   const std::string& field) {
  try {
    read();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, path) << e.what();
    EXPECT_GT(e.where().line, 0) << e.what();
    EXPECT_NE(e.where().key.find(field), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << path;
  return "";
}

// Directions r (1) and theta (2) of a cylindrical system read as radial and tangential; the
// angles come from the positions (0 at node 101), the values are those written.
TEST_F(UffGeometry, CylindricalDirectionsAndPositionsGiveTheTyreDofs) {
  const FrfSet planted = ring_frfs();
  UffOptions o;
  o.radial_code = 1;
  o.tangential_code = 2;
  for (const bool d2411 : {false, true}) {
    const std::string text =
        cylindrical_system() + nodes(90, 5, d2411) + modaltyre_test::uff58_file(planted, o);
    const FrfSet s = read_uff58(write(text, d2411 ? "g2411.unv" : "g15.unv"));
    ASSERT_EQ(s.channels.size(), planted.channels.size());
    for (std::size_t c = 0; c < s.channels.size(); ++c) {
      EXPECT_EQ(s.channels[c].response, planted.channels[c].response) << c;
      EXPECT_EQ(s.channels[c].reference, planted.channels[c].reference) << c;
      EXPECT_NEAR(std::abs(s.channels[c].values[100] - planted.channels[c].values[100]), 0,
                  1e-9 * std::abs(planted.channels[c].values[100]));
    }
    ASSERT_EQ(s.point_angle_deg.size(), 12u);
    for (int i = 0; i < 12; ++i) {
      EXPECT_NEAR(s.point_angle_deg.at(101 + i), 30.0 * i, 1e-4) << i;
    }
    // The identification on the geometry's points: the ring's modes, angles as measured.
    EmaOptions eo;
    eo.band_lo_hz = 60;
    eo.band_hi_hz = 330;
    const EmaResult r = run_ema(s, eo);
    EXPECT_EQ(r.modes.size(), 6u);
    EXPECT_EQ(r.points.front(), 101);
    EXPECT_NEAR(r.angle_deg[3], 90.0, 1e-4);
  }
}

// A local Cartesian frame per node (axis 3 radial outward, axis 1 tangential: the implied
// convention written out), with node 101's axis 3 pointing inward: directions 3 and 1 read as
// radial and tangential, and every FRF whose DOF at node 101 is radial changes sign once (the
// driving point, with both DOFs there, keeps its sign).
TEST_F(UffGeometry, LocalFramesAreProjectedOnTheTyreFrame) {
  const FrfSet planted = ring_frfs();
  std::string frames = "    -1\n  2420\n         1\nTYRE\n";
  for (int i = 0; i < 12; ++i) {
    const double a = 30.0 * i * kPi / 180, c = std::cos(a), sn = std::sin(a);
    const double out = i == 0 ? -1 : 1;
    frames += fmt("%10d%10d%10d\nFRAME\n", 11 + i, 0, 8);
    frames += fmt("%25.16e%25.16e%25.16e\n", -sn, 0.0, c);  // axis 1: tangential
    frames += fmt("%25.16e%25.16e%25.16e\n", 0.0, -1.0, 0.0);
    frames += fmt("%25.16e%25.16e%25.16e\n", out * c, 0.0, out * sn);  // axis 3: radial
    frames += fmt("%25.16e%25.16e%25.16e\n", 0.0, 0.0, 0.0);
  }
  frames += "    -1\n";
  std::string nodes_text = "    -1\n  2411\n";
  for (int i = 0; i < 12; ++i) {
    const double a = 30.0 * i * kPi / 180;
    nodes_text += fmt("%10d%10d%10d%10d\n", 101 + i, 0, 11 + i, 1);
    nodes_text +=
        fmt("%25.16e%25.16e%25.16e\n", kRadius_m * std::cos(a), 0.0, kRadius_m * std::sin(a));
  }
  nodes_text += "    -1\n";
  const FrfSet s = read_uff58(
      write(frames + nodes_text + modaltyre_test::uff58_file(planted, UffOptions{}), "local.unv"));
  ASSERT_EQ(s.channels.size(), planted.channels.size());
  for (std::size_t c = 0; c < s.channels.size(); ++c) {
    EXPECT_EQ(s.channels[c].response, planted.channels[c].response) << c;
    const bool driving = planted.channels[c].response == planted.channels[c].reference;
    const std::complex<double> want = (driving ? 1.0 : -1.0) * planted.channels[c].values[100];
    EXPECT_NEAR(std::abs(s.channels[c].values[100] - want), 0, 1e-9 * std::abs(want)) << c;
  }
}

// Refusals name the file, the record's line and field: an axial DOF (direction 3 of the
// cylindrical system, along the axle), a measured node without coordinates, a spherical system.
TEST_F(UffGeometry, AxialDofMissingNodeAndSphericalSystemAreRefused) {
  const FrfSet planted = ring_frfs();
  UffOptions axial;
  axial.radial_code = 3;  // z of the cylindrical system: the axle, not radial
  axial.tangential_code = 2;
  const std::string a =
      write(cylindrical_system() + nodes(0, 5, true) + modaltyre_test::uff58_file(planted, axial),
            "axial.unv");
  const std::string m1 = expect_input_error_any([&] { read_uff58(a); }, a, "direction");
  EXPECT_NE(m1.find("90 deg from the tyre's radial"), std::string::npos) << m1;

  std::string few = nodes(0, 0, true);
  few.erase(few.find(fmt("%10d", 112)));  // node 112 left out
  few += "    -1\n";
  UffOptions o;
  const std::string b = write(few + modaltyre_test::uff58_file(planted, o), "missing.unv");
  const std::string m2 = expect_input_error_any([&] { read_uff58(b); }, b, "node");
  EXPECT_NE(m2.find("node 112 has no coordinates"), std::string::npos) << m2;

  std::string sph = cylindrical_system();
  sph.replace(sph.find("         5         1"), 20, "         5         2");
  const std::string c = write(sph + modaltyre_test::uff58_file(planted, o), "sph.unv");
  const std::string m3 = expect_input_error_any([&] { read_uff58(c); }, c, "2420 record 3");
  EXPECT_NE(m3.find("spherical"), std::string::npos) << m3;
}

// A point placed off the equal spacing: its angle is the measured one, and ema warns that the
// points are not equally spaced (the hammer CSV's reader needs them so).
TEST_F(UffGeometry, UnevenPointsKeepTheirAnglesAndAreWarnedAbout) {
  const FrfSet planted = ring_frfs();
  UffOptions o;
  o.radial_code = 1;
  o.tangential_code = 2;
  const FrfSet s = read_uff58(
      write(cylindrical_system() + nodes(0, 5, true, 6.0) + modaltyre_test::uff58_file(planted, o),
            "uneven.unv"));
  EXPECT_NEAR(s.point_angle_deg.at(105), 126.0, 1e-4);
  EmaOptions eo;
  eo.band_lo_hz = 60;
  eo.band_hi_hz = 330;
  const EmaResult r = run_ema(s, eo);
  bool warned = false;
  for (const auto& w : r.warnings)
    warned = warned || w.find("not equally spaced") != std::string::npos;
  EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace modaltyre::ema

// Wong and Reece's normal stress on the rigid wheel (ground/soil_options.h, rigid_wheel.h)
// against the independent open-source rigid-wheel code pyTerramechanics (tests/data/wong_reece/:
// its numbers and the script that made them), and the distribution's limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "modaltyre/ground/rigid_wheel.h"

namespace modaltyre::ground {
namespace {

const RigidWheel kReferenceWheel{0.2948, 0.14};  // as the reference script's R and width

GroundSettings lete_wong_reece() {
  GroundSettings g;  // Wong, Theory of Ground Vehicles, 4th ed., Table 2.3 (LETE sand)
  g.model = GroundModel::bekker;
  g.bekker.n = 0.79, g.bekker.k_c = 102, g.bekker.k_phi = 5301;
  g.bekker_shear = {1.3, 31.1, 12};
  g.wong_reece = {true, 0.43, 0.32, 0.0};
  return g;
}

struct ReferenceRow {
  double load_N, slip, b_mm, sinkage_mm, entry_deg, drawbar_pull_N, torque_Nm;
};

std::vector<ReferenceRow> reference_rows() {
  std::ifstream in(std::string(MODALTYRE_SOURCE_DIR) + "/tests/data/wong_reece/reference.csv");
  std::vector<ReferenceRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'l') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    ReferenceRow r{};
    s >> r.load_N >> r.slip >> r.b_mm >> r.sinkage_mm >> r.entry_deg >> r.drawbar_pull_N >>
        r.torque_Nm;
    rows.push_back(r);
  }
  return rows;
}

// The bounds are 1 % in sinkage, 0.01 W in drawbar pull and 2 % in torque; both codes
// solve the same integrals (scipy's adaptive quadrature and fsolve there, Gauss panels and the
// Illinois root here), so they agree far closer: the bounds below are the codes' own accuracy.
TEST(WongReece, LeteSandMatchesTheIndependentRigidWheelCode) {
  const std::vector<ReferenceRow> rows = reference_rows();
  ASSERT_EQ(rows.size(), 20u);
  for (const ReferenceRow& ref : rows) {
    const RigidWheelResult r =
        rigid_wheel_rolling(lete_wong_reece(), kReferenceWheel, ref.load_N, ref.slip);
    ASSERT_TRUE(r.ok()) << r.message;
    const std::string at = std::to_string(ref.load_N) + " N, s " + std::to_string(ref.slip);
    EXPECT_NEAR(r.bekker_width_m * 1e3, ref.b_mm, 1e-5 * ref.b_mm) << at;
    EXPECT_NEAR(r.sinkage_m * 1e3, ref.sinkage_mm, 1e-5 * ref.sinkage_mm) << at;
    EXPECT_NEAR(r.drawbar_pull_N, ref.drawbar_pull_N, 1e-5 * ref.load_N) << at;
    EXPECT_NEAR(r.torque_Nm, ref.torque_Nm, 1e-5 * ref.torque_Nm) << at;
    EXPECT_NEAR(r.exit_angle_rad, 0.0, 1e-15) << at;
  }
}

TEST(WongReece, ThePeakMovesBackAndTheWheelSinksDeeperThanWithBekkersFrontStress) {
  // The rear region's stress is the front's compressed onto [theta2, theta_m]: it carries less
  // than the loading stress at the same angles near the peak, so the same load needs a deeper
  // sinkage; the wheel sinks deeper and pulls less, more so as slip moves the peak back.
  GroundSettings front_only = lete_wong_reece();
  front_only.wong_reece.enabled = false;
  double last_ratio = 0;
  for (double s : {0.05, 0.2, 0.4}) {
    const RigidWheelResult wr = rigid_wheel_rolling(lete_wong_reece(), kReferenceWheel, 3000, s);
    const RigidWheelResult bk = rigid_wheel_rolling(front_only, kReferenceWheel, 3000, s);
    ASSERT_TRUE(wr.ok() && bk.ok());
    EXPECT_GT(wr.sinkage_m, bk.sinkage_m) << s;
    EXPECT_LT(wr.drawbar_pull_N, bk.drawbar_pull_N) << s;
    const double ratio = wr.sinkage_m / bk.sinkage_m;
    EXPECT_GT(ratio, last_ratio) << s;
    last_ratio = ratio;
  }
}

TEST(WongReece, ThePeakAtTheLowestPointOnARigidPlasticSoilIsBekkersFrontStress) {
  // c1 = c2 = c3 = 0: theta_m = theta2 = 0, no rear region: the front-only stress exactly.
  GroundSettings g = lete_wong_reece(), off = lete_wong_reece();
  g.wong_reece = {true, 0, 0, 0};
  off.wong_reece.enabled = false;
  for (double s : {-0.2, 0.1, 0.3}) {
    const RigidWheelResult a = rigid_wheel_rolling(g, kReferenceWheel, 4000, s);
    const RigidWheelResult b = rigid_wheel_rolling(off, kReferenceWheel, 4000, s);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a.sinkage_m, b.sinkage_m) << s;
    EXPECT_EQ(a.drawbar_pull_N, b.drawbar_pull_N) << s;
    EXPECT_EQ(a.torque_Nm, b.torque_Nm) << s;
  }
}

TEST(WongReece, ALinearFrictionlessSoilGivesTheClosedFormLoad) {
  // n = 1, no shear: sigma = k R (cos th - cos th1) in front, and the rear's mirror
  // sigma(th) = k R (cos(th1 - (th - th2) q) - cos th1). W = b R int sigma cos: the front in
  // closed form, the rear by Simpson on its smooth integrand (independent of the Gauss panels).
  GroundSettings g = lete_wong_reece();
  g.bekker.n = 1, g.bekker.k_c = 0, g.bekker.k_phi = 2e4;
  g.bekker_shear = {0, 0, 12};
  g.wong_reece = {true, 0.43, 0.32, 0.1};
  const double z0 = 0.02, s = 0.25, R = kReferenceWheel.radius_m, k = 2e7;
  const JanosiHanamoto shear(g.bekker_shear);
  const BekkerWong law(g.bekker, 0.1);
  const RigidWheelResult r =
      rigid_wheel_at_sinkage(law, shear, kReferenceWheel, z0, s, 0, true, g.wong_reece);
  const double th1 = std::acos(1 - z0 / R), thm = (0.43 + 0.32 * s) * th1, th2 = -0.1 * th1;
  const double q = (th1 - thm) / (thm - th2);
  auto F = [&](double t) {  // int (cos t - cos th1) cos t dt
    return 0.5 * (t + std::sin(t) * std::cos(t)) - std::cos(th1) * std::sin(t);
  };
  const double front = k * R * (F(th1) - F(thm));
  const int N = 20000;
  double rear = 0;
  for (int i = 0; i <= N; ++i) {
    const double t = th2 + (thm - th2) * i / N;
    const double f = k * R * (std::cos(th1 - (t - th2) * q) - std::cos(th1)) * std::cos(t);
    rear += f * (i == 0 || i == N ? 1 : (i % 2 ? 4 : 2));
  }
  rear *= (thm - th2) / N / 3;
  EXPECT_NEAR(r.vertical_N, kReferenceWheel.width_m * R * (front + rear), 1e-9 * r.vertical_N);
  EXPECT_NEAR(r.exit_angle_rad, th2, 1e-15);
}

}  // namespace
}  // namespace modaltyre::ground

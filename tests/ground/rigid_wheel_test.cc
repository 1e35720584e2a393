// The rigid wheel on soil (ground/rigid_wheel.h) against closed forms and an independent
// quadrature written here (composite Simpson in t = sqrt(theta1 - theta), bisection on the
// sinkage), docs/soil.md section 3.
#include "modaltyre/ground/rigid_wheel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace modaltyre::ground {
namespace {

// The solver's root tolerance is 1e-10 of the load and its quadrature error below 1e-7 on these
// integrands (48 Gauss panels); the reference quadrature below resolves to ~1e-8.
constexpr double kQuadrature = 2e-6;

GroundSettings lete(double c_kPa = 0, double phi_deg = 0, double K_mm = 12) {
  GroundSettings g;  // Wong, Theory of Ground Vehicles, 4th ed., Table 2.3 (LETE sand)
  g.model = GroundModel::bekker;
  g.bekker.n = 0.79, g.bekker.k_c = 102, g.bekker.k_phi = 5301;
  g.bekker_shear = {c_kPa, phi_deg, K_mm};
  return g;
}

const RigidWheel kWheel{0.2948, 0.14};  // the SF-350's outer radius, its 2D contact width

// Independent reference: sigma = k (R (cos th - cos th1))^n on [th_lo, th1] by Simpson in
// t = sqrt(th1 - th) (smooth at the entry point), f(th) any weight.
double front_integral(double k, double n, double R, double th1, double th_lo,
                      const std::function<double(double)>& weight) {
  const int N = 20000;
  const double T = std::sqrt(th1 - th_lo);
  double sum = 0;
  for (int i = 0; i <= N; ++i) {
    const double t = T * i / N, th = th1 - t * t;
    const double sigma = k * std::pow(std::max(R * (std::cos(th) - std::cos(th1)), 0.0), n);
    const double f = sigma * weight(th) * 2 * t;
    sum += f * (i == 0 || i == N ? 1 : (i % 2 ? 4 : 2));
  }
  return sum * T / N / 3;
}

struct Reference {
  double sinkage_m, resistance_N;
};

// Frictionless soil: static (symmetric, factor 2) or rolling (front only, rigid-plastic).
Reference reference(double load_N, double b_m, bool rolling) {
  const double R = kWheel.radius_m, bw = kWheel.width_m;
  const double k = (102 / b_m + 5301) * 1e3, n = 0.79;
  auto W = [&](double th1) {
    return (rolling ? 1 : 2) * bw * R *
           front_integral(k, n, R, th1, 0, [](double th) { return std::cos(th); });
  };
  double lo = 1e-6, hi = 1.4;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (W(mid) > load_N ? hi : lo) = mid;
  }
  const double th1 = 0.5 * (lo + hi);
  const double Rc =
      bw * R * front_integral(k, n, R, th1, 0, [](double th) { return std::sin(th); });
  return {R * (1 - std::cos(th1)), Rc};
}

TEST(RigidWheel, StaticSinkageOfALinearSoilIsTheClosedForm) {
  // n = 1: W = b k R^2 (theta1 - sin theta1 cos theta1) exactly.
  GroundSettings g = lete();
  g.bekker.n = 1, g.bekker.k_c = 0, g.bekker.k_phi = 2e4;
  const double load = 3000;
  const RigidWheelResult r = rigid_wheel_static(g, kWheel, load);
  ASSERT_TRUE(r.ok()) << r.message;
  const double k = 2e4 * 1e3, R = kWheel.radius_m, th = r.entry_angle_rad;
  EXPECT_NEAR(kWheel.width_m * k * R * R * (th - std::sin(th) * std::cos(th)), load,
              kQuadrature * load);
  EXPECT_NEAR(r.sinkage_m, R * (1 - std::cos(th)), 1e-15);
}

TEST(RigidWheel, FrontContactOfALinearSoilIsTheClosedForm) {
  // n = 1, rolling, frictionless, rigid-plastic: W = b k R^2 (th1 - sin th1 cos th1) / 2 and
  // R_c = b k R^2 (1 - cos th1)^2 / 2.
  GroundSettings g = lete();
  g.bekker.n = 1, g.bekker.k_c = 0, g.bekker.k_phi = 2e4;
  const RigidWheelResult r = rigid_wheel_rolling(g, kWheel, 3000, 0.0);
  ASSERT_TRUE(r.ok()) << r.message;
  const double k = 2e4 * 1e3, R = kWheel.radius_m, th = r.entry_angle_rad;
  const double bkR2 = kWheel.width_m * k * R * R;
  EXPECT_NEAR(0.5 * bkR2 * (th - std::sin(th) * std::cos(th)), 3000, kQuadrature * 3000);
  EXPECT_NEAR(r.motion_resistance_N, 0.5 * bkR2 * std::pow(1 - std::cos(th), 2),
              kQuadrature * r.motion_resistance_N);
  EXPECT_EQ(r.exit_angle_rad, 0.0);  // no rebound
  EXPECT_NEAR(r.drawbar_pull_N, -r.motion_resistance_N, 1e-12);
  EXPECT_EQ(r.torque_Nm, 0.0);
}

// Done-when (issue 37): the rigid tyre on LETE sand at 2-5 kN, static sinkage within 2 % of the
// exact symmetric-contact integral; frictionless rolling at zero slip: sinkage within 2 %,
// motion resistance within 3 % of the front-contact integral. Here to the quadrature.
TEST(RigidWheel, LeteSandStaticAndFrictionlessRollingMatchTheIntegrals) {
  for (double load : {2000.0, 3000.0, 4000.0, 5000.0}) {
    const RigidWheelResult s = rigid_wheel_static(lete(), kWheel, load);
    ASSERT_TRUE(s.ok()) << s.message;
    const Reference rs = reference(load, s.bekker_width_m, false);
    EXPECT_NEAR(s.sinkage_m, rs.sinkage_m, kQuadrature * rs.sinkage_m) << load;
    const RigidWheelResult r = rigid_wheel_rolling(lete(), kWheel, load, 0.0);
    ASSERT_TRUE(r.ok()) << r.message;
    const Reference rr = reference(load, r.bekker_width_m, true);
    EXPECT_NEAR(r.sinkage_m, rr.sinkage_m, kQuadrature * rr.sinkage_m) << load;
    EXPECT_NEAR(r.motion_resistance_N, rr.resistance_N, kQuadrature * rr.resistance_N) << load;
    EXPECT_NEAR(r.bekker_width_m, std::min(kWheel.width_m, r.contact_length_m), 1e-8);
  }
}

// Bekker's small-sinkage closed form (Bekker 1956; Wong eq. 2.71-2.73):
// z0 = (3 W / ((3 - n) k b sqrt(D)))^(2 / (2n + 1)), R_c = b k z0^(n+1) / (n + 1). The issue
// quotes it as 3.5-4 % off the integral in sinkage and 6-7 % in resistance on LETE sand at
// 2-5 kN. Its small-sinkage limit is not exact either: with the contact a parabola,
// W = b k sqrt(D) I_n z0^(n + 1/2), I_n = int_0^1 (1 - u^2)^n du = (sqrt(pi)/2) G(n+1)/G(n+3/2),
// which Bekker replaces by (3 - n)/3 (0.737 against 0.710 at n = 0.79, 2.9 % in sinkage). The
// integral must approach the parabola's exact form as the load goes to zero.
TEST(RigidWheel, BekkersClosedFormIsTheSmallSinkageLimit) {
  auto parabola = [](double load, double b) {
    const double n = 0.79, k = (102 / b + 5301) * 1e3, bw = kWheel.width_m;
    const double In = 0.5 * std::sqrt(M_PI) * std::tgamma(n + 1) / std::tgamma(n + 1.5);
    return std::pow(load / (bw * k * std::sqrt(2 * kWheel.radius_m) * In), 1 / (n + 0.5));
  };
  auto bekker = [](double load, double b) {
    const double n = 0.79, k = (102 / b + 5301) * 1e3, bw = kWheel.width_m;
    const double z0 =
        std::pow(3 * load / ((3 - n) * k * bw * std::sqrt(2 * kWheel.radius_m)), 2 / (2 * n + 1));
    return Reference{z0, bw * k * std::pow(z0, n + 1) / (n + 1)};
  };
  double last_gap = 1;
  for (double load : {5000.0, 2000.0, 200.0, 20.0}) {
    const RigidWheelResult r = rigid_wheel_rolling(lete(), kWheel, load, 0.0);
    ASSERT_TRUE(r.ok());
    const Reference b = bekker(load, r.bekker_width_m);
    const double gap_z = std::abs(b.sinkage_m / r.sinkage_m - 1);
    const double gap_r = std::abs(b.resistance_N / r.motion_resistance_N - 1);
    if (load >= 2000) {
      EXPECT_GT(gap_z, 0.02) << load;  // the closed form is an approximation here
      EXPECT_LT(gap_z, 0.06) << load;
      EXPECT_GT(gap_r, 0.04) << load;
      EXPECT_LT(gap_r, 0.09) << load;
    }
    const double gap_parabola = std::abs(parabola(load, r.bekker_width_m) / r.sinkage_m - 1);
    EXPECT_LT(gap_parabola, last_gap) << load;
    last_gap = gap_parabola;
  }
  EXPECT_LT(last_gap, 0.002);  // at 20 N (sinkage 0.4 mm)
}

// Done-when (issue 37): with shear (LETE sand, c 1.3 kPa, phi 31.1 deg, K 12 mm) at slips
// 0.05-0.4, drawbar pull within 0.02 W and torque within 5 % of the integral. The reference here:
// Simpson in t = sqrt(theta1 - theta) at the solver's entry angle, j(theta) in closed form,
// sigma from Bekker, tau from Janosi-Hanamoto written out; the solver's vertical integral must
// equal the load and its entry angle reproduce it.
TEST(RigidWheel, LeteSandDrawbarPullAndTorqueAtSlipMatchTheIntegral) {
  const double c = 1.3e3, tphi = std::tan(31.1 * M_PI / 180), K = 0.012, n = 0.79;
  const double R = kWheel.radius_m, bw = kWheel.width_m;
  for (double load : {2000.0, 5000.0}) {
    for (double s : {0.05, 0.1, 0.2, 0.4}) {
      const RigidWheelResult r = rigid_wheel_rolling(lete(1.3, 31.1, 12), kWheel, load, s);
      ASSERT_TRUE(r.ok()) << r.message;
      const double k = (102 / r.bekker_width_m + 5301) * 1e3, th1 = r.entry_angle_rad;
      auto sigma = [&](double th) {
        return k * std::pow(std::max(R * (std::cos(th) - std::cos(th1)), 0.0), n);
      };
      auto tau = [&](double th) {
        const double j = R * ((th1 - th) - (1 - s) * (std::sin(th1) - std::sin(th)));
        return (c + sigma(th) * tphi) * (1 - std::exp(-j / K));
      };
      const int N = 20000;
      const double T = std::sqrt(th1);
      double W = 0, DP = 0, M = 0;
      for (int i = 0; i <= N; ++i) {
        const double t = T * i / N, th = th1 - t * t,
                     w = (i == 0 || i == N ? 1 : (i % 2 ? 4 : 2)) * 2 * t;
        W += w * (sigma(th) * std::cos(th) + tau(th) * std::sin(th));
        DP += w * (tau(th) * std::cos(th) - sigma(th) * std::sin(th));
        M += w * tau(th);
      }
      const double h = T / N / 3;
      W *= bw * R * h, DP *= bw * R * h, M *= bw * R * R * h;
      EXPECT_NEAR(W, load, kQuadrature * load) << load << " " << s;
      EXPECT_NEAR(r.drawbar_pull_N, DP, kQuadrature * load) << load << " " << s;
      EXPECT_NEAR(r.torque_Nm, M, kQuadrature * std::abs(M)) << load << " " << s;
    }
  }
}

TEST(RigidWheel, PureCohesionAtLargeDisplacementGivesTheClosedFormTorqueAndThrust) {
  // phi = 0, K -> 0: tau = c over the whole contact (j > 0 at a driven slip), so
  // T = c b R^2 (th1 - th2), H = c b R (sin th1 - sin th2).
  const double c = 5e3;
  const RigidWheelResult r = rigid_wheel_rolling(lete(5, 0, 1e-4), kWheel, 3000, 0.3);
  ASSERT_TRUE(r.ok()) << r.message;
  const double R = kWheel.radius_m, b = kWheel.width_m;
  const double th1 = r.entry_angle_rad, th2 = r.exit_angle_rad;
  // K = 0.1 um: tau reaches c within a few K of the entry point.
  EXPECT_NEAR(r.torque_Nm, c * b * R * R * (th1 - th2), 1e-3 * r.torque_Nm);
  EXPECT_NEAR(r.thrust_N, c * b * R * (std::sin(th1) - std::sin(th2)), 1e-3 * r.thrust_N);
}

TEST(RigidWheel, DrawbarPullRisesWithSlipAndBrakingReversesIt) {
  const GroundSettings g = lete(1.3, 31.1, 12);
  double last = -1e300;
  for (double s : {0.05, 0.1, 0.2, 0.3, 0.4}) {
    const RigidWheelResult r = rigid_wheel_rolling(g, kWheel, 3000, s);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_GT(r.drawbar_pull_N, last) << s;
    EXPECT_GT(r.torque_Nm, 0) << s;
    EXPECT_NEAR(r.vertical_N, 3000, 1e-8 * 3000);
    last = r.drawbar_pull_N;
  }
  const RigidWheelResult braked = rigid_wheel_rolling(g, kWheel, 3000, -0.3);
  ASSERT_TRUE(braked.ok());
  EXPECT_LT(braked.drawbar_pull_N, 0);
  EXPECT_LT(braked.torque_Nm, 0);
}

TEST(RigidWheel, ASecondPassSinksLessAndTheRutIsNoDeeperThanTheSinkage) {
  GroundSettings g = lete(1.3, 31.1, 12);
  for (bool elastic : {false, true}) {
    // A_u such that Wong's k_u exceeds the secant at this sinkage (a partial rebound).
    if (elastic) g.bekker.unloading = WongUnloading{0, 5e6};
    const RigidWheelResult first = rigid_wheel_rolling(g, kWheel, 3000, 0.1);
    ASSERT_TRUE(first.ok());
    const RigidWheelResult second = rigid_wheel_rolling(g, kWheel, 3000, 0.1, first.z_max_m);
    ASSERT_TRUE(second.ok()) << second.message;
    EXPECT_LE(first.rut_depth_m, first.sinkage_m);
    EXPECT_LE(second.rut_depth_m, second.sinkage_m);
    EXPECT_GT(second.sinkage_m, first.rut_depth_m);
    EXPECT_LT(second.sinkage_m - first.sinkage_m, first.sinkage_m) << elastic;
    EXPECT_LT(second.motion_resistance_N, first.motion_resistance_N) << elastic;
    if (elastic) {
      EXPECT_LT(first.exit_angle_rad, 0);  // rebound behind the wheel
      EXPECT_LT(first.rut_depth_m, first.sinkage_m);
    }
  }
}

}  // namespace
}  // namespace modaltyre::ground

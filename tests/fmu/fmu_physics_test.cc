// The FMU's physics through its fmi2 functions (the dlopen'ed library of a packed FMU): the
// press against the static footprint, free rolling against the transient's rolling scenario,
// braking against the brush's limits and the model's own slip stiffness. configs/
// sf350_2d_table3.yaml (the 2D transient), 1 ms communication steps.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <vector>

#include "fmu_host.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/transient/driver.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::fmu::test {
namespace {

const std::string kPhysicsConfig =
    std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
constexpr double kStep_s = 1e-3;
constexpr double kLoad_N = 4000;

const transient::TransientModel& model() {
  static const transient::TransientModel m = transient::build_transient_model(
      contact::build_tyre_model(contact::load_tyre_config(kPhysicsConfig)));
  return m;
}

double R0() { return model().tyre.config.outer_radius_m; }

// The press (issue 34: within 1 % of footprint's load at the sinking). The hub is lowered
// from touching to R0 - delta in 50 ms, then held 0.45 s.
constexpr double kPressTolerance = 0.01;

TEST(FmuPhysics, PressSettlesToTheFootprintsLoadAtTheSinking) {
  const contact::Prediction p =
      contact::predict(model().tyre, model().tyre.config.default_conditions(kLoad_N));
  ASSERT_TRUE(p.ok());
  const double delta = p.sinking_mm * 1e-3;
  FmuInstance f(road_2d_fmu());
  ASSERT_TRUE(f.ok());
  f.set_wheel(0, R0(), 0, 0, 0, 0);
  ASSERT_EQ(f.initialize(), fmi2OK);
  EXPECT_NEAR(f.get("wheel_load.force.z"), 0, 1e-6);
  const double ramp = 0.05, v = -delta / ramp;
  for (int k = 0; k < 500; ++k) {
    const double t = k * kStep_s;
    const bool moving = t < ramp - 1e-12;
    f.set_wheel(0, R0() + (moving ? v * t : -delta), 0, moving ? v : 0, 0, 0);
    ASSERT_EQ(f.step(kStep_s), fmi2OK) << (f.messages().empty() ? "" : f.messages().back());
  }
  EXPECT_NEAR(f.get("wheel_load.force.z"), kLoad_N, kPressTolerance * kLoad_N);
  std::cout << "press to the footprint's sinking " << delta * 1e3 << " mm at " << kLoad_N
            << " N: F_z " << f.get("wheel_load.force.z") << " N\n";
  EXPECT_NEAR(f.get("tyre.deflection"), delta, 1e-3 * delta);
  EXPECT_NEAR(f.get("wheel_load.force.x"), 0, 1e-6 * kLoad_N);  // standing: no shear
}

/// A wheel rolling under a constant vertical load: the host's hub (20 kg, the transient's
/// hub mass) carries kLoad_N on the tyre, and the wheel spins freely under the tyre's moment
/// (inertia `inertia`) unless `spin_of` prescribes it. Speed ramps by smoothstep over
/// ramp_s as in the rolling scenario.
struct Rolling {
  double speed = 60 / 3.6, ramp_s = 1.0, inertia = 1.0;
  double z = 0, w = 0, x = 0, angle = 0, spin = 0;
  std::vector<double> fx, fz, my, slip;
};

void roll(FmuInstance& f, Rolling& r, double until_s,
          const std::function<double(double)>& spin_of = {}) {
  const double m = 20, c = 2000;  // hub mass and a damper that settles the hub bounce
  while (f.time() < until_s - 1e-9) {
    const double t = f.time();
    const double s = std::min(t / r.ramp_s, 1.0);
    const double v = r.speed * s * s * (3 - 2 * s);
    if (spin_of) r.spin = spin_of(v);
    f.set_wheel(r.x, r.z, v, r.w, r.angle, r.spin);
    ASSERT_EQ(f.step(kStep_s), fmi2OK) << (f.messages().empty() ? "" : f.messages().back());
    const double Fz = f.get("wheel_load.force.z"), Fx = f.get("wheel_load.force.x");
    const double My = f.get("wheel_load.moment.y");
    r.w += kStep_s * ((Fz - kLoad_N) / m - c * r.w / m);
    r.z += kStep_s * r.w;
    if (!spin_of) r.spin += kStep_s * My / r.inertia;
    r.angle += kStep_s * r.spin;
    r.x += kStep_s * v;
    r.fx.push_back(Fx);
    r.fz.push_back(Fz);
    r.my.push_back(My);
    r.slip.push_back(f.get("tyre.slip_ratio"));
  }
}

double mean_tail(const std::vector<double>& v, std::size_t n) {
  double s = 0;
  for (std::size_t k = v.size() - n; k < v.size(); ++k) s += v[k];
  return s / n;
}

TEST(FmuPhysics, FreeRollingGivesTheRollingScenariosResistance) {
  const transient::TransientResult ref =
      transient::run_transient(model(), transient::Scenario::rolling);
  ASSERT_TRUE(ref.ok()) << ref.message;
  const double rr_over_load = ref.rolling_resistance_N / model().settings.rolling.load_N;
  const contact::Prediction p =
      contact::predict(model().tyre, model().tyre.config.default_conditions(kLoad_N));
  FmuInstance f(road_2d_fmu());
  Rolling r;
  r.z = R0() - p.sinking_mm * 1e-3;
  f.set_wheel(0, r.z, 0, 0, 0, 0);
  ASSERT_EQ(f.initialize(), fmi2OK);
  roll(f, r, 3.0);
  const std::size_t tail = 300;  // the last 10 %, as the scenario's rolling resistance
  const double Fx = mean_tail(r.fx, tail), Fz = mean_tail(r.fz, tail);
  EXPECT_NEAR(Fz, kLoad_N, 0.002 * kLoad_N);                     // the host's load control holds
  EXPECT_NEAR(mean_tail(r.my, tail), 0, 1e-3 * kLoad_N * R0());  // free rolling: M_y = 0
  // Issue 34: F_x / F_z within 5 % of the rolling scenario's rolling resistance over load.
  EXPECT_NEAR(-Fx / Fz, rr_over_load, 0.05 * rr_over_load)
      << "FMU " << -Fx / Fz << " scenario " << rr_over_load;
  std::cout << "free rolling at 60 km/h: FMU Fx/Fz " << -Fx / Fz << ", rolling scenario "
            << rr_over_load << ", slip " << mean_tail(r.slip, tail) << "\n";
}

// Braking at 30 km/h and 4 kN: after free rolling (its spin gives the effective rolling radius
// R_e = V / Omega_free, SAE's reference for the slip), the spin is held at V (1 + kappa) / R_e
// for 0.3 s per slip. The brush's limits: |F_x| rises with the slip and saturates at mu F_z;
// its slope at small slip is 2 c_px a^2 for the model's tread (c_px = k_t / ds) and patch
// (a = half the contact length), whatever the pressure distribution.
constexpr double kMu = 0.8;
/// The slope is a finite difference over kappa = -0.005 and the patch length the transient's
/// edge interpolation: 10 % covers both.
constexpr double kSlipStiffnessTolerance = 0.10;

TEST(FmuPhysics, BrakingForceRisesWithSlipAndSaturatesAtMuFz) {
  const contact::Prediction p =
      contact::predict(model().tyre, model().tyre.config.default_conditions(kLoad_N));
  FmuInstance f(road_2d_fmu());
  Rolling r;
  r.speed = 30 / 3.6;
  r.ramp_s = 0.5;
  r.z = R0() - p.sinking_mm * 1e-3;
  f.set_wheel(0, r.z, 0, 0, 0, 0);
  ASSERT_EQ(f.initialize(), fmi2OK);
  roll(f, r, 1.5);
  const std::size_t tail = 200;
  const double Re = r.speed / r.spin;
  const double fx_free = mean_tail(r.fx, tail);
  const double length = f.get("tyre.contact_length");
  std::vector<double> kappas = {-0.005, -0.02, -0.05, -0.1, -0.2, -0.3}, Fx, Fz;
  double until = 1.5;
  for (double kappa : kappas) {
    until += 0.3;
    const std::size_t before = r.fx.size();
    roll(f, r, until, [&](double v) { return v * (1 + kappa) / Re; });
    ASSERT_GT(r.fx.size(), before + 100);
    Fx.push_back(mean_tail(r.fx, 100));
    Fz.push_back(mean_tail(r.fz, 100));
  }
  for (std::size_t k = 0; k < kappas.size(); ++k) {
    std::cout << "kappa " << kappas[k] << ": Fx " << Fx[k] << " N, Fz " << Fz[k] << " N\n";
    EXPECT_LE(std::abs(Fx[k]), kMu * Fz[k] * 1.001) << kappas[k];
    if (k > 0) {
      EXPECT_GT(std::abs(Fx[k]), std::abs(Fx[k - 1])) << kappas[k];
    }
  }
  EXPECT_GT(std::abs(Fx.back()), 0.9 * kMu * Fz.back());  // saturated
  const double c_kappa = (Fx[0] - fx_free) / kappas[0];
  const transient::TransientModel& M = model();
  const double cpx = M.tyre.k_tangential_N_m / M.tyre.unit_length_m;
  const double brush = 2 * cpx * 0.25 * length * length;
  std::cout << "C_kappa " << c_kappa << " N (brush 2 c_px a^2 " << brush << " N, contact length "
            << length * 1e3 << " mm), C_kappa / Fz " << c_kappa / kLoad_N << ", R_e " << Re
            << " m\n";
  EXPECT_NEAR(c_kappa, brush, kSlipStiffnessTolerance * brush);
}

/// A quarter-car (a quarter of a 1200 kg car: sprung 300 kg, unsprung 35 kg, 25 kN/m,
/// 2 kN s/m; wheel inertia 0.9 kg m^2, spinning freely) at 30 km/h over a raised-cosine cleat
/// 10 mm high and 20 mm long given as the road_profile, 1 ms communication steps: the host's
/// co-simulation of examples/fmu/quarter_car.py.
struct QuarterCar {
  std::vector<double> t, fz, zu;
};

QuarterCar quarter_car(FmuInstance& f, const std::string& profile, double duration) {
  const double h = kStep_s, g = 9.81, ms = 300, mu = 35, ks = 25e3, cs = 2e3, Iw = 0.9;
  const double speed = 30 / 3.6;
  f.set("step_size", h);
  const fmi2ValueReference r = road_2d_fmu().vr("road_profile");
  const fmi2String p = profile.c_str();
  EXPECT_EQ(road_2d_fmu().api().set_string(f.component(), &r, 1, &p), fmi2OK);
  // Start at the static equilibrium: the tyre at its footprint's sinking under the car's
  // weight, the suspension compressed by the body's.
  const contact::Prediction p0 =
      contact::predict(model().tyre, model().tyre.config.default_conditions((ms + mu) * g));
  double zu = R0() - p0.sinking_mm * 1e-3, wu = 0, zs = zu + 0.35 - ms * g / ks, ws = 0;
  double x = 0, angle = 0;
  double spin = speed / R0();
  f.set_wheel(x, zu, speed, wu, angle, spin);
  QuarterCar q;
  EXPECT_EQ(f.initialize(), fmi2OK) << (f.messages().empty() ? "" : f.messages().back());
  while (f.time() < duration - 1e-9) {
    f.set_wheel(x, zu, speed, wu, angle, spin);
    if (f.step(h) != fmi2OK) {
      ADD_FAILURE() << (f.messages().empty() ? "" : f.messages().back());
      return q;
    }
    const double fz = f.get("wheel_load.force.z"), my = f.get("wheel_load.moment.y");
    const double fsusp = ks * (zs - zu - 0.35) + cs * (ws - wu);
    ws += h * (-fsusp / ms - g);
    wu += h * ((fsusp + fz) / mu - g);
    zs += h * ws;
    zu += h * wu;
    spin += h * my / Iw;
    angle += h * spin;
    x += h * speed;
    q.t.push_back(f.time());
    q.fz.push_back(fz);
    q.zu.push_back(zu);
  }
  return q;
}

std::string cleat_profile(double x_centre) {
  const std::string path = road_2d_fmu().folder() + "/cleat_test.csv";
  std::ofstream out(path);
  out << "x_m,height_m\n-1000,0\n";
  const double H = 0.01, L = 0.02, edge = L / 4;
  for (double x = x_centre - L / 2; x <= x_centre + L / 2 + 1e-12; x += 0.5e-3) {
    const double d = std::abs(x - x_centre);
    out << x << "," << (d <= L / 2 - edge ? H : 0.5 * H * (1 - std::cos(M_PI * (L / 2 - d) / edge)))
        << "\n";
  }
  out << "1000,0\n";
  return path;
}

// After the cleat the car settles: the tyre carries the car's weight again, the wheel centre
// returns to where it stood before the cleat (equilibrium within the suspension's decay: the
// body mode at 1.4 Hz with 0.23 damping ratio decays by e^-2 per second).
constexpr double kSettledLoadTolerance = 0.01;

TEST(FmuPhysics, QuarterCarOverACleatSettlesBackToStaticEquilibrium) {
  const double speed = 30 / 3.6, t_cleat = 0.6;
  const std::string profile = cleat_profile(speed * t_cleat);
  FmuInstance a(road_2d_fmu(), "car a"), b(road_2d_fmu(), "car b");
  const QuarterCar qa = quarter_car(a, profile, 3.0);
  ASSERT_EQ(qa.t.size(), 3000u);
  const double weight = (300 + 35) * 9.81;
  auto mean = [](const std::vector<double>& v, double from, double to,
                 const std::vector<double>& t) {
    double s = 0;
    int n = 0;
    for (std::size_t k = 0; k < v.size(); ++k)
      if (t[k] >= from && t[k] < to) s += v[k], ++n;
    return s / n;
  };
  const double before = mean(qa.fz, 0.45, 0.55, qa.t), after = mean(qa.fz, 2.8, 3.0, qa.t);
  double peak = 0;
  for (double v : qa.fz) peak = std::max(peak, v);
  std::cout << "quarter car: static " << weight << " N, before the cleat " << before << " N, peak "
            << peak << " N, after " << after << " N; wheel centre before "
            << mean(qa.zu, 0.45, 0.55, qa.t) * 1e3 << " mm, after "
            << mean(qa.zu, 2.8, 3.0, qa.t) * 1e3 << " mm\n";
  // The cleat is felt: the transient's own cleat scenario (10 x 20 mm at 30 km/h, 4 kN) peaks
  // 19 % over its load (docs/transient.md, 4767 N).
  EXPECT_GT(peak, 1.1 * weight);
  EXPECT_NEAR(before, weight, kSettledLoadTolerance * weight);
  EXPECT_NEAR(after, weight, kSettledLoadTolerance * weight);
  // The wheel centre back where it rolled before the cleat (to 10 um: the body's residual
  // motion after 2.4 s of decay and the rolling tyre's own settling).
  EXPECT_NEAR(mean(qa.zu, 2.8, 3.0, qa.t), mean(qa.zu, 0.45, 0.55, qa.t), 1e-5);
  // A second instance in the same process gives the same run, bit for bit.
  const QuarterCar qb = quarter_car(b, profile, 3.0);
  EXPECT_EQ(qa.fz, qb.fz);
}

}  // namespace
}  // namespace modaltyre::fmu::test

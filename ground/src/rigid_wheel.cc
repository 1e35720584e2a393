#include "modaltyre/ground/rigid_wheel.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "modaltyre/solvers/bracketed_root.h"

namespace modaltyre::ground {
namespace {

// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n from Chebyshev starting points).
struct Gauss {
  std::vector<double> x, w;
};

const Gauss& gauss8() {
  static const Gauss g = [] {
    const int n = 8;
    Gauss out;
    for (int i = 0; i < n; ++i) {
      double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = x;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
          p0 = p1, p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1);
        const double step = p1 / dp;
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
      out.x.push_back(0.5 * (1 - x));
      out.w.push_back(1.0 / ((1 - x * x) * dp * dp));  // (2 / ((1-x^2) P'^2)) / 2
    }
    return out;
  }();
  return g;
}

struct Node {
  double theta, weight;
};

// Nodes on [lo, hi] with theta = hi - (hi - lo) u^2 (clustered at hi, where the loading
// stress rises from zero as a power of the distance), or at lo (`at_lo`: Wong and Reece's rear
// region, whose stress falls to zero there as the front's mirror).
void add_segment(std::vector<Node>& nodes, double lo, double hi, int panels, bool at_lo = false) {
  if (!(hi > lo)) return;
  const Gauss& g = gauss8();
  for (int p = 0; p < panels; ++p) {
    for (std::size_t k = 0; k < g.x.size(); ++k) {
      const double u = (p + g.x[k]) / panels, w = g.w[k] / panels * 2 * (hi - lo) * u;
      nodes.push_back({at_lo ? lo + (hi - lo) * u * u : hi - (hi - lo) * u * u, w});
    }
  }
}

double angle_at_depth(double R, double depth_below_lowest) {
  return std::acos(std::clamp(1 - depth_below_lowest / R, -1.0, 1.0));
}

}  // namespace

double speed_ratio(double slip) { return slip >= 0 ? 1 - slip : 1 / (1 + slip); }

RigidWheelResult rigid_wheel_at_sinkage(const PressureSinkage& law, const ShearLaw& shear,
                                        const RigidWheel& wheel, double z0, double slip,
                                        double prior, bool rolling, const WongReeceStress& wr,
                                        int panels) {
  RigidWheelResult r;
  r.slip = slip;
  r.sinkage_m = z0;
  r.status = SolveStatus::converged;
  const double R = wheel.radius_m, bw = wheel.width_m;
  const double surface = prior > 0 ? law.rebound_depth_m(prior) : 0.0;
  r.z_max_m = std::max(prior, z0);
  r.rut_depth_m = law.rebound_depth_m(r.z_max_m);
  if (!(z0 > surface)) return r;  // not touching the incoming surface
  const double theta1 = angle_at_depth(R, z0 - surface);
  r.entry_angle_rad = theta1;
  std::vector<Node> nodes;
  // Wong and Reece's distribution (soil_options.h): the front's loading stress from theta1 down
  // to theta_m, its mirror image on [theta2, theta_m]; otherwise the front down to the lowest
  // point and the memory's unloading branch behind it.
  const bool wong_reece = rolling && wr.enabled;
  const double theta_m = wong_reece ? wr.peak_ratio(slip) * theta1 : 0.0;
  // Front: a kink (elastic reload) or a jump (rigid-plastic) where z passes the prior z_max.
  const double tp = prior > surface && prior < z0 ? angle_at_depth(R, z0 - prior) : -1.0;
  if (tp > theta_m) {
    add_segment(nodes, tp, theta1, panels);
    add_segment(nodes, theta_m, tp, panels);
  } else {
    add_segment(nodes, theta_m, theta1, panels);
  }
  double theta2 = -theta1;
  // The rear region's angle theta maps onto the front's theta1 - (theta - theta2) q.
  double q = 0;
  if (wong_reece) {
    theta2 = wr.c3 > 0 ? -wr.c3 * theta1 : 0.0;
    q = theta_m > theta2 ? (theta1 - theta_m) / (theta_m - theta2) : 0.0;
    if (!(q > 0)) {
      // theta_m = theta2 = 0: no rear region
    } else if (tp > theta_m) {
      const double tp_rear = theta2 + (theta1 - tp) / q;  // the front's jump, mirrored
      add_segment(nodes, theta2, tp_rear, panels, true);
      add_segment(nodes, tp_rear, theta_m, panels, true);
    } else {
      add_segment(nodes, theta2, theta_m, panels, true);
    }
  } else if (rolling) {
    theta2 = z0 > r.rut_depth_m ? -angle_at_depth(R, z0 - r.rut_depth_m) : 0.0;
    add_segment(nodes, theta2, 0, panels);
  }
  r.exit_angle_rad = theta2;
  r.contact_length_m = R * (std::sin(theta1) - std::sin(theta2));
  std::sort(nodes.begin(), nodes.end(),
            [](const Node& a, const Node& b) { return a.theta > b.theta; });
  const double rho = speed_ratio(slip);
  auto j_at = [&](double th) {
    return R * ((theta1 - th) - rho * (std::sin(theta1) - std::sin(th)));
  };
  ShearPoint point;
  double j_prev = 0;
  double W = 0, H = 0, Rc = 0, T = 0;
  auto front_stress = [&](double th) {
    const double z = z0 - R * (1 - std::cos(th));
    return law.pressure_Pa(z, std::max(prior, z));
  };
  for (const Node& n : nodes) {
    double sigma = 0;
    if (wong_reece) {
      sigma = front_stress(n.theta >= theta_m ? n.theta : theta1 - (n.theta - theta2) * q);
    } else {
      const double z = z0 - R * (1 - std::cos(n.theta));
      sigma = n.theta >= 0 ? front_stress(n.theta) : law.pressure_Pa(z, r.z_max_m);
    }
    double tau = 0;
    if (rolling) {
      const double j = j_at(n.theta);
      tau = shear.advance(point, sigma, j - j_prev);
      j_prev = j;
    }
    const double c = std::cos(n.theta), s = std::sin(n.theta);
    W += n.weight * (sigma * c + tau * s);
    H += n.weight * tau * c;
    Rc += n.weight * sigma * s;
    T += n.weight * tau;
  }
  const double scale = bw * R * (rolling ? 1.0 : 2.0);
  r.vertical_N = scale * W;
  r.load_N = r.vertical_N;
  if (rolling) {
    r.thrust_N = scale * H;
    r.motion_resistance_N = scale * Rc;
    r.drawbar_pull_N = r.thrust_N - r.motion_resistance_N;
    r.torque_Nm = scale * R * T;
  }
  return r;
}

namespace {

// Vertical equilibrium at a fixed Bekker width: the sinkage z0 with W(z0) = load.
RigidWheelResult solve_sinkage(const PressureSinkage& law, const ShearLaw& shear,
                               const RigidWheel& wheel, double load_N, double slip, double prior,
                               bool rolling, const WongReeceStress& wr) {
  const double surface = prior > 0 ? law.rebound_depth_m(prior) : 0.0;
  const double R = wheel.radius_m;
  auto W = [&](double z0) {
    return rigid_wheel_at_sinkage(law, shear, wheel, z0, slip, prior, rolling, wr).vertical_N;
  };
  // The wheel may not sink beyond 80 degrees of contact (its axle would plough).
  const double deepest = surface + R * (1 - std::cos(80 * M_PI / 180));
  double lo = surface, flo = -load_N, hi = surface + 1e-6 * R, fhi = W(hi) - load_N;
  while (fhi <= 0 && hi < deepest) {
    lo = hi, flo = fhi;
    hi = std::min(deepest, surface + 2 * (hi - surface));
    fhi = W(hi) - load_N;
  }
  RigidWheelResult fail;
  fail.load_N = load_N;
  fail.slip = slip;
  if (!(fhi > 0)) {
    std::ostringstream msg;
    msg << "the rigid wheel does not carry " << load_N << " N before its contact reaches 80 deg "
        << "(sinkage " << (deepest * 1e3) << " mm): the soil is too soft for this load";
    fail.message = msg.str();
    return fail;
  }
  solvers::IllinoisOptions opt;
  opt.tolerance = 1e-10 * load_N;
  opt.max_iterations = 200;
  const solvers::RootResult root = solvers::illinois_root(
      [&](double z0) -> std::optional<double> { return W(z0) - load_N; }, lo, flo, hi, fhi, opt);
  if (!root.ok()) {
    fail.status = root.status;
    std::ostringstream msg;
    msg << "rigid wheel: vertical equilibrium not reached (residual " << root.fx << " N)";
    fail.message = msg.str();
    return fail;
  }
  RigidWheelResult r = rigid_wheel_at_sinkage(law, shear, wheel, root.x, slip, prior, rolling, wr);
  r.load_N = load_N;
  r.message = "converged";
  return r;
}

RigidWheelResult solve_wheel(const GroundSettings& ground, const RigidWheel& wheel, double load_N,
                             double slip, double prior, bool rolling) {
  RigidWheelResult bad;
  bad.load_N = load_N;
  bad.slip = slip;
  if (!ground.soil()) {
    bad.message = "the rigid wheel needs a soil (ground.model bekker or kelvin_voigt)";
    return bad;
  }
  if (!(load_N > 0) || !(wheel.radius_m > 0) || !(wheel.width_m > 0) || !(slip > -1) ||
      !(slip <= 1) || !(prior >= 0)) {
    bad.message = "rigid wheel: load, radius and width must be > 0, slip in (-1, 1]";
    return bad;
  }
  if (rolling && ground.wong_reece.enabled) {
    try {
      ground.wong_reece.validate();
    } catch (const std::invalid_argument& e) {
      bad.message = e.what();
      return bad;
    }
  }
  const JanosiHanamoto shear(ground.soil_shear());
  auto at_width = [&](double b) {
    const auto law = ground.normal_law(b, rolling ? slip : 0.0);
    RigidWheelResult r =
        solve_sinkage(*law, shear, wheel, load_N, slip, prior, rolling, ground.wong_reece);
    r.bekker_width_m = b;
    return r;
  };
  RigidWheelResult full = at_width(wheel.width_m);
  // Bekker's b is the smaller side of the contact: b = min(width, length) as a fixed point. Only
  // k_c / b depends on it.
  const bool b_acts = ground.model == GroundModel::bekker && ground.bekker.k_c > 0;
  if (!full.ok() || !b_acts || full.contact_length_m >= wheel.width_m) return full;
  // L(b) grows with b (a softer soil sinks deeper); g(b) = L(b) - b < 0 at the width, > 0 as
  // b -> 0 (L ~ b^(1/(2n+1))).
  double hi = wheel.width_m, ghi = full.contact_length_m - hi;
  double lo = full.contact_length_m;
  RigidWheelResult at_lo = at_width(lo);
  double glo = at_lo.contact_length_m - lo;
  for (int k = 0; k < 60 && at_lo.ok() && glo <= 0; ++k) {
    hi = lo, ghi = glo;
    lo *= 0.5;
    at_lo = at_width(lo);
    glo = at_lo.contact_length_m - lo;
  }
  if (!at_lo.ok()) return at_lo;
  if (!(glo > 0)) {
    bad.message = "rigid wheel: Bekker's width b = contact length has no solution";
    return bad;
  }
  RigidWheelResult last;
  solvers::IllinoisOptions opt;
  opt.tolerance = 1e-9 * wheel.width_m;
  const solvers::RootResult root = solvers::illinois_root(
      [&](double b) -> std::optional<double> {
        last = at_width(b);
        if (!last.ok()) return std::nullopt;
        return last.contact_length_m - b;
      },
      lo, glo, hi, ghi, opt);
  if (!root.ok()) {
    if (!last.ok()) return last;
    bad.message = "rigid wheel: Bekker's width b = contact length did not converge";
    return bad;
  }
  return at_width(root.x);
}

}  // namespace

RigidWheelResult rigid_wheel_static(const GroundSettings& ground, const RigidWheel& wheel,
                                    double load_N, double prior_z_max_m) {
  return solve_wheel(ground, wheel, load_N, 0.0, prior_z_max_m, false);
}

RigidWheelResult rigid_wheel_rolling(const GroundSettings& ground, const RigidWheel& wheel,
                                     double load_N, double slip, double prior_z_max_m) {
  return solve_wheel(ground, wheel, load_N, slip, prior_z_max_m, true);
}

}  // namespace modaltyre::ground

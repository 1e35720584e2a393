#include "modaltyre/transient/soil_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/ground_patch.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::transient {
namespace {

/// The series root is solved until its residual in the penetration is below this share of g:
/// 1e-13 of a 10 mm penetration is 1e-15 m, a force error of ~1e-9 N on a tread spring of
/// 1e6 N/m, far below the integrator's tolerances (0.1 um on displacements).
constexpr double kRootTolerance = 1e-13;
/// Safeguarded Newton steps before giving up on quadratic convergence (bisection guarantees
/// progress; 200 halvings reach any double's resolution).
constexpr int kMaxRootIterations = 200;
/// A viscous soil's surface counts as frozen over a step when 1 - w is below this (the step is
/// below 1e-12 of eta2 / E2): the tread spring alone on the surface of the last accepted step.
constexpr double kFrozenSurface = 1e-12;

/// The Kelvin-Voigt soil's time constant eta2 / E2 [s] (seed 000 eq. 23), 0 for another soil.
double soil_time_constant_s(const ground::GroundSettings& g) {
  if (g.model != ground::GroundModel::kelvin_voigt) return 0.0;
  return g.kelvin_voigt.eta2_kPa_s * 1e3 / (g.kelvin_voigt.E2_MPa * 1e6);
}

}  // namespace

namespace {

Eigen::VectorXd unit_areas(const TransientModel& M, double width_m) {
  if (!(width_m > 0)) throw std::invalid_argument("SoilContact: contact width must be positive");
  Eigen::VectorXd a(M.m);
  for (int i = 0; i < M.m; ++i) a(i) = width_m * M.tyre.unit_length_m * std::cos(M.tyre.theta[i]);
  return a;
}

}  // namespace

SoilContact::SoilContact(const TransientModel& M, const ground::GroundSettings& ground,
                         double width_m, double bekker_width_m,
                         std::function<double(double)> distance)
    : SoilContact(ground, unit_areas(M, width_m), M.k_contact, M.x_road, bekker_width_m,
                  std::move(distance)) {}

SoilContact::SoilContact(const ground::GroundSettings& ground, Eigen::VectorXd area_m2,
                         Eigen::VectorXd k_N_m, Eigen::VectorXd x_m, double bekker_width_m,
                         std::function<double(double)> distance)
    : law_(ground.normal_law(bekker_width_m)),
      area_(std::move(area_m2)),
      k_(std::move(k_N_m)),
      x_(std::move(x_m)),
      tau_s_(soil_time_constant_s(ground)),
      distance_(std::move(distance)),
      bekker_width_m_(bekker_width_m) {
  const int m = static_cast<int>(area_.size());
  if (k_.size() != m || x_.size() != m || !(area_.array() > 0).all())
    throw std::invalid_argument("SoilContact: one positive area, spring and x per contact");
  z_max_.setZero(m);
  depth_acc_.setZero(m);
  depth_acc_prev_.setZero(m);
  surface_.setZero(m);
  surface_prev_.setZero(m);
  stiffness_.setZero(m);
  depth_.setZero(m);
  pressure_.setZero(m);
}

void SoilContact::set_memory(const Eigen::VectorXd& z_max_m, double t) {
  if (z_max_m.size() != z_max_.size())
    throw std::invalid_argument("SoilContact: one z_max per unit");
  z_max_ = z_max_m.cwiseMax(0.0);
  z_max_prev_ = z_max_;
  depth_acc_ = depth_acc_prev_ = z_max_;  // at rest under its load the soil stands at z_max
  surface_ = surface_prev_ = z_max_;      // a static contact: the soil at rest under its load
  distance_acc_ = distance_prev_ = distance_ ? distance_(t) : 0.0;
  t_accepted_ = t_accepted_prev_ = t;
}

const Eigen::VectorXd& SoilContact::surface(double t, double& w) const {
  const bool prev = t < t_accepted_;
  const double h = std::max(0.0, t - (prev ? t_accepted_prev_ : t_accepted_));
  w = tau_s_ > 0 ? std::exp(-h / tau_s_) : 0.0;
  return prev ? surface_prev_ : surface_;
}

const Eigen::VectorXd& SoilContact::memory(double t, double& shift,
                                           const Eigen::VectorXd** depths) const {
  const double D = distance_ ? distance_(t) : 0.0;
  const bool prev = t < t_accepted_;
  shift = distance_ ? D - (prev ? distance_prev_ : distance_acc_) : 0.0;
  if (depths) *depths = prev ? &depth_acc_prev_ : &depth_acc_;
  return prev ? z_max_prev_ : z_max_;
}

double SoilContact::swept_memory_at(const Eigen::VectorXd& zm, const Eigen::VectorXd& depths, int i,
                                    double shift) const {
  if (shift == 0.0) return zm(i);
  // One walk from i to the ground point's position at the recording, X = x_i + shift: the units
  // strictly between are the depths it passed over since (with its own unit's), the bracket of X
  // the recorded memory read there (memory_at's interpolation, virgin soil ahead of the front).
  const int m = static_cast<int>(x_.size());
  const double X = x_(i) + shift;
  double swept = depths(i);
  int j = i;
  if (shift > 0) {
    while (j + 1 < m && x_(j + 1) <= X) {
      ++j;
      if (x_(j) < X) swept = std::max(swept, depths(j));
    }
    if (j == m - 1) return std::max(X > x_(m - 1) ? 0.0 : zm(m - 1), swept);
  } else {
    while (j > 0 && x_(j) > X) {
      --j;
      if (x_(j) > X) swept = std::max(swept, depths(j));
    }
    if (X <= x_(0)) return std::max(zm(0), swept);
  }
  const double w = (X - x_(j)) / (x_(j + 1) - x_(j));
  return std::max((1 - w) * zm(j) + w * zm(j + 1), swept);
}

double SoilContact::memory_at(const Eigen::VectorXd& zm, int i, double shift) const {
  if (shift == 0.0) return zm(i);
  const int m = static_cast<int>(x_.size());
  const double X = x_(i) + shift;
  if (X >= x_(m - 1)) return X > x_(m - 1) ? 0.0 : zm(m - 1);  // ahead: virgin soil
  if (X <= x_(0)) return zm(0);
  // Walk from i over the step's travel (tens of units at 60 km/h).
  int j = i;
  while (j + 1 < m && x_(j + 1) <= X) ++j;
  while (j > 0 && x_(j) > X) --j;
  const double w = (X - x_(j)) / (x_(j + 1) - x_(j));
  return (1 - w) * zm(j) + w * zm(j + 1);
}

double SoilContact::z_max_m(int i, double t) const {
  double s = 0;
  const Eigen::VectorXd* d = nullptr;
  const Eigen::VectorXd& zm = memory(t, s, &d);
  return swept_memory_at(zm, *d, i, s);
}

double SoilContact::rut_m(int i, double t) const {
  const double zm = z_max_m(i, t);
  const double rut = zm > 0 ? law_->rebound_depth_m(zm) : 0.0;
  if (!(tau_s_ > 0)) return rut;
  // A viscous soil recovers towards its rut with eta2 / E2 (soil_contact.h).
  double s = 0, w = 0;
  memory(t, s);
  const double za = memory_at(surface(t, w), i, s);
  return w * za + (1 - w) * rut;
}

double SoilContact::unit_force(int i, double g, double zm, double* dfdg, double* depth, double za,
                               double w) const {
  if (!(w > 0)) return elastic_force(i, g, zm, k_(i), dfdg, depth);
  const double k = k_(i), one_w = 1 - w;
  if (one_w < kFrozenSurface) {  // the surface of the last accepted step, the tread spring alone
    *depth = za;
    *dfdg = g > za ? k : 0.0;
    pressure_(i) = g > za ? k * (g - za) / area_(i) : 0.0;
    return pressure_(i) * area_(i);
  }
  // Z(p; t) = w z_a + (1 - w) Z_el(p): the elastic root with k (1 - w) at (g - w z_a) / (1 - w).
  double d = 0, z = 0;
  const double f = elastic_force(i, (g - w * za) / one_w, zm, k * one_w, &d, &z);
  *dfdg = d / one_w;
  *depth = w * za + one_w * z;
  return f;
}

double SoilContact::elastic_force(int i, double g, double zm, double k, double* dfdg,
                                  double* depth) const {
  const ground::PressureSinkage& L = *law_;
  const double A = area_(i);
  const double rut = zm > 0 ? L.rebound_depth_m(zm) : 0.0;
  if (!(g > rut)) {
    *dfdg = 0;
    *depth = rut;
    pressure_(i) = 0;
    return 0;
  }
  // h(p) = A p / k + Z(p) - g, increasing in p; the root lies in [0, k (g - rut) / A] since
  // Z >= rut. The branch is known from h at the memory's virgin pressure.
  double lo = 0, hi = k * (g - rut) / A;
  bool virgin = true;
  if (zm > 0) {
    const double pv = L.loading_Pa(zm);
    if (A * pv / k + zm - g >= 0) {
      virgin = false;
      hi = std::min(hi, pv);
      if (L.rigid_plastic()) {  // a vertical branch at z_max: the tread spring alone
        const double p = k * (g - zm) / A;
        *dfdg = k;
        *depth = zm;
        pressure_(i) = p;
        return p * A;
      }
    } else {
      lo = pv;
    }
  }
  auto Z = [&](double p) { return virgin ? L.loading_sinkage_m(p) : L.unloading_sinkage_m(p, zm); };
  double p = pressure_(i);
  if (!(p > lo && p < hi)) p = 0.5 * (lo + hi);
  const double tol = kRootTolerance * g;
  double dZ = 0, Zp = 0, p_of_Zp = -1;  // Z at p_of_Zp (the last evaluation, reused below)
  for (int it = 0; it < kMaxRootIterations; ++it) {
    Zp = Z(p), p_of_Zp = p;
    const double h = A * p / k + Zp - g;
    if (h > 0)
      hi = p;
    else
      lo = p;
    dZ = L.compliance_m_per_Pa(p, virgin ? 0.0 : zm);
    if (std::abs(h) <= tol || hi - lo <= 1e-15 * hi) break;
    double next = p - h / (A / k + dZ);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    p = next;
  }
  pressure_(i) = p;
  *depth = p == p_of_Zp ? Zp : Z(p);
  *dfdg = 1.0 / (1.0 / k + dZ / A);
  return p * A;
}

void SoilContact::forces(double t, int lo, int n, double* g) const {
  double s = 0, w = 0;
  const Eigen::VectorXd* swept = nullptr;
  const Eigen::VectorXd& zm = memory(t, s, &swept);
  const Eigen::VectorXd& za = surface(t, w);
  band_lo_ = lo, band_hi_ = lo + n - 1, t_forces_ = t;
  for (int k = 0; k < n; ++k) {
    const int i = lo + k;
    double d = 0, z = 0;
    g[k] = unit_force(i, g[k], swept_memory_at(zm, *swept, i, s), &d, &z,
                      w > 0 ? memory_at(za, i, s) : 0.0, w);
    stiffness_(i) = d;
    depth_(i) = z;
  }
}

double SoilContact::depth(int i) const {
  return i >= band_lo_ && i <= band_hi_ ? depth_(i) : rut_m(i, t_forces_);
}

double SoilContact::deepest_loaded_m(int lo, int hi, const Eigen::VectorXd& f) const {
  double deepest = 0;
  for (int i = lo; i <= hi; ++i)
    if (f(i) > 0) deepest = std::max(deepest, depth(i));
  return deepest;
}

double SoilContact::compaction_resistance_N(int lo, int hi, const Eigen::VectorXd& f) const {
  double R = 0;
  const int m = static_cast<int>(x_.size());
  for (int i = std::max(lo, 1); i <= std::min(hi, m - 2); ++i)
    if (f(i) > 0) R += f(i) * (depth(i - 1) - depth(i + 1)) / (x_(i + 1) - x_(i - 1));
  return R;
}

void SoilContact::accept(double t, int lo, int hi) {
  const int m = static_cast<int>(z_max_.size());
  // A viscous soil: every unit's surface at t, the evaluated units' from forces() (at t), the
  // others recovering towards their rut (before the memory moves: rut_m reads the last one).
  Eigen::VectorXd surface_now;
  if (tau_s_ > 0) {
    surface_now.resize(m);
    for (int i = 0; i < m; ++i) surface_now(i) = i >= lo && i <= hi ? depth_(i) : rut_m(i, t);
  }
  z_max_prev_ = z_max_;
  surface_prev_ = surface_;
  distance_prev_ = distance_acc_;
  t_accepted_prev_ = t_accepted_;
  t_accepted_ = t;
  const double s = distance_ ? distance_(t) - distance_acc_ : 0.0;
  if (s != 0.0) {
    // Move the memory with the ground (the units' own values read ahead of them, with the
    // depths each ground point passed over during the step).
    Eigen::VectorXd moved(m);
    for (int i = 0; i < m; ++i) moved(i) = swept_memory_at(z_max_prev_, depth_acc_, i, s);
    z_max_ = moved;
    distance_acc_ += s;
  }
  for (int i = lo; i <= hi; ++i) z_max_(i) = std::max(z_max_(i), depth_(i));
  // The depths of this accepted state (the units carrying no force stand at their rut, below
  // every depth a ground point passing them had reached, so 0 there).
  std::swap(depth_acc_prev_, depth_acc_);
  depth_acc_.setZero(m);
  for (int i = lo; i <= hi; ++i) depth_acc_(i) = depth_(i);
  if (tau_s_ > 0) {
    surface_ = surface_now;
    z_max_ = z_max_.cwiseMax(surface_);
  }
}

}  // namespace modaltyre::transient

namespace modaltyre::transient {

StaticContact static_soil_contact(const TransientModel& M, double load_N, double bekker_width_m,
                                  double* bekker_used) {
  StaticContact c{Eigen::VectorXd::Zero(M.m), 0.0, Eigen::VectorXd::Zero(M.m)};
  if (bekker_used) *bekker_used = bekker_width_m;
  if (load_N <= 0) return c;
  contact::GroundPatchInput in;
  in.bekker_width_m = bekker_width_m;
  in.fixed_bekker_width = bekker_width_m > 0;
  const contact::FootprintResult fr =
      contact::solve_ground_patch(M.tyre, contact::static_operator(M.tyre, 0.0),
                                  contact::LoadCase{load_N, 0}, M.tyre.config.ground, in);
  if (!fr.ok()) throw ComputationError("static contact on the soil: " + fr.message);
  std::size_t k = 0;
  for (int i = 0; i < M.m; ++i)
    if (fr.active[i]) c.f(i) = fr.units.at(k++).fz_N;
  c.sinking_m = fr.sinking_m;
  if (static_cast<int>(fr.soil_depth_m.size()) == M.m)
    c.soil_depth_m = Eigen::Map<const Eigen::VectorXd>(fr.soil_depth_m.data(), M.m);
  if (bekker_used) *bekker_used = fr.bekker_width_m;
  return c;
}

std::optional<StaticContact> bounding_soil_contact(const TransientModel& M,
                                                   const ScenarioPlan& plan,
                                                   const StaticContact& initial,
                                                   double bekker_width_m) {
  double F_max = std::max(plan.load(0.0), plan.load(plan.duration_s));
  for (double t : plan.breakpoints) F_max = std::max(F_max, plan.load(t));
  if (F_max <= plan.initial_load_N) return initial;
  try {
    return static_soil_contact(M, 2 * F_max - plan.initial_load_N, bekker_width_m);
  } catch (const ComputationError&) {
    return std::nullopt;
  }
}

std::unique_ptr<SoilContact> soil_for_plan(const TransientModel& M, const ScenarioPlan& plan,
                                           StaticContact& initial) {
  // Bekker's b (the smaller side of the loaded area) changes with the contact length; the run
  // keeps the static footprint's at the scenario's largest load (where the sinkage is made).
  double F_max = std::max({plan.load(0.0), plan.load(plan.duration_s), plan.initial_load_N});
  for (double t : plan.breakpoints) F_max = std::max(F_max, plan.load(t));
  double b = 0;
  static_soil_contact(M, F_max, 0.0, &b);
  const double width = M.tyre.config.tread.width_m;
  if (!(b > 0)) b = width;
  std::function<double(double)> distance;
  if (plan.speed_m_s != 0) distance = [&plan](double t) { return plan.distance(t); };
  auto soil = std::make_unique<SoilContact>(M, M.tyre.config.ground, width, b, distance);
  initial = static_soil_contact(M, plan.initial_load_N, b);
  soil->set_memory(initial.soil_depth_m, 0.0);
  return soil;
}

void refuse_on_soil(const TransientModel& model, Scenario scenario, bool cells) {
  const auto& config = model.tyre.config;
  if (cells && soil_time_constant_s(config.ground) > 0) {
    throw InputError(InputLocation{config.source, 0, "ground.kelvin_voigt.eta2_kPa_s"},
                     "the 3D patch's transient on the Kelvin-Voigt soil models its elastic law "
                     "only; set eta2_kPa_s to 0 or run a 2D config (docs/soil.md section 8.3)");
  }
  if (scenario == Scenario::cleat) {
    throw InputError(InputLocation{config.source, 0, "ground.model"},
                     "the cleat scenario crosses a rigid cleat on the rigid road; on a soil run "
                     "load-hold, free-vibration or rolling");
  }
  if (config.rigid) {
    throw InputError(InputLocation{config.source, 0, "tyre.rigid"},
                     "the transient runs the flexible tyre (the rigid wheel is traction's)");
  }
}

}  // namespace modaltyre::transient

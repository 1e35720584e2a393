#pragma once
// The 2D transient's units on a deformable soil (docs/soil.md section 8): each unit's contact
// spring k (the tread's instantaneous spring k_g with relaxation, else k_i; model.h) in series
// with the soil under its road area A_i = b_t ds cos theta_i. At the tip penetration g into the
// undisturbed surface (g = z + h - s - u - e, ode_system.h) the unit carries
//   f = phi_i(g):   f / k + Z(f / A_i; z_max,i) = g,   f = 0 when g <= Z(0; z_max,i) (the rut),
// Z the soil's sinkage law with memory (ground/pressure_sinkage.h: Bekker-Wong loading, Wong's
// unloading or rigid-plastic, the Kelvin-Voigt soil's elastic law). Z is continuous and
// non-decreasing, so phi is continuous and non-decreasing in g with
//   d phi / d g = 1 / (1 / k + Z'(p) / A_i),
// the stiffness Newton's matrix takes in place of k. The force stays an explicit function of the
// state (no soil state in the ODE): Bekker-Wong and the elastic Kelvin-Voigt law are
// rate-independent.
//
// The Kelvin-Voigt soil's rate term (eta2 > 0, docs/soil.md sections 1.2, 8.4): on either branch
// E2 (z - z_0) + eta2 dz/dt = H p / s (s = k_E loading, 1 unloading), i.e. the soil surface z
// relaxes towards the elastic law's depth Z_el(p; z_max) with the one time constant
// tau = eta2 / E2. Each unit's soil surface z_i is a state kept here beside z_max (not in the
// ODE): from its value z_a at the last accepted step it is advanced to t by the exact solution
// for the pressure of t held over the step (exponential Euler, first order in the pressure's
// change over a step, exact for a held pressure):
//   Z(p; t) = w z_a + (1 - w) Z_el(p; z_max),   w = exp(-(t - t_a) / tau),
// continuous and non-decreasing in p, so the series root above carries over with k (1 - w) and
// (g - w z_a) / (1 - w) in place of k and g, and d phi / d g = 1 / (1 / k + (1 - w) Z_el' / A).
// A unit out of contact recovers towards the rut the same way. eta2 = 0 is w = 0: the elastic law.
//
// Memory: z_max per unit in the ground frame. It is recorded at every accepted step (the soil
// depth Z_i of the units in contact), and while rolling it moves with the ground: the ground
// point under unit i at time t was under hub position x_i + (D(t) - D_acc) at the last accepted
// step (D the distance rolled), interpolated linearly between the units' x. Inside a step the
// point also passes over the units between x_i + (D(t) - D_acc) and x_i, so its memory is raised
// to the deepest of their depths at the accepted step (the sinkage profile taken as steady over
// a step, the rolling's quasi-steady state). Without that sweep a step that carries a point
// past the deepest unit (tens of units at 60 km/h) recorded the depths at the step ends only,
// and the rear's unloading branch, hence the compaction resistance, moved with the step size:
// 13.5-14.4 N on the flat-crown test of cell_soil_transient_test.cc at tolerances 1e-5 to 1e-7
// (docs/soil.md section 8). An evaluation at a time before the last accepted step (the driver's
// output samples, interpolated inside the step just taken) uses the memory that step was
// integrated with: the accepted memory already holds the depths of the step's end, which a
// state inside the step has not reached.
#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/transient/model.h"
#include "modaltyre/transient/scenario.h"
#include "modaltyre/transient/tread_window.h"

namespace modaltyre::transient {

class SoilContact {
 public:
  /// The soil of `ground` (a soil, else std::invalid_argument) under the units of `model`, with
  /// Bekker's b fixed at `bekker_width_m` and road areas from the contact width `width_m`;
  /// `distance` is the distance rolled D(t) [m] (empty: at rest).
  SoilContact(const TransientModel& model, const ground::GroundSettings& ground, double width_m,
              double bekker_width_m, std::function<double(double)> distance = {});
  /// The same on any row of contacts (the 3D patch's cells of one column class, cell_soil.h):
  /// road area, contact spring and road position x per entry.
  SoilContact(const ground::GroundSettings& ground, Eigen::VectorXd area_m2, Eigen::VectorXd k_N_m,
              Eigen::VectorXd x_m, double bekker_width_m,
              std::function<double(double)> distance = {});

  const ground::PressureSinkage& law() const { return *law_; }
  double bekker_width_m() const { return bekker_width_m_; }
  double area_m2(int i) const { return area_(i); }

  /// Sets the memory (e.g. a static contact's soil depths) at time t (m entries).
  void set_memory(const Eigen::VectorXd& z_max_m, double t = 0);
  /// The memory under unit i at time t (moved with the ground since the last accepted step).
  double z_max_m(int i, double t) const;

  /// The forces phi_i(g_i) in place of the penetrations g over units [lo, lo + n) at time t;
  /// keeps d phi / d g and the soil depth per unit of this evaluation (stiffness(), depth()).
  void forces(double t, int lo, int n, double* g) const;
  /// d phi / d g of unit i at the last forces() evaluation (0 where it carried no force).
  double stiffness(int i) const { return stiffness_(i); }
  /// The soil's surface depth under unit i at the last forces() evaluation (Z_i; the rut where
  /// the unit carried no force, also outside the units evaluated) [m].
  double depth(int i) const;
  /// The virgin curve's compliance dZ/df at unit i's pressure of the last forces() [m/N]: the
  /// contact edge's level function (as the static footprint on virgin soil, ground_patch.cc).
  /// On the memory's branch (a rigid-plastic one has dZ/df = 0) the branch's tangent would move
  /// the interpolated edge by up to a unit after a bounce, though no unit entered or left.
  double virgin_compliance_m_N(int i) const {
    return pressure_(i) > 0 ? law_->compliance_m_per_Pa(pressure_(i), 0.0) / area_(i) : 0.0;
  }
  /// The soil's surface depth under unit i unloaded at time t (Z(0; z_max)) [m].
  double rut_m(int i, double t) const;
  /// The deepest soil depth under the units [lo, hi] with a force f_i > 0 (the last forces()
  /// evaluation's, m entries).
  double deepest_loaded_m(int lo, int hi, const Eigen::VectorXd& f) const;

  /// sum_i f_i tan(alpha_i) over [lo, hi] at the last forces() evaluation (forces f, m entries):
  /// the normal forces' backward components on the soil surface's slope tan(alpha_i) =
  /// -dZ/dx, central differences of the depths over the units' x (contact/traction.cc's R_c).
  double compaction_resistance_N(int lo, int hi, const Eigen::VectorXd& f) const;

  /// An accepted step at t: moves the memory with the ground to t and records the soil depths of
  /// the last forces() evaluation (which must be at the accepted state) over [lo, hi].
  void accept(double t, int lo, int hi);

  /// Unit i's force and d phi / d g at penetration g with memory z_max (the series root); on a
  /// viscous soil the surface z_a at the last accepted step and the weight w = exp(-h / tau)
  /// of the time h since it (w = 0: the elastic law).
  double unit_force(int i, double g, double z_max, double* dfdg, double* depth, double z_a = 0,
                    double w = 0) const;
  /// The Kelvin-Voigt soil's time constant eta2 / E2 [s] (0: a rate-independent soil).
  double time_constant_s() const { return tau_s_; }

 private:
  /// Memory `zm` (per unit) at hub position x_i + shift, linear between the units' x (beyond the
  /// front: virgin soil; behind the rear: the rearmost unit's).
  double memory_at(const Eigen::VectorXd& zm, int i, double shift) const;
  /// The memory in force at t (the previous one before the last accepted step), the shift of
  /// the ground since it was recorded and (depths) the soil depths recorded with it.
  const Eigen::VectorXd& memory(double t, double& shift,
                                const Eigen::VectorXd** depths = nullptr) const;
  /// memory_at, raised to the deepest recorded depth the ground point passed over since the
  /// recording (the units between x_i + shift and x_i): the sweep of a step's travel, in the
  /// same walk over the units.
  double swept_memory_at(const Eigen::VectorXd& zm, const Eigen::VectorXd& depths, int i,
                         double shift) const;
  /// The soil surface recorded with memory(t) and the weight w = exp(-h / tau) of the time h
  /// since it was recorded (w = 0 on a rate-independent soil).
  const Eigen::VectorXd& surface(double t, double& w) const;
  /// Unit i's force at penetration g with memory z_max on the elastic law, tread spring k.
  double elastic_force(int i, double g, double z_max, double k, double* dfdg, double* depth) const;

  std::shared_ptr<const ground::PressureSinkage> law_;  ///< shared: a copy keeps the memory
  Eigen::VectorXd area_, k_, x_;
  Eigen::VectorXd z_max_;           ///< memory per unit at the last accepted step
  Eigen::VectorXd z_max_prev_;      ///< the one before it (evaluations inside the last step)
  Eigen::VectorXd depth_acc_;       ///< soil depths at the last accepted step (0: no force)
  Eigen::VectorXd depth_acc_prev_;  ///< the ones before it
  Eigen::VectorXd surface_;         ///< viscous soil: surface depth per unit, last accepted step
  Eigen::VectorXd surface_prev_;    ///< the one before it
  double tau_s_ = 0;                ///< eta2 / E2 (0: rate-independent)
  double t_accepted_ = -1e300, t_accepted_prev_ = -1e300, distance_prev_ = 0;
  mutable Eigen::VectorXd stiffness_, depth_, pressure_;  ///< last forces() per unit
  mutable int band_lo_ = 0, band_hi_ = -1;                ///< the units of the last forces()
  mutable double t_forces_ = 0;                           ///< its time
  std::function<double(double)> distance_;
  double distance_acc_ = 0;
  double bekker_width_m_ = 0;
};

/// The static footprint of `model` on its config's soil (contact/ground_patch.h, the tread width
/// as contact width) under load_N, virgin soil: forces, sinking and the soil's depth per unit.
/// Bekker's b fixed at bekker_width_m, or (0) iterated with the contact length as the footprint
/// does; the b used into *bekker_used. Zero forces for load_N <= 0; ComputationError when the
/// footprint fails.
StaticContact static_soil_contact(const TransientModel& model, double load_N,
                                  double bekker_width_m = 0, double* bekker_used = nullptr);

/// bounding_contact() (tread_window.h) on the soil at Bekker's b: the initial contact when the
/// load never rises above it, else the static footprint under 2 F_max - F0; none when that
/// footprint fails (the run then keeps every unit).
std::optional<StaticContact> bounding_soil_contact(const TransientModel& model,
                                                   const ScenarioPlan& plan,
                                                   const StaticContact& initial,
                                                   double bekker_width_m);

/// What a run on the config's soil does not model, refused naming the key (both patches): the
/// cleat (a rigid cleat on the rigid road) and the rigid wheel (traction's).
/// On the 3D patch (`cells`) also the Kelvin-Voigt soil's rate term (eta2 > 0), which only the 2D
/// units model.
void refuse_on_soil(const TransientModel& model, Scenario scenario, bool cells = false);

/// The soil of a 2D run (the config's ground: a soil) under `plan`: Bekker's b of the static
/// footprint at the scenario's largest load, fixed for the run, the ground moving with the
/// distance rolled. The initial contact on it into `initial` (its memory set from it).
std::unique_ptr<SoilContact> soil_for_plan(const TransientModel& model, const ScenarioPlan& plan,
                                           StaticContact& initial);

}  // namespace modaltyre::transient

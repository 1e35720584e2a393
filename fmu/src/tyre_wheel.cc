#include "modaltyre/fmu/tyre_wheel.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/fmu/longitudinal_contact.h"
#include "modaltyre/transient/driven_tyre.h"
#include "modaltyre/transient/tread_window.h"

namespace modaltyre::fmu {
namespace {

/// Below this forward speed the slip ratio is not reported (its denominator vanishes); the
/// tangential contact itself needs no such limit (it integrates slip displacements).
constexpr double kSlipSpeed_m_s = 0.1;
/// The tread states are kept for the units that can touch up to this multiple of the initial
/// deflection (and at least kMinDeflectionBound_m): DrivenTyre redoes a step with every unit
/// should one beyond touch, so the bound costs time, never accuracy.
constexpr double kDeflectionBoundFactor = 2.0;
constexpr double kMinDeflectionBound_m = 0.03;

}  // namespace

struct TyreWheel::Impl {
  Impl(std::shared_ptr<const transient::TransientModel> m, const WheelSettings& s)
      : model(std::move(m)), settings(s), on_soil(model->tyre.config.ground.soil()) {}

  /// The hub as the transient sees it at the start of a step.
  transient::HubState hub_of(const WheelInput& in) const {
    transient::HubState h;
    // On a profile the heights are the world's (the flat road at z = 0); else the host's
    // single-point terrain height.
    const double ground = settings.profile ? 0.0 : in.terrain_height_m;
    h.deflection_m = model->tyre.config.outer_radius_m - (in.plane.z_m - ground);
    h.speed_m_s = in.plane.speed_m_s;
    h.spin_rad_s = in.plane.spin_rad_s;
    return h;
  }

  /// The road profile's height and slope at ground position x relative to the hub at t (the
  /// hub carried from x0 at t0 at speed v over the current step).
  double road(double t, double x, double* slope) const {
    const double X = x0 + v * (t - t0) + x;
    // Level beyond the profile's first and last change of height (most units, most of the
    // time: the transient asks for every unit, and every 3D cell, in each right-hand side).
    if (X <= level_below_m || X >= level_above_m) {
      if (slope) *slope = 0;
      return X <= level_below_m ? settings.profile->height_m.front()
                                : settings.profile->height_m.back();
    }
    if (slope) *slope = settings.profile->slope_at(X);
    return settings.profile->height_at(X);
  }

  /// level_below_m / level_above_m of a profile: the x up to which (from which) it is level.
  void find_level_ends() {
    const auto& x = settings.profile->x_m;
    const auto& h = settings.profile->height_m;
    std::size_t a = 0, b = x.size() - 1;
    while (a + 1 < x.size() && h[a + 1] == h.front()) ++a;
    while (b > 0 && h[b - 1] == h.back()) --b;
    level_below_m = x[a];
    level_above_m = x[b];
  }

  /// The outputs from the vertical unit forces at the step's end (`forces`) and the tangential
  /// contact. transient::DrivenTyre::load() would give F_z and M_y too, with the patch length
  /// interpolated on the deformed belt, but its pass over the belt's shape was a third of a 3D
  /// step (sin/cos per unit); the length here is the loaded units' extent (one unit's
  /// resolution).
  /// The tyre's deflection at the road under the hub at time() with the unit forces `forces`:
  /// the hub's on a flat road, the deepest loaded unit's on a profile (its sinking into the
  /// profile's height there, less the unit's sag).
  double road_deflection(const transient::HubState& hub) const {
    double sinking = hub.deflection_m;
    if (!settings.profile) return sinking;
    const double t = tyre->time();
    for (int i = 0; i < model->m; ++i)
      if (forces(i) > 0)
        sinking = std::max(
            sinking, hub.deflection_m + road(t, model->x_road(i), nullptr) - model->tyre.sag(i));
    return sinking;
  }

  /// Whether the rim reaches the road: the tyre deflected by its section height or more.
  bool rim_on_road(const transient::HubState& hub) const {
    if (!(settings.section_height_m > 0)) return false;
    const double d = road_deflection(hub);
    if (d < settings.section_height_m) return false;
    // On a soil the tyre deflects by the hub's approach less the soil's sinkage (read only when
    // the approach alone reaches the section height: the wheel load's pass is a 3D step's third).
    return !on_soil || d - tyre->load().soil_sinkage_m >= settings.section_height_m;
  }

  void refresh(const WheelInput& in, const transient::HubState& hub) {
    // On a soil: its sinkage and the normal forces' backward share on its sloped surface (the
    // compaction resistance R_c = sum f tan alpha, docs/soil.md section 8), from the wheel load.
    double soil_sinkage = 0, compaction = 0;
    if (on_soil) {
      const transient::WheelLoad w = tyre->load();
      soil_sinkage = w.soil_sinkage_m;
      compaction = w.compaction_resistance_N;
    }
    // The lever of the forces at the ground: the loaded radius down to the deepest contact.
    const double r_loaded = model->tyre.config.outer_radius_m - (hub.deflection_m - soil_sinkage);
    const double t = tyre->time();
    double fz = 0, moment = 0, slope_force = 0;
    int first = -1, last = -1;
    for (int i = 0; i < model->m; ++i) {
      const double f = forces(i);
      if (!(f > 0)) continue;
      first = first < 0 ? i : first;
      last = i;
      const double x = model->x_road(i);
      fz += f;
      moment += f * x;
      if (settings.profile) {
        // On a profile the normal forces on its slopes push back: -sum f h'(x) (as the cleat's).
        double slope = 0;
        road(t, x, &slope);
        slope_force -= f * slope;
      }
    }
    // The ground's longitudinal force: the tread's (the soil's) shear, the profile's slopes
    // pushing back, a soil's compaction resistance.
    const double shear = contact->force_N() + slope_force - compaction;
    out.load.fz_N = fz;
    // The road's longitudinal force is the tread's shear (a free-rolling wheel's drag -M / r
    // comes out of it when the spin is free: M_y = 0).
    out.load.fx_N = shear;
    // Moment about the wheel axis: the vertical forces' (-M) and the shear's at the road,
    // r_loaded below the centre: (r x F)_y = r_z F_x = -r_loaded F_x.
    out.load.my_Nm = -moment - r_loaded * shear;
    out.deflection_m =
        first < 0 ? std::max(0.0, hub.deflection_m) : road_deflection(hub) - soil_sinkage;
    out.soil_sinkage_m = first < 0 ? 0.0 : soil_sinkage;
    out.compaction_resistance_N = compaction;
    out.contact_length_m =
        first < 0 ? 0.0 : model->x_road(last) - model->x_road(first) + model->tyre.unit_length_m;
    const double v = in.plane.speed_m_s;
    out.slip_ratio =
        std::abs(v) > kSlipSpeed_m_s
            ? (in.plane.spin_rad_s * contact->properties().base_radius_m - v) / std::abs(v)
            : 0.0;
  }

  std::shared_ptr<const transient::TransientModel> model;
  WheelSettings settings;
  std::unique_ptr<transient::DrivenTyre> tyre;
  std::unique_ptr<LongitudinalContact> contact;
  bool on_soil = false;                          ///< the config's ground is a soil
  std::unique_ptr<ground::ShearLaw> soil_shear;  ///< its Janosi-Hanamoto law
  Eigen::VectorXd forces;
  WheelOutput out;
  double x0 = 0, t0 = 0, v = 0;  ///< the hub along the road over the current step
  double level_below_m = 0, level_above_m = 0;
  bool rim_last = false;  ///< the rim on the road at the last sub-step's end
};

double section_height_m(const contact::TyreConfig& c) {
  if (c.rim_radius_m > 0) return c.outer_radius_m - c.rim_radius_m;
  if (c.section_width_m > 0 && c.aspect_ratio > 0) return c.section_width_m * c.aspect_ratio;
  return 0;
}

TyreWheel::TyreWheel(std::shared_ptr<const transient::TransientModel> model,
                     const WheelSettings& settings)
    : impl_(std::make_unique<Impl>(std::move(model), settings)) {}

TyreWheel::~TyreWheel() = default;

std::string TyreWheel::refusal(const WheelInput& in, double h) const {
  const Impl& I = *impl_;
  const double R0 = I.model->tyre.config.outer_radius_m;
  for (double s : {0.0, h}) {
    transient::HubState hub = I.hub_of(in);
    hub.deflection_m -= in.plane.vertical_m_s * s;
    // On a profile the road under the centre is the profile's height there.
    const double road = I.settings.profile
                            ? I.settings.profile->height_at(in.plane.x_m + in.plane.speed_m_s * s)
                            : 0.0;
    if (!(hub.deflection_m - road < R0)) {
      std::ostringstream msg;
      msg << "the wheel centre lies " << (hub.deflection_m - road - R0) * 1e3
          << " mm below the road at " << (s == 0 ? "the step's start" : "the step's end")
          << " (wheel_state.pos.z, terrain_height): no tyre is left between the rim and the "
             "road";
      return msg.str();
    }
  }
  // The carcass's critical speed (transient::critical_speed_of(), docs/transient.md section 3a):
  // a wheel spinning at or beyond it has no steady state in the model (a blow-up, not a tyre).
  const modal::CriticalSpeed c = transient::critical_speed_of(*I.model);
  if (std::abs(in.plane.spin_rad_s) * R0 >= c.speed_m_s) {
    std::ostringstream msg;
    msg.precision(4);
    msg << "the wheel's circumferential speed |spin| R0 = "
        << std::abs(in.plane.spin_rad_s) * R0 * 3.6 << " km/h is at or beyond the carcass's "
        << "critical speed " << c.speed_km_h() << " km/h (order " << c.order
        << ", its standing wave; docs/transient.md section 3a): the model has no steady rolling "
           "state there";
    return msg.str();
  }
  return "";
}

void TyreWheel::start(double t, const WheelInput& in) {
  Impl& I = *impl_;
  const transient::HubState hub = I.hub_of(in);
  transient::DrivenTyreOptions opt;
  opt.max_step_s = I.settings.step_size_s;
  opt.max_deflection_m =
      std::max(kMinDeflectionBound_m, kDeflectionBoundFactor * std::max(hub.deflection_m, 0.0));
  I.x0 = in.plane.x_m;
  I.t0 = t;
  I.v = in.plane.speed_m_s;
  Impl* self = &I;
  if (I.on_soil) {
    // The soil's memory moves with the hub's travel along its heading.
    opt.distance_m = [self](double tt) { return self->x0 + self->v * (tt - self->t0); };
    I.soil_shear = I.model->tyre.config.ground.shear_law(0.0);
  }
  if (I.settings.profile) {
    opt.road_profile = [self](double tt, double x, double* slope) {
      return self->road(tt, x, slope);
    };
    const auto& h = I.settings.profile->height_m;
    opt.road_max_height_m = std::max(0.0, *std::max_element(h.begin(), h.end()));
    I.find_level_ends();
  }
  I.tyre = std::make_unique<transient::DrivenTyre>(*I.model, opt);
  I.tyre->reset(hub, t);
  I.forces.setZero(I.model->m);
  I.tyre->vertical_forces(I.forces);
  // The carcass's longitudinal compliance averaged over the patch at the start, or over the
  // static patch under the config's rolling load when the wheel starts off the road.
  const Eigen::VectorXd patch =
      I.forces.maxCoeff() > 0
          ? Eigen::VectorXd(I.forces)
          : transient::static_contact(*I.model, I.model->settings.rolling.load_N).f;
  I.contact = std::make_unique<LongitudinalContact>(longitudinal_properties(I.model->tyre, patch),
                                                    0, I.model->m - 1);
  I.refresh(in, hub);
  I.rim_last = I.out.rim_contact = I.rim_on_road(hub);
  I.out.rim_contact_started = I.out.rim_contact;
  I.out.rim_started_at_s = t;
}

void TyreWheel::step(double t, double h, const WheelInput& in) {
  Impl& I = *impl_;
  MODALTYRE_CHECK(I.tyre, "TyreWheel::step before start");
  // The hub's state at t, carried at its velocity over the step in sub-steps of at most
  // step_size: the transient moves it linearly inside each, the tangential contact takes the
  // vertical forces at each sub-step's end.
  const transient::HubState h0 = I.hub_of(in);
  I.x0 = in.plane.x_m;
  I.t0 = t;
  I.v = in.plane.speed_m_s;
  const int n = std::max(1, static_cast<int>(std::ceil(h / I.settings.step_size_s - 1e-9)));
  const double dt = h / n;
  transient::HubState hub = h0;
  const bool rim_before = I.out.rim_contact;
  I.out.rim_contact = false;
  I.out.rim_contact_started = false;
  for (int k = 1; k <= n; ++k) {
    const double s = k * dt;
    hub.deflection_m = h0.deflection_m - in.plane.vertical_m_s * s;
    const transient::DriveStatus st = I.tyre->advance(t + s, hub);
    if (!st.ok) throw ComputationError(st.message);
    I.forces.setZero();
    I.tyre->vertical_forces(I.forces);
    if (I.soil_shear)
      I.contact->advance(dt, I.forces.data(), in.plane.spin_rad_s, in.plane.speed_m_s,
                         *I.soil_shear);
    else
      I.contact->advance(dt, I.forces.data(), in.plane.spin_rad_s, in.plane.speed_m_s, in.mu);
    // The rim on the road at a sub-step's end: raised for the whole communication step, and
    // "started" when it was not on the road at the sub-step before.
    const bool rim = I.rim_on_road(hub);
    if (rim && !(k == 1 ? rim_before : I.rim_last)) {
      if (!I.out.rim_contact_started) I.out.rim_started_at_s = t + s;
      I.out.rim_contact_started = true;
    }
    I.rim_last = rim;
    I.out.rim_contact = I.out.rim_contact || rim;
  }
  I.refresh(in, hub);
}

const WheelOutput& TyreWheel::output() const { return impl_->out; }

}  // namespace modaltyre::fmu

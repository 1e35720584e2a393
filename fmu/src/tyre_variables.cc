#include "modaltyre/fmu/tyre_variables.h"

#include "modaltyre/fmu/soil_parameters.h"

namespace modaltyre::fmu {
namespace {

/// The inputs the tyre at rest depends on (initialization mode: the outputs of the standing tyre
/// at the wheel state set, fmi2GetReal in Instance::get_real): the hub's position and
/// orientation and the road height. The slip ratio reads the velocities instead.
const std::vector<std::string> kStandingTyreKnowns = {
    "wheel_state.pos.x",  "wheel_state.pos.y",  "wheel_state.pos.z",  "wheel_state.rot.e0",
    "wheel_state.rot.e1", "wheel_state.rot.e2", "wheel_state.rot.e3", "terrain_height"};
const std::vector<std::string> kSlipKnowns = {
    "wheel_state.rot.e0",    "wheel_state.rot.e1",    "wheel_state.rot.e2",
    "wheel_state.rot.e3",    "wheel_state.lin_vel.x", "wheel_state.lin_vel.y",
    "wheel_state.ang_vel.x", "wheel_state.ang_vel.y", "wheel_state.ang_vel.z"};

/// A variable of another type than Real (no unit).
ScalarVariable other(const std::string& name, unsigned ref, BaseType type, Causality c,
                     Variability variability, Initial initial) {
  ScalarVariable v;
  v.name = name;
  v.value_reference = ref;
  v.type = type;
  v.causality = c;
  v.variability = variability;
  v.initial = initial;
  return v;
}

ScalarVariable real(const std::string& name, unsigned ref, Causality c, const std::string& unit,
                    const std::string& description, std::optional<double> start = {}) {
  ScalarVariable v;
  v.name = name;
  v.value_reference = ref;
  v.type = BaseType::real;
  v.causality = c;
  v.unit = unit;
  v.description = description;
  if (c == Causality::input) {
    v.variability = Variability::continuous;
    v.start = start;
  } else if (c == Causality::output) {
    v.variability = Variability::continuous;
    v.initial = Initial::calculated;
    // At a communication point the outputs are those of the step that ended there: setting the
    // inputs there does not change them (no direct feedthrough, section 2.2.8).
    v.dependencies = std::vector<std::string>{};
    v.initial_dependencies = kStandingTyreKnowns;
  } else if (c == Causality::parameter) {
    v.variability = Variability::fixed;
    v.initial = Initial::exact;
    v.start = start;
  }
  return v;
}

}  // namespace

ModelDescription tyre_model_description(const TyreDescriptionInfo& info) {
  ModelDescription d;
  d.model_name = "ModalTyre: " + info.tyre_name;
  d.guid = info.guid;
  d.model_identifier = kModelIdentifier;
  d.generation_tool = "ModalTyre (modaltyre fmu)";
  d.description =
      "Transient modal tyre (seed 001 modal carcass, Kelvin-Voigt tread, unilateral contact, "
      "CVODE/KLU) in the wheel plane. Filled: wheel_load.force.x (longitudinal), .force.z "
      "(vertical) and .moment.y (about the spin axis), in the world frame along the wheel's "
      "heading. Not modelled (always 0): lateral force, overturning and aligning moments "
      "(wheel_load.force.y, moment.x, moment.z along the wheel frame). Load point: the wheel "
      "centre.";
  d.default_step_s = info.step_size_s;
  d.log_categories = {"logStatusError", "logStatusDiscard", "logStatusWarning", "logEvents"};

  using C = Causality;
  auto& v = d.variables;
  const char* xyz[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k)
    v.push_back(real(std::string("wheel_state.pos.") + xyz[k], vr::pos_x + k, C::input, "m",
                     "wheel centre position (world frame)", k == 2 ? info.outer_radius_m : 0.0));
  const char* e[] = {"e0", "e1", "e2", "e3"};
  for (int k = 0; k < 4; ++k) {
    v.push_back(real(std::string("wheel_state.rot.") + e[k], vr::rot_e0 + k, C::input, "1",
                     "wheel orientation quaternion (e0 scalar; wheel frame to world); a unit "
                     "quaternion: a host's drift up to |q|^2 = 1 +- 1e-3 is normalised",
                     k == 0 ? 1.0 : 0.0));
    v.back().min = -1.0;
    v.back().max = 1.0;
  }
  for (int k = 0; k < 3; ++k)
    v.push_back(real(std::string("wheel_state.lin_vel.") + xyz[k], vr::lin_vel_x + k, C::input,
                     "m/s", "wheel centre velocity (world frame)", 0.0));
  for (int k = 0; k < 3; ++k)
    v.push_back(real(std::string("wheel_state.ang_vel.") + xyz[k], vr::ang_vel_x + k, C::input,
                     "rad/s", "wheel angular velocity (world frame); spin about the wheel's y",
                     0.0));
  v.push_back(real("terrain_height", vr::terrain_height, C::input, "m",
                   "terrain height at query_point (unused when road_profile is set)", 0.0));
  for (int k = 0; k < 3; ++k) {
    v.push_back(real(std::string("terrain_normal.") + xyz[k], vr::terrain_normal_x + k, C::input,
                     "1", "terrain normal at query_point (the in-plane model takes z up)",
                     k == 2 ? 1.0 : 0.0));
    v.back().min = -1.0;
    v.back().max = 1.0;
  }
  v.push_back(real("terrain_mu", vr::terrain_mu, C::input, "1",
                   "friction coefficient of the road (Coulomb mu of the tread)",
                   info.friction_coefficient));
  v.back().min = 0.0;
  v.back().max = kMaxFriction;
  for (int k = 0; k < 3; ++k)
    v.push_back(real(std::string("wheel_load.point.") + xyz[k], vr::load_point_x + k, C::output,
                     "m", "application point of wheel_load (the wheel centre)"));
  for (int k = 0; k < 3; ++k)
    v.push_back(real(std::string("wheel_load.force.") + xyz[k], vr::force_x + k, C::output, "N",
                     "force of the road on the wheel through the tyre (world frame)"));
  for (int k = 0; k < 3; ++k)
    v.push_back(real(std::string("wheel_load.moment.") + xyz[k], vr::moment_x + k, C::output, "N.m",
                     "moment about the wheel centre (world frame)"));
  for (int k = 0; k < 3; ++k)
    v.push_back(real(std::string("query_point.") + xyz[k], vr::query_x + k, C::output, "m",
                     "where the host should evaluate terrain_height (the wheel centre)"));
  v.push_back(real("tyre.deflection", vr::deflection, C::output, "m",
                   "radial deflection of the tyre at the road (sinking)"));
  v.push_back(real("tyre.contact_length", vr::contact_length, C::output, "m",
                   "length of the contact patch: the extent of its loaded units along x"));
  v.push_back(real("tyre.slip_ratio", vr::slip_ratio, C::output, "1",
                   "longitudinal slip (spin x rolling radius - speed) / speed, 0 below 0.1 m/s"));
  v.back().initial_dependencies = kSlipKnowns;
  if (info.soil) {
    v.push_back(real("soil.sinkage", vr::soil_sinkage, C::output, "m",
                     "the soil's deepest loaded point below its undisturbed surface "
                     "(terrain_height); the tyre's own deflection is tyre.deflection"));
    v.push_back(real("soil.compaction_resistance", vr::compaction_resistance, C::output, "N",
                     "the normal forces' backward share on the soil's sloped surface, sum f "
                     "tan(alpha) (in wheel_load.force along the heading, as a drag)"));
  }
  v.push_back(real("step_size", vr::step_size, C::parameter, "s",
                   "largest internal step between two hub states (the integrator takes its "
                   "own steps inside)",
                   info.step_size_s));
  v.back().min = kMinStepSize_s;
  v.back().max = kMaxStepSize_s;
  if (info.soil) {
    const std::vector<SoilParameter> soil = soil_parameters(*info.soil, info.patch_3d);
    for (std::size_t k = 0; k < soil.size(); ++k) {
      const SoilParameter& p = soil[k];
      v.push_back(real(p.name, vr::first_soil_parameter + unsigned(k), C::parameter, p.unit,
                       p.description + " (the packed soil's " +
                           (info.soil->name.empty() ? std::string("value") : info.soil->name) + ")",
                       p.get(*info.soil)));
      v.back().min = p.min;
      v.back().max = p.max;
      v.back().min_exclusive = p.positive;
    }
  }
  ScalarVariable rim = other("tyre.rim_contact", vr::rim_contact, BaseType::boolean, C::output,
                             Variability::discrete, Initial::calculated);
  rim.dependencies = std::vector<std::string>{};
  rim.initial_dependencies = kStandingTyreKnowns;
  rim.description =
      info.section_height_m > 0
          ? "true while the rim is on the road: the tyre deflected by its section height (" +
                std::to_string(info.section_height_m * 1e3).substr(0, 5) +
                " mm) or more at a sub-step of the last step (a warning is logged when it starts)"
          : "never raised: the config states no rim radius nor section width and aspect ratio";
  v.push_back(rim);
  ScalarVariable road = other("road_profile", vr::road_profile, BaseType::string, C::parameter,
                              Variability::fixed, Initial::exact);
  road.start_string = "";
  road.description =
      "optional CSV x_m,height_m: the road under the whole tyre in world x (a cleat, a profile); "
      "absolute or relative to the FMU's resources folder; empty: flat at terrain_height";
  v.push_back(road);
  // The units the variables name, each defined once.
  for (const ScalarVariable& x : d.variables) {
    if (x.unit.empty()) continue;
    bool defined = false;
    for (const UnitDefinition& u : d.units) defined = defined || u.name == x.unit;
    if (!defined) d.units.push_back(*known_unit(x.unit));
  }
  return d;
}

}  // namespace modaltyre::fmu

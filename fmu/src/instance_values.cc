// The instance's values (instance.h): fmi2GetXXX / fmi2SetXXX with the checks of FMI 2.0
// section 2.2.7 (causality, the state a variable may be set in, its declared range).
#include <cmath>
#include <sstream>

#include "modaltyre/core/input_file.h"
#include "modaltyre/fmu/instance.h"
#include "modaltyre/fmu/tyre_variables.h"
#include "modaltyre/fmu/tyre_wheel.h"

namespace modaltyre::fmu {
namespace {

/// A unit quaternion's and a unit normal's components may exceed 1 by a host's rounding drift:
/// |q|^2 within 1 +- 1e-3 is normalised (wheel.cc), so a component up to sqrt(1 + 1e-3).
constexpr double kUnitComponentSlack = 5e-4;

std::string text(double x) {
  std::ostringstream s;
  s.precision(12);
  s << x;
  return s.str();
}

}  // namespace

const ScalarVariable* Instance::real_variable(unsigned r) const {
  return r < real_vars_.size() ? real_vars_[r] : nullptr;
}

std::string Instance::refusal(const ScalarVariable& v, double value) const {
  if (!std::isfinite(value)) return "is not finite";
  const bool unit_vector =
      v.name.rfind("wheel_state.rot.", 0) == 0 || v.name.rfind("terrain_normal.", 0) == 0;
  const double slack = unit_vector ? kUnitComponentSlack : 0.0;
  const bool below = v.min && (v.min_exclusive ? !(value > *v.min) : value < *v.min - slack);
  if (below || (v.max && value > *v.max + slack))
    return "is outside the variable's range " + std::string(v.min_exclusive ? "(" : "[") +
           (v.min ? text(*v.min) : "-inf") + ", " + (v.max ? text(*v.max) : "inf") + "] " + v.unit;
  return "";
}

fmi2Status Instance::get_real(const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
  if (!readable("fmi2GetReal", n, vr, value)) return fmi2Error;
  for (size_t k = 0; k < n; ++k)
    if (!real_variable(vr[k]))
      return fail("fmi2GetReal: no Real variable has value reference " + std::to_string(vr[k]));
  if (state_ == State::initialization) {
    // Outputs in initialization mode: the tyre at rest under the current inputs.
    const fmi2Status s = standing_outputs("fmi2GetReal in initialization mode");
    if (s != fmi2OK) return s;
  }
  for (size_t k = 0; k < n; ++k) value[k] = real_[vr[k]];
  return fmi2OK;
}

fmi2Status Instance::set_real(const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
  if (!allowed({State::instantiated, State::initialization, State::step_complete}, "fmi2SetReal"))
    return fmi2Error;
  if (n > 0 && (!vr || !value)) return fail("fmi2SetReal: NULL array");
  // Every value is checked before any is taken: a refused call changes nothing.
  std::string discarded;
  for (size_t k = 0; k < n; ++k) {
    const ScalarVariable* v = real_variable(vr[k]);
    const bool input = v && v->causality == Causality::input;
    const bool parameter = v && v->causality == Causality::parameter;
    if (!(input || parameter))
      return fail("fmi2SetReal: value reference " + std::to_string(vr[k]) +
                  " is not an input or parameter (outputs cannot be set)");
    if (parameter && state_ == State::step_complete)
      return fail("fmi2SetReal: " + v->name +
                  " is a fixed parameter (set it before fmi2ExitInitializationMode)");
    const std::string why = refusal(*v, value[k]);
    if (!why.empty() && discarded.empty())
      discarded = "fmi2SetReal: " + v->name + " = " + text(value[k]) + " " + why;
  }
  if (!discarded.empty()) {
    // Section 2.2.7: a value outside [min, max] is answered with fmi2Discard (a parameter's, and
    // this FMU's choice for an input); no value of the call is taken.
    log(fmi2Discard, discarded + " (not taken; no value of this call was)");
    return fmi2Discard;
  }
  for (size_t k = 0; k < n; ++k) real_[vr[k]] = value[k];
  return fmi2OK;
}

bool Instance::readable(const char* function, size_t n, const void* vr, const void* value) {
  if (!allowed({State::initialization, State::step_complete, State::step_failed, State::terminated,
                State::error},
               function))
    return false;
  if (n > 0 && (!vr || !value)) {
    fail(std::string(function) + ": NULL array");
    return false;
  }
  return true;
}

fmi2Status Instance::get_boolean(const fmi2ValueReference vr[], size_t n, fmi2Boolean value[]) {
  if (!readable("fmi2GetBoolean", n, vr, value)) return fmi2Error;
  for (size_t k = 0; k < n; ++k)
    if (vr[k] != vr::rim_contact)
      return fail("fmi2GetBoolean: no Boolean variable has value reference " +
                  std::to_string(vr[k]));
  if (state_ == State::initialization) {
    const fmi2Status s = standing_outputs("fmi2GetBoolean in initialization mode");
    if (s != fmi2OK) return s;
  }
  for (size_t k = 0; k < n; ++k) value[k] = rim_contact_ ? fmi2True : fmi2False;
  return fmi2OK;
}

fmi2Status Instance::get_string(const fmi2ValueReference vr[], size_t n, fmi2String value[]) {
  if (!readable("fmi2GetString", n, vr, value)) return fmi2Error;
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] != vr::road_profile)
      return fail("fmi2GetString: no String variable has value reference " + std::to_string(vr[k]));
    value[k] = road_profile_.c_str();
  }
  return fmi2OK;
}

fmi2Status Instance::set_string(const fmi2ValueReference vr[], size_t n, const fmi2String value[]) {
  if (!allowed({State::instantiated, State::initialization}, "fmi2SetString")) return fmi2Error;
  if (n > 0 && (!vr || !value)) return fail("fmi2SetString: NULL array");
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] != vr::road_profile)
      return fail("fmi2SetString: no String variable has value reference " + std::to_string(vr[k]));
    // fmi2String is UTF-8 (FMI 2.0 section 2.1.2); a path in another encoding is not one.
    if (value[k] && !valid_utf8(value[k])) {
      log(fmi2Discard,
          "fmi2SetString: road_profile is not UTF-8 text (a Latin-1 byte?): not taken");
      return fmi2Discard;
    }
  }
  for (size_t k = 0; k < n; ++k) road_profile_ = value[k] ? value[k] : "";
  return fmi2OK;
}

fmi2Status Instance::no_variables(const char* function, size_t n) {
  if (n == 0) return fmi2OK;
  return fail(std::string(function) + ": this FMU has no variable of that type and causality");
}

}  // namespace modaltyre::fmu

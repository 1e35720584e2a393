#include "modaltyre/contact/operating_conditions.h"

#include <stdexcept>

namespace modaltyre::contact {

double condition_value(const OperatingConditions& c, ConditionId id) {
  switch (id) {
    case ConditionId::load_N:
      return c.load_N;
    case ConditionId::pressure_kPa:
      return c.pressure_kPa;
    case ConditionId::hold_s:
      return c.hold_s;
    case ConditionId::speed_kmh:
      return c.speed_kmh;
    case ConditionId::branch:
      return c.branch == Branch::unloading ? 1.0 : 0.0;
    case ConditionId::surface:
      return c.surface == Surface::soil ? 1.0 : 0.0;
    case ConditionId::horizontal_force_N:
      return c.horizontal_force_N;
    case ConditionId::slip:
      return c.slip;
  }
  throw std::logic_error("unknown condition id");
}

void set_condition(OperatingConditions& c, ConditionId id, double value) {
  switch (id) {
    case ConditionId::load_N:
      c.load_N = value;
      return;
    case ConditionId::pressure_kPa:
      c.pressure_kPa = value;
      return;
    case ConditionId::hold_s:
      c.hold_s = value;
      return;
    case ConditionId::speed_kmh:
      c.speed_kmh = value;
      return;
    case ConditionId::branch:
      c.branch = value != 0 ? Branch::unloading : Branch::loading;
      return;
    case ConditionId::surface:
      c.surface = value != 0 ? Surface::soil : Surface::rigid;
      return;
    case ConditionId::horizontal_force_N:
      c.horizontal_force_N = value;
      return;
    case ConditionId::slip:
      c.slip = value;
      return;
  }
  throw std::logic_error("unknown condition id");
}

const char* branch_name(Branch b) {
  return condition_info(ConditionId::branch).words.at(static_cast<int>(b)).front().c_str();
}
const char* surface_name(Surface s) {
  return condition_info(ConditionId::surface).words.at(static_cast<int>(s)).front().c_str();
}

std::optional<Branch> branch_named(const std::string& name) {
  const auto v = condition_info(ConditionId::branch).value_of(name);
  return v ? std::optional<Branch>(static_cast<Branch>(*v)) : std::nullopt;
}

std::optional<Surface> surface_named(const std::string& name) {
  const auto v = condition_info(ConditionId::surface).value_of(name);
  return v ? std::optional<Surface>(static_cast<Surface>(*v)) : std::nullopt;
}

}  // namespace modaltyre::contact

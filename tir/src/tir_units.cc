// [UNITS] of a .tir file (tir_units.h). Unit names as MSC Adams and MF-Tool write them, with the
// usual abbreviations; matching ignores case, blanks, '-' and '_' ("kilo_newton" = "kN").
#include "modaltyre/tir/tir_units.h"

#include <cctype>
#include <utility>
#include <vector>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::tir {
namespace {

using UnitTable = std::vector<std::pair<const char*, double>>;

const UnitTable kLength = {{"meter", 1},     {"metre", 1},         {"meters", 1},
                           {"m", 1},         {"millimeter", 1e-3}, {"millimetre", 1e-3},
                           {"mm", 1e-3},     {"centimeter", 1e-2}, {"centimetre", 1e-2},
                           {"cm", 1e-2},     {"kilometer", 1e3},   {"km", 1e3},
                           {"inch", 0.0254}, {"in", 0.0254},       {"foot", 0.3048},
                           {"feet", 0.3048}, {"ft", 0.3048}};
const UnitTable kForce = {{"newton", 1},
                          {"n", 1},
                          {"kilonewton", 1e3},
                          {"knewton", 1e3},
                          {"kn", 1e3},
                          {"millinewton", 1e-3},
                          {"poundforce", 4.4482216152605},
                          {"lbf", 4.4482216152605},
                          {"kilogramforce", 9.80665},
                          {"kgf", 9.80665},
                          {"dyne", 1e-5}};
const UnitTable kTime = {{"second", 1},         {"seconds", 1}, {"sec", 1},     {"s", 1},
                         {"millisecond", 1e-3}, {"ms", 1e-3},   {"minute", 60}, {"min", 60},
                         {"hour", 3600},        {"h", 3600}};
const UnitTable kMass = {
    {"kg", 1},           {"kilogram", 1},      {"gram", 1e-3},    {"g", 1e-3},
    {"tonne", 1e3},      {"t", 1e3},           {"megagram", 1e3}, {"poundmass", 0.45359237},
    {"lbm", 0.45359237}, {"slug", 14.59390294}};
const UnitTable kAngle = {{"radian", 1},
                          {"radians", 1},
                          {"rad", 1},
                          {"degree", 0.017453292519943295},
                          {"degrees", 0.017453292519943295},
                          {"deg", 0.017453292519943295}};
const UnitTable kPressure = {{"pascal", 1},          {"pa", 1},    {"kilopascal", 1e3},
                             {"kpascal", 1e3},       {"kpa", 1e3}, {"megapascal", 1e6},
                             {"mpascal", 1e6},       {"mpa", 1e6}, {"bar", 1e5},
                             {"psi", 6894.757293168}};

std::string normalised(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (c == ' ' || c == '_' || c == '-') continue;
    out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

double unit(const TirFile& file, const char* key, const UnitTable& table, double fallback) {
  const TirValue* v = file.value("UNITS", key);
  if (!v) return fallback;
  const std::string name = normalised(v->text);
  for (const auto& [known, factor] : table) {
    if (name == known) return factor;
  }
  std::string list;
  for (const auto& [known, factor] : table) {
    (void)factor;
    if (std::string(known).size() > 3) list += (list.empty() ? "" : ", ") + std::string(known);
  }
  throw InputError({file.path, v->line, std::string("UNITS.") + key},
                   "unknown unit '" + printable(v->text) + "'; known: " + list);
}

}  // namespace

double TirUnits::to_si(Dimension d) const {
  switch (d) {
    case Dimension::none:
      return 1;
    case Dimension::length:
      return length_m;
    case Dimension::force:
      return force_N;
    case Dimension::stiffness:
      return force_N / length_m;
    case Dimension::pressure:
      return pressure_Pa;
    case Dimension::damping:
      return force_N * time_s / length_m;
    case Dimension::speed:
      return length_m / time_s;
    case Dimension::mass:
      return mass_kg;
    case Dimension::time:
      return time_s;
    case Dimension::angle:
      return angle_rad;
  }
  return 1;
}

TirUnits read_units(const TirFile& file) {
  TirUnits u;
  u.stated = file.section("UNITS") != nullptr;
  u.length_m = unit(file, "LENGTH", kLength, 1);
  u.force_N = unit(file, "FORCE", kForce, 1);
  u.time_s = unit(file, "TIME", kTime, 1);
  u.mass_kg = unit(file, "MASS", kMass, 1);
  u.angle_rad = unit(file, "ANGLE", kAngle, 1);
  u.pressure_Pa = unit(file, "PRESSURE", kPressure, u.force_N / (u.length_m * u.length_m));
  return u;
}

}  // namespace modaltyre::tir

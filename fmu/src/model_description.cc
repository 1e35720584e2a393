#include "modaltyre/fmu/model_description.h"

#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "modaltyre/core/errors.h"

namespace modaltyre::fmu {

const char* to_string(Causality c) {
  switch (c) {
    case Causality::parameter:
      return "parameter";
    case Causality::calculated_parameter:
      return "calculatedParameter";
    case Causality::input:
      return "input";
    case Causality::output:
      return "output";
    case Causality::local:
      return "local";
    case Causality::independent:
      return "independent";
  }
  return "?";
}

const char* to_string(Variability v) {
  switch (v) {
    case Variability::constant:
      return "constant";
    case Variability::fixed:
      return "fixed";
    case Variability::tunable:
      return "tunable";
    case Variability::discrete:
      return "discrete";
    case Variability::continuous:
      return "continuous";
  }
  return "?";
}

const char* to_string(Initial i) {
  switch (i) {
    case Initial::none:
      return "";
    case Initial::exact:
      return "exact";
    case Initial::approx:
      return "approx";
    case Initial::calculated:
      return "calculated";
  }
  return "?";
}

const char* to_string(BaseType t) {
  switch (t) {
    case BaseType::real:
      return "Real";
    case BaseType::integer:
      return "Integer";
    case BaseType::boolean:
      return "Boolean";
    case BaseType::string:
      return "String";
  }
  return "?";
}

std::optional<UnitDefinition> known_unit(const std::string& name) {
  // SI base exponents kg, m, s, A, K, mol, cd, rad and the factor to SI.
  constexpr double kDeg = 3.14159265358979323846 / 180;
  static const std::map<std::string, UnitDefinition> known = {
      {"1", {"1", UnitExponents{0, 0, 0, 0, 0, 0, 0, 0}, 1}},
      {"m", {"m", UnitExponents{0, 1, 0, 0, 0, 0, 0, 0}, 1}},
      {"s", {"s", UnitExponents{0, 0, 1, 0, 0, 0, 0, 0}, 1}},
      {"m/s", {"m/s", UnitExponents{0, 1, -1, 0, 0, 0, 0, 0}, 1}},
      {"rad/s", {"rad/s", UnitExponents{0, 0, -1, 0, 0, 0, 0, 1}, 1}},
      {"N", {"N", UnitExponents{1, 1, -2, 0, 0, 0, 0, 0}, 1}},
      {"N.m", {"N.m", UnitExponents{1, 2, -2, 0, 0, 0, 0, 0}, 1}},
      {"mm", {"mm", UnitExponents{0, 1, 0, 0, 0, 0, 0, 0}, 1e-3}},
      {"kPa", {"kPa", UnitExponents{1, -1, -2, 0, 0, 0, 0, 0}, 1e3}},
      {"MPa", {"MPa", UnitExponents{1, -1, -2, 0, 0, 0, 0, 0}, 1e6}},
      {"kPa.s", {"kPa.s", UnitExponents{1, -1, -1, 0, 0, 0, 0, 0}, 1e3}},
      {"kN/m3", {"kN/m3", UnitExponents{1, -2, -2, 0, 0, 0, 0, 0}, 1e3}},
      {"kN/m4", {"kN/m4", UnitExponents{1, -3, -2, 0, 0, 0, 0, 0}, 1e3}},
      {"deg", {"deg", UnitExponents{0, 0, 0, 0, 0, 0, 0, 1}, kDeg}},
      // Bekker's moduli (Wong, Table 2.3): the exponent n + 1, n + 2 is a soil parameter.
      {"kN/m^(n+1)", {"kN/m^(n+1)", std::nullopt, 1}},
      {"kN/m^(n+2)", {"kN/m^(n+2)", std::nullopt, 1}}};
  auto it = known.find(name);
  if (it == known.end()) return std::nullopt;
  return it->second;
}

namespace {

/// Structured naming (FMI 2.0 section 2.2.9, without array subscripts and der()): identifiers
/// of letters, digits and '_' not starting with a digit, joined by single dots.
bool structured_name(const std::string& name) {
  if (name.empty()) return false;
  bool start = true;
  for (char ch : name) {
    if (ch == '.') {
      if (start) return false;
      start = true;
      continue;
    }
    const bool alpha = std::isalpha(static_cast<unsigned char>(ch)) || ch == '_';
    if (!(alpha || std::isdigit(static_cast<unsigned char>(ch)))) return false;
    if (start && !alpha) return false;
    start = false;
  }
  return !start;
}

/// The initial values allowed for a causality/variability pair (section 2.2.7's tables); empty
/// when the pair itself is not allowed. The first entry is the default.
std::vector<Initial> allowed_initial(Causality c, Variability v) {
  using C = Causality;
  using V = Variability;
  using I = Initial;
  const bool param_var = v == V::fixed || v == V::tunable;
  const bool time_var = v == V::discrete || v == V::continuous;
  switch (c) {
    case C::parameter:
      return param_var ? std::vector{I::exact} : std::vector<I>{};
    case C::calculated_parameter:
      return param_var ? std::vector{I::calculated, I::approx} : std::vector<I>{};
    case C::input:
      return time_var ? std::vector{I::none} : std::vector<I>{};
    case C::independent:
      return v == V::continuous ? std::vector{I::none} : std::vector<I>{};
    case C::output:
      if (v == V::constant) return {I::exact};
      return time_var ? std::vector{I::calculated, I::exact, I::approx} : std::vector<I>{};
    case C::local:
      if (v == V::constant) return {I::exact};
      if (param_var) return {I::calculated, I::approx};
      return {I::calculated, I::exact, I::approx};
  }
  return {};
}

}  // namespace

namespace {

/// The dependencies' rules (section 2.2.8): outputs at a communication point depend on inputs;
/// the initial unknowns on inputs and initial="exact" variables; no name twice.
template <class Bad>
void check_dependencies(const ModelDescription& d, Bad bad) {
  std::map<std::string, const ScalarVariable*> by_name;
  for (const ScalarVariable& v : d.variables) by_name[v.name] = &v;
  auto check = [&](const ScalarVariable& v, const std::vector<std::string>& names, bool initial) {
    std::set<std::string> seen;
    for (const std::string& n : names) {
      const std::string who = "variable '" + v.name + "': dependency '" + n + "'";
      auto it = by_name.find(n);
      if (it == by_name.end()) {
        bad(who + " is not a variable");
        continue;
      }
      if (!seen.insert(n).second) bad(who + " is listed twice");
      const ScalarVariable& k = *it->second;
      const bool known =
          k.causality == Causality::input || (initial && effective_initial(k) == Initial::exact);
      if (!known) bad(who + " is not a known " + (initial ? "in initialization mode" : "input"));
    }
  };
  for (const ScalarVariable& v : d.variables) {
    if (v.dependencies) {
      if (v.causality != Causality::output) bad("variable '" + v.name + "': not an output");
      check(v, *v.dependencies, false);
    }
    if (v.initial_dependencies) check(v, *v.initial_dependencies, true);
  }
}

}  // namespace

Initial effective_initial(const ScalarVariable& v) {
  if (v.initial != Initial::none) return v.initial;
  const std::vector<Initial> allowed = allowed_initial(v.causality, v.variability);
  return allowed.empty() ? Initial::none : allowed.front();
}

std::vector<std::string> validate(const ModelDescription& d) {
  std::vector<std::string> problems;
  auto bad = [&](const std::string& what) { problems.push_back(what); };
  if (d.model_name.empty()) bad("modelName is empty");
  if (d.guid.empty()) bad("guid is empty");
  if (!structured_name(d.model_identifier) || d.model_identifier.find('.') != std::string::npos)
    bad("modelIdentifier '" + d.model_identifier + "' is not a C identifier");
  if (!(d.default_step_s > 0 && std::isfinite(d.default_step_s)))
    bad("DefaultExperiment stepSize must be > 0");

  std::set<std::string> unit_names;
  for (const UnitDefinition& u : d.units) {
    if (!unit_names.insert(u.name).second) bad("unit '" + u.name + "' is defined twice");
    const auto expected = known_unit(u.name);
    if (!expected)
      bad("unit '" + u.name + "' is not a unit this writer knows the SI exponents of");
    else if (expected->exponents != u.exponents || expected->factor != u.factor)
      bad("unit '" + u.name + "' has base-unit exponents that do not match its name");
  }

  std::set<std::string> names;
  std::map<BaseType, std::set<unsigned>> references;
  for (const ScalarVariable& v : d.variables) {
    const std::string who = "variable '" + v.name + "'";
    if (!structured_name(v.name)) bad(who + ": not a structured name");
    if (!names.insert(v.name).second) bad(who + ": name declared twice");
    if (!references[v.type].insert(v.value_reference).second)
      bad(who + ": value reference " + std::to_string(v.value_reference) + " is used by another " +
          to_string(v.type) + " variable (no aliases are declared)");
    if (v.variability == Variability::continuous && v.type != BaseType::real)
      bad(who + ": only a Real can be continuous");
    const std::vector<Initial> allowed = allowed_initial(v.causality, v.variability);
    if (allowed.empty()) {
      bad(who + ": causality " + to_string(v.causality) + " with variability " +
          to_string(v.variability) + " is not allowed");
    } else {
      bool ok = false;
      for (Initial i : allowed) ok = ok || i == v.initial;
      // Leaving the attribute out means the default (the first allowed value).
      if (!ok && !(v.initial == Initial::none && allowed.front() != Initial::none))
        bad(who + ": initial " + (v.initial == Initial::none ? "(none)" : to_string(v.initial)) +
            " is not allowed with causality " + to_string(v.causality) + " and variability " +
            to_string(v.variability));
    }
    const Initial effective = effective_initial(v);
    const bool has_start =
        v.type == BaseType::string ? v.start_string.has_value() : v.start.has_value();
    const bool needs_start = effective == Initial::exact || effective == Initial::approx ||
                             v.causality == Causality::input;
    const bool forbids_start =
        effective == Initial::calculated || v.causality == Causality::independent;
    if (needs_start && !has_start) bad(who + ": a start value is required");
    if (forbids_start && has_start) bad(who + ": a start value is not allowed");
    if (v.start && !std::isfinite(*v.start)) bad(who + ": start value is not finite");
    if ((v.min || v.max) && v.type != BaseType::real) bad(who + ": only a Real has a range here");
    if (v.min && v.max && !(*v.min < *v.max)) bad(who + ": min is not below max");
    if (v.start && ((v.min && *v.start < *v.min) || (v.max && *v.start > *v.max)))
      bad(who + ": start value outside [min, max]");
    if (v.type == BaseType::real) {
      if (v.unit.empty())
        bad(who + ": a Real without a unit");
      else if (!unit_names.count(v.unit))
        bad(who + ": unit '" + v.unit + "' is not in UnitDefinitions");
    } else if (!v.unit.empty()) {
      bad(who + ": only a Real has a unit");
    }
  }
  check_dependencies(d, bad);
  return problems;
}

}  // namespace modaltyre::fmu

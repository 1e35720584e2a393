#include "modaltyre/fmu/model_description.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

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

std::optional<UnitExponents> unit_exponents(const std::string& name) {
  //                                  kg m  s  A  K mol cd rad
  static const std::map<std::string, UnitExponents> known = {
      {"1", {0, 0, 0, 0, 0, 0, 0, 0}},      {"m", {0, 1, 0, 0, 0, 0, 0, 0}},
      {"s", {0, 0, 1, 0, 0, 0, 0, 0}},      {"m/s", {0, 1, -1, 0, 0, 0, 0, 0}},
      {"rad/s", {0, 0, -1, 0, 0, 0, 0, 1}}, {"N", {1, 1, -2, 0, 0, 0, 0, 0}},
      {"N.m", {1, 2, -2, 0, 0, 0, 0, 0}}};
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
    const auto expected = unit_exponents(u.name);
    if (!expected)
      bad("unit '" + u.name + "' is not a unit this writer knows the SI exponents of");
    else if (*expected != u.exponents)
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
    if (v.type == BaseType::real) {
      if (v.unit.empty())
        bad(who + ": a Real without a unit");
      else if (!unit_names.count(v.unit))
        bad(who + ": unit '" + v.unit + "' is not in UnitDefinitions");
    } else if (!v.unit.empty()) {
      bad(who + ": only a Real has a unit");
    }
  }
  return problems;
}

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

/// The shortest text that reads back as x.
std::string number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

const char* bool_attr(bool b) { return b ? "true" : "false"; }

}  // namespace

std::string to_xml(const ModelDescription& d) {
  const std::vector<std::string> problems = validate(d);
  if (!problems.empty()) {
    std::string msg = "the FMU's model description breaks FMI 2.0's rules:";
    for (const std::string& p : problems) msg += "\n  " + p;
    throw ComputationError(msg);
  }
  static const char* base_units[] = {"kg", "m", "s", "A", "K", "mol", "cd", "rad"};
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"" << escape(d.model_name)
    << "\" guid=\"" << escape(d.guid) << "\" description=\"" << escape(d.description)
    << "\" generationTool=\"" << escape(d.generation_tool)
    << "\" variableNamingConvention=\"structured\">\n";
  x << "  <CoSimulation modelIdentifier=\"" << escape(d.model_identifier)
    << "\" needsExecutionTool=\"false\" canHandleVariableCommunicationStepSize=\"true\""
       " canInterpolateInputs=\"false\" maxOutputDerivativeOrder=\"0\""
       " canRunAsynchronuously=\"false\" canBeInstantiatedOnlyOncePerProcess=\"false\""
       " canNotUseMemoryManagementFunctions=\"true\" canGetAndSetFMUstate=\"false\""
       " canSerializeFMUstate=\"false\" providesDirectionalDerivative=\"false\"/>\n";
  x << "  <UnitDefinitions>\n";
  for (const UnitDefinition& u : d.units) {
    x << "    <Unit name=\"" << escape(u.name) << "\">";
    std::string attrs;
    for (int k = 0; k < 8; ++k)
      if (u.exponents[k] != 0)
        attrs += std::string(" ") + base_units[k] + "=\"" + std::to_string(u.exponents[k]) + "\"";
    x << "<BaseUnit" << attrs << "/></Unit>\n";
  }
  x << "  </UnitDefinitions>\n";
  x << "  <LogCategories>\n";
  for (const std::string& c : d.log_categories)
    x << "    <Category name=\"" << escape(c) << "\"/>\n";
  x << "  </LogCategories>\n";
  x << "  <DefaultExperiment startTime=\"" << number(d.default_start_s) << "\" stepSize=\""
    << number(d.default_step_s) << "\"/>\n";
  x << "  <ModelVariables>\n";
  for (std::size_t k = 0; k < d.variables.size(); ++k) {
    const ScalarVariable& v = d.variables[k];
    x << "    <!-- index " << k + 1 << " -->\n";
    x << "    <ScalarVariable name=\"" << escape(v.name) << "\" valueReference=\""
      << v.value_reference << "\" description=\"" << escape(v.description) << "\" causality=\""
      << to_string(v.causality) << "\" variability=\"" << to_string(v.variability) << "\"";
    if (v.initial != Initial::none) x << " initial=\"" << to_string(v.initial) << "\"";
    x << ">\n      <" << to_string(v.type);
    if (v.type == BaseType::real) x << " unit=\"" << escape(v.unit) << "\"";
    if (v.type == BaseType::string && v.start_string)
      x << " start=\"" << escape(*v.start_string) << "\"";
    if (v.type == BaseType::boolean && v.start)
      x << " start=\"" << bool_attr(*v.start != 0) << "\"";
    if ((v.type == BaseType::real || v.type == BaseType::integer) && v.start)
      x << " start=\"" << number(*v.start) << "\"";
    x << "/>\n    </ScalarVariable>\n";
  }
  x << "  </ModelVariables>\n";
  x << "  <ModelStructure>\n    <Outputs>\n";
  for (std::size_t k = 0; k < d.variables.size(); ++k)
    if (d.variables[k].causality == Causality::output)
      x << "      <Unknown index=\"" << k + 1 << "\"/>\n";
  x << "    </Outputs>\n    <InitialUnknowns>\n";
  for (std::size_t k = 0; k < d.variables.size(); ++k) {
    const ScalarVariable& v = d.variables[k];
    const Initial initial = effective_initial(v);
    const bool calc = initial == Initial::calculated || initial == Initial::approx;
    if ((v.causality == Causality::output && calc) ||
        v.causality == Causality::calculated_parameter)
      x << "      <Unknown index=\"" << k + 1 << "\"/>\n";
  }
  x << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
  return x.str();
}

}  // namespace modaltyre::fmu

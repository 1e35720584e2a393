// modelDescription.xml of a ModelDescription (model_description.h): FMI 2.0 section 2.2's
// elements in the order its schema (fmi2ModelDescription.xsd) requires.
#include <algorithm>
#include <charconv>
#include <map>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/fmu/model_description.h"

namespace modaltyre::fmu {
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

void write_unit(std::ostringstream& x, const UnitDefinition& u) {
  static const char* base_units[] = {"kg", "m", "s", "A", "K", "mol", "cd", "rad"};
  x << "    <Unit name=\"" << escape(u.name) << "\"";
  if (!u.exponents) {
    x << "/>\n";  // no SI form with integer exponents
    return;
  }
  std::string attrs;
  for (int k = 0; k < 8; ++k)
    if ((*u.exponents)[k] != 0)
      attrs += std::string(" ") + base_units[k] + "=\"" + std::to_string((*u.exponents)[k]) + "\"";
  if (u.factor != 1) attrs += " factor=\"" + number(u.factor) + "\"";
  x << "><BaseUnit" << attrs << "/></Unit>\n";
}

void write_variable(std::ostringstream& x, const ScalarVariable& v, std::size_t index) {
  x << "    <!-- index " << index << " -->\n";
  x << "    <ScalarVariable name=\"" << escape(v.name) << "\" valueReference=\""
    << v.value_reference << "\" description=\"" << escape(v.description) << "\" causality=\""
    << to_string(v.causality) << "\" variability=\"" << to_string(v.variability) << "\"";
  if (v.initial != Initial::none) x << " initial=\"" << to_string(v.initial) << "\"";
  x << ">\n      <" << to_string(v.type);
  if (v.type == BaseType::real) x << " unit=\"" << escape(v.unit) << "\"";
  if (v.min) x << " min=\"" << number(*v.min) << "\"";
  if (v.max) x << " max=\"" << number(*v.max) << "\"";
  if (v.type == BaseType::string && v.start_string)
    x << " start=\"" << escape(*v.start_string) << "\"";
  if (v.type == BaseType::boolean && v.start) x << " start=\"" << bool_attr(*v.start != 0) << "\"";
  if ((v.type == BaseType::real || v.type == BaseType::integer) && v.start)
    x << " start=\"" << number(*v.start) << "\"";
  x << "/>\n    </ScalarVariable>\n";
}

/// One ModelStructure entry: its index and, when declared, its dependencies as indices in
/// ascending order (section 2.2.8).
void write_unknown(std::ostringstream& x, std::size_t index,
                   const std::optional<std::vector<std::string>>& dependencies,
                   const std::map<std::string, std::size_t>& index_of) {
  x << "      <Unknown index=\"" << index << "\"";
  if (dependencies) {
    std::vector<std::size_t> ids;
    for (const std::string& n : *dependencies) ids.push_back(index_of.at(n));
    std::sort(ids.begin(), ids.end());
    x << " dependencies=\"";
    for (std::size_t k = 0; k < ids.size(); ++k) x << (k ? " " : "") << ids[k];
    x << "\"";
  }
  x << "/>\n";
}

}  // namespace

std::string to_xml(const ModelDescription& d) {
  const std::vector<std::string> problems = validate(d);
  if (!problems.empty()) {
    std::string msg = "the FMU's model description breaks FMI 2.0's rules:";
    for (const std::string& p : problems) msg += "\n  " + p;
    throw ComputationError(msg);
  }
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
  for (const UnitDefinition& u : d.units) write_unit(x, u);
  x << "  </UnitDefinitions>\n";
  x << "  <LogCategories>\n";
  for (const std::string& c : d.log_categories)
    x << "    <Category name=\"" << escape(c) << "\"/>\n";
  x << "  </LogCategories>\n";
  x << "  <DefaultExperiment startTime=\"" << number(d.default_start_s) << "\" stepSize=\""
    << number(d.default_step_s) << "\"/>\n";
  x << "  <ModelVariables>\n";
  std::map<std::string, std::size_t> index_of;
  for (std::size_t k = 0; k < d.variables.size(); ++k) {
    write_variable(x, d.variables[k], k + 1);
    index_of[d.variables[k].name] = k + 1;
  }
  x << "  </ModelVariables>\n";
  x << "  <ModelStructure>\n    <Outputs>\n";
  for (std::size_t k = 0; k < d.variables.size(); ++k)
    if (d.variables[k].causality == Causality::output)
      write_unknown(x, k + 1, d.variables[k].dependencies, index_of);
  x << "    </Outputs>\n    <InitialUnknowns>\n";
  for (std::size_t k = 0; k < d.variables.size(); ++k) {
    const ScalarVariable& v = d.variables[k];
    const Initial initial = effective_initial(v);
    const bool calc = initial == Initial::calculated || initial == Initial::approx;
    if ((v.causality == Causality::output && calc) ||
        v.causality == Causality::calculated_parameter)
      write_unknown(x, k + 1, v.initial_dependencies, index_of);
  }
  x << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
  return x.str();
}

}  // namespace modaltyre::fmu

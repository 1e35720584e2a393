#pragma once
// An FMI 2.0 co-simulation model description: its scalar variables, units and capabilities, the
// rules of the standard that a description must obey (checked before it is written), and the
// modelDescription.xml text.
//
// Rules checked (FMI 2.0, section 2.2):
//  - value references unique within each base type (this FMU declares no aliases), names unique
//    and structured (identifiers joined by '.');
//  - causality x variability (section 2.2.7's table): parameter and calculatedParameter are
//    fixed or tunable, input discrete or continuous, independent continuous, output constant,
//    discrete or continuous, local any; only a Real may be continuous;
//  - initial per combination: parameter exact only; calculatedParameter calculated or approx;
//    output/local discrete or continuous calculated, exact or approx; constant exact; input and
//    independent none;
//  - start: required with initial exact or approx and for inputs, forbidden with calculated and
//    for the independent variable;
//  - units: every Real has a unit, every unit it names is defined once in UnitDefinitions, and a
//    defined unit's SI base exponents are those of its name (unit_exponents());
//  - ModelStructure: the outputs in order, and every output with initial calculated or approx
//    and every calculatedParameter among the initial unknowns (derived here, so always so).
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace modaltyre::fmu {

enum class Causality { parameter, calculated_parameter, input, output, local, independent };
enum class Variability { constant, fixed, tunable, discrete, continuous };
enum class Initial { none, exact, approx, calculated };
enum class BaseType { real, integer, boolean, string };

const char* to_string(Causality c);
const char* to_string(Variability v);
const char* to_string(Initial i);
const char* to_string(BaseType t);

struct ScalarVariable {
  std::string name;
  unsigned value_reference = 0;
  BaseType type = BaseType::real;
  Causality causality = Causality::local;
  Variability variability = Variability::continuous;
  Initial initial = Initial::none;  ///< none: the attribute is left out
  std::string unit;                 ///< Real only
  std::optional<double> start;      ///< Real, Integer, Boolean start
  std::optional<std::string> start_string;
  std::string description;
};

/// SI base-unit exponents in the order kg, m, s, A, K, mol, cd, rad.
using UnitExponents = std::array<int, 8>;
/// The exponents of the unit names this project writes ("1", "m", "s", "m/s", "rad/s", "N",
/// "N.m"); nullopt for another name.
std::optional<UnitExponents> unit_exponents(const std::string& name);

struct UnitDefinition {
  std::string name;
  UnitExponents exponents{};
};

struct ModelDescription {
  std::string model_name;
  std::string guid;
  std::string description;
  std::string model_identifier;
  std::string generation_tool;
  double default_start_s = 0, default_step_s = 1e-3;
  std::vector<std::string> log_categories;
  std::vector<UnitDefinition> units;
  std::vector<ScalarVariable> variables;
};

/// The initial attribute in force: the one stated, else the default of the causality/variability
/// pair (none where the pair is not allowed or takes no initial).
Initial effective_initial(const ScalarVariable& v);

/// The rules above; one sentence per violation naming the variable or unit (empty: valid).
std::vector<std::string> validate(const ModelDescription& description);

/// modelDescription.xml (UTF-8). ComputationError listing the violations for an invalid one.
std::string to_xml(const ModelDescription& description);

}  // namespace modaltyre::fmu

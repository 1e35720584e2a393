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
//    defined unit's SI base exponents and factor are those of its name (known_unit(); a unit
//    whose exponents are not integers, Bekker's k_c in kN/m^(n+1), is defined without them);
//  - min <= start <= max where given (Real only here), min < max;
//  - ModelStructure: the outputs in order, and every output with initial calculated or approx
//    and every calculatedParameter among the initial unknowns (derived here, so always so);
//    their `dependencies` (section 2.2.8) name only knowns: inputs for the outputs at a
//    communication point, inputs and initial="exact" variables for the initial unknowns.
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
  std::optional<double> min, max;  ///< Real: the range the FMU is designed for
  bool min_exclusive = false;      ///< not written (FMI has no open bound): the FMU refuses min
  std::string description;
  /// Outputs: the knowns they depend on at a communication point (empty: none, no direct
  /// feedthrough; absent: every known). By name, written as indices.
  std::optional<std::vector<std::string>> dependencies;
  /// Initial unknowns: the knowns they depend on in initialization mode (absent: every known).
  std::optional<std::vector<std::string>> initial_dependencies;
};

/// SI base-unit exponents in the order kg, m, s, A, K, mol, cd, rad.
using UnitExponents = std::array<int, 8>;

/// A unit: value in SI = factor x value in the unit (FMI 2.0 section 2.2.2's BaseUnit). Without
/// exponents the unit has no SI form with integer exponents (written without a BaseUnit).
struct UnitDefinition {
  std::string name;
  std::optional<UnitExponents> exponents = UnitExponents{};
  double factor = 1;
};

/// The units this project writes ("1", "m", "s", "m/s", "rad/s", "N", "N.m", and the soil
/// keys' "mm", "kPa", "MPa", "deg", "kPa.s", "kN/m3", "kN/m4", "kN/m^(n+1)", "kN/m^(n+2)");
/// nullopt for another name.
std::optional<UnitDefinition> known_unit(const std::string& name);

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

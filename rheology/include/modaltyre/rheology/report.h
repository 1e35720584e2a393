#pragma once
// What every identification method returns: named parameters with value, unit and standard
// error, the fit residual and the number of rows used. Values are in the unit named next to
// them (SI except K_Z, which the seed writes in mm N^-3/4).
#include <string>
#include <vector>

namespace modaltyre::rheology {

struct Parameter {
  std::string name;
  double value = 0.0;
  std::string unit;
  double std_error = 0.0;  ///< one standard error from the fit, 0 when exact (no redundancy)
};

struct FitReport {
  std::string method;
  std::vector<Parameter> parameters;
  double residual_rms = 0.0;   ///< RMS of the fit residuals, in residual_unit
  std::string residual_unit;
  int rows = 0;                ///< data rows (or samples) the fit used
  std::vector<std::string> notes;  ///< choices the method made (which formula, which source)

  /// The parameter with this name; throws ComputationError if absent (a bug).
  const Parameter& at(const std::string& name) const;
  bool has(const std::string& name) const;
};

}  // namespace modaltyre::rheology

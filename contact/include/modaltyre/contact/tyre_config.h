#pragma once
// The tyre configuration: what a YAML file such as configs/sf350.yaml describes, in SI units.
// Config keys carry their unit in the name (outer_radius_mm, modulus_MPa); conversion to SI
// happens here and nowhere else.
#include <string>
#include <vector>

#include "modaltyre/core/config_tree.h"

namespace modaltyre::contact {

struct TreadParams {
  double modulus_Pa = 6e6;      ///< storage (elastic) modulus E_tr of the tread rubber, > 0
  double tan_delta = 0.15;      ///< loss factor G_tr / E_tr (seed 001 eq. 8), >= 0
  double thickness_m = 0.008;   ///< radial thickness of the tread layer, > 0
  double width_m = 0.14;        ///< contact width of the 2D model's patch, > 0
  double poisson = 0.49;        ///< rubber Poisson ratio, shear modulus G = E / (2 (1 + nu))
};

struct Discretisation {
  double unit_length_m = 0.5e-3;  ///< arc length of one patch unit (seed 001 eq. 11)
  double window_m = 0.36;         ///< arc length of the candidate region around the contact centre
  int max_order = 0;              ///< highest harmonic order in the kernel, 0 = mesh Nyquist
};

struct SolverSettings {
  int max_iterations = 200;     ///< active-set iterations per load case
  double gap_tolerance = 1e-10; ///< relative gap tolerance of the complementarity check
};

struct ValidationSettings {
  std::vector<std::string> calibrate;  ///< dotted config keys to fit (at most two)
  std::vector<int> calibration_rows;   ///< 1-based rows of the measured file (at most two)
  std::vector<std::string> observables = {"sinking_mm"};  ///< fitted on those rows
};

struct TyreConfig {
  std::string source;           ///< config file path
  std::string name = "tyre";
  double outer_radius_m = 0.2948;
  double inflation_pressure_Pa = 230e3;
  std::string hammer_csv;       ///< resolved path of the hammer data
  bool extend_orders = true;
  double compliance_scale = 1.0;
  /// Bending term s2 of the dispersion extension [rad^2/s^2]; negative = as fitted to the
  /// resolved orders. Stating it lets a config add belt bending stiffness the hammer test cannot
  /// resolve (it acts on unmeasured orders only).
  double extension_s2 = -1.0;
  TreadParams tread;
  Discretisation mesh;
  SolverSettings solver;
  std::vector<double> loads_N;
  double horizontal_force_N = 0;
  ValidationSettings validation;
};

/// Reads every key of the tree into a TyreConfig; unknown keys, wrong types and out-of-range
/// values are InputErrors naming file, line and key.
TyreConfig read_tyre_config(const ConfigTree& tree);

/// Convenience: load a YAML file with --set overrides and read it.
TyreConfig load_tyre_config(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace modaltyre::contact

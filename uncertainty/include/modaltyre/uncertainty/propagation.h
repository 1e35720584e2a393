#pragma once
// From the inputs' standard deviations (inputs.h) to a band on every footprint output
// (docs/uncertainty.md). Linearised: a central difference of each output over each input at
// +-1 standard deviation, the outputs' variances summed over the (independent) inputs, the 95 %
// band +-1.96 sigma. The same differences measure each input's curvature; where an output's
// second difference exceeds `max_nonlinearity` of its first, the linearisation is not trusted
// and `auto` samples instead: Monte Carlo over every input at once (normal, seeded per sample
// so that any thread count gives the same numbers), mean, standard deviation and the 2.5 / 97.5
// percentiles. The model is rebuilt for each evaluation (the inputs move its kernels); the
// evaluations run in parallel (OpenMP).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "modaltyre/contact/operating_conditions.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/modal/mode_identification.h"
#include "modaltyre/uncertainty/inputs.h"

namespace modaltyre::uncertainty {

enum class Method { linear, sampled, automatic };

/// The Monte Carlo sample counts accepted. Above 2000 the band's ends gain nothing a reader can
/// use: with m samples the 2.5 % point's own probability scatters by sqrt(p (1 - p) / m), 0.35 %
/// at 2000 (one tenth of the 2.5 % it stands for), while every sample costs a model build and a
/// prediction (100 000 samples: about 1 h on the default footprint, 7.5 h on the 3D free
/// vibration).
constexpr int kMinSamples = 20, kMaxSamples = 2000;

struct PropagationOptions {
  Method method = Method::automatic;
  int samples = 200;              ///< Monte Carlo samples (kMinSamples..kMaxSamples)
  unsigned long seed = 20261127;  ///< the samples' seed
  int threads = 0;                ///< OpenMP threads, 0 = the default
  /// automatic: sample when an output's |f(+) + f(-) - 2 f0| / |f(+) - f(-)| exceeds this.
  double max_nonlinearity = 0.1;
  /// Called after each model evaluation (done, total): first the differences (1 + 2 inputs),
  /// then, when sampled, the samples (a new total); may be empty.
  std::function<void(int, int)> progress;
  /// Inputs beside the config's (collect_inputs), e.g. calibration_inputs() in validate.
  std::vector<UncertainInput> extra_inputs;
  /// Throws std::invalid_argument naming the field.
  void validate() const;
};

/// The outputs a band is given for, as the footprint JSON names them; the mean pressure is over
/// the interpolated contact area (contact/footprint_measures.h: smooth_mean_pressure_Pa).
inline const std::vector<std::string>& output_names() {
  static const std::vector<std::string> names = {"sinking_mm", "contact_length_mm", "width_mm",
                                                 "peak_pressure_kPa", "mean_pressure_kPa"};
  return names;
}

/// A prediction's values of output_names(), in that order.
std::vector<double> footprint_output_values(const contact::Prediction& p);

struct Band {
  double value = 0;  ///< at the nominal inputs (linear) or the samples' mean (sampled)
  double std = 0;
  double p025 = 0, p975 = 0;
};

struct CaseBands {
  double load_N = 0;
  std::vector<Band> bands;  ///< per output_names()
};

struct InputEffect {
  UncertainInput input;
  /// d sinking_mm / (1 sigma of the input), per case (footprint outputs; else the first output)
  std::vector<double> sinking_sensitivity;
  /// d output / (1 sigma of the input), [case][output_names()], the central differences.
  std::vector<std::vector<double>> sensitivity;
  double nonlinearity = 0;       ///< the largest second/first difference ratio
  std::string nonlinear_output;  ///< where it is (output name and load)
};

/// An order assignment of a frequency list mixed into the bands (modal.order_alternatives).
struct OrderAlternative {
  std::vector<int> orders;
  double probability = 0;
};

struct PropagationResult {
  std::string method;  ///< "linear" or "sampled"
  std::string check;   ///< how the method was checked, in words
  /// The assignments mixed in, the config's modal.orders first; empty without alternatives.
  std::vector<OrderAlternative> order_alternatives;
  std::vector<InputEffect> inputs;
  std::vector<CaseBands> cases;
  int evaluations = 0;  ///< model builds
};

/// Any outputs of a model of (config, modes), [row][output], e.g. tir export's fitted
/// coefficients or a transient's summary; `what` names the evaluation for an error message.
/// Throws ComputationError when the model fails. Called from several threads at once.
using Evaluator = std::function<std::vector<std::vector<double>>(
    const contact::TyreConfig&, const modal::ModeIdentification&, const std::string& what)>;

struct OutputSet {
  std::vector<std::string> names;  ///< per output
  /// Per output: false for a quantity whose second differences are a grid's, not the physics'
  /// (a maximum over cells); it is left out of the curvature check. Empty: all checked.
  std::vector<bool> curved;
  std::vector<std::string> row_labels;  ///< per row, for the check's words (e.g. "4000 N")
  /// The outputs at the nominal inputs when the caller already has them (its own run), [row]
  /// [output]; empty: evaluated here.
  std::vector<std::vector<double>> nominal;
};

/// The same propagation for any outputs (propagate() is it with the footprint's outputs).
/// The result's cases are the rows (load_N 0), their bands per `outputs.names`.
PropagationResult propagate_outputs(const contact::TyreConfig& config,
                                    const modal::ModeIdentification& modes,
                                    const Evaluator& evaluate, const OutputSet& outputs,
                                    const PropagationOptions& options = {});

/// One row of named outputs (a command's summary, fitted coefficients) at (config, modes).
using RowEvaluator = std::function<std::pair<std::vector<std::string>, std::vector<double>>(
    const contact::TyreConfig&, const modal::ModeIdentification&, const std::string& what)>;

/// propagate_outputs for one row whose outputs are `names` with the values `nominal` (the
/// caller's own run at the nominal inputs, not repeated here): a perturbation
/// whose row carries other names (a quantity that appears or vanishes) is a ComputationError
/// naming `command` and the input, not a band.
PropagationResult propagate_row(const contact::TyreConfig& config,
                                const modal::ModeIdentification& modes,
                                const RowEvaluator& evaluate, const std::vector<std::string>& names,
                                const std::vector<double>& nominal, const std::string& label,
                                const std::string& command, const PropagationOptions& options = {});

/// Outputs a caller adds to the footprint's per case, from each (perturbed) prediction: e.g.
/// the pressure map's cells. Their curvature is not checked (a grid's quantities); a case with
/// fewer than `count` values is padded with zeros (a band of zero width).
struct ExtraOutputs {
  std::size_t count = 0;
  std::string label = "extra output";  ///< their name in the check's words ("map cell")
  std::function<std::vector<double>(std::size_t case_index, const contact::Prediction&)> values;
};

/// Propagates the config's inputs (collect_inputs) to the cases. With no uncertain input every
/// band has zero width (method "linear", said in `check`). ComputationError when the nominal or a
/// perturbed prediction fails (with the input and its message).
PropagationResult propagate(const contact::TyreConfig& config,
                            const modal::ModeIdentification& modes,
                            const std::vector<contact::OperatingConditions>& cases,
                            const PropagationOptions& options = {});

/// The same with `extra` outputs after output_names() in every case's bands.
PropagationResult propagate(const contact::TyreConfig& config,
                            const modal::ModeIdentification& modes,
                            const std::vector<contact::OperatingConditions>& cases,
                            const PropagationOptions& options, const ExtraOutputs& extra);

}  // namespace modaltyre::uncertainty

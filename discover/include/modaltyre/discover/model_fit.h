#pragma once
// Fitting a model variant (the baseline's calibrated scalars plus the fitted parameters of some
// effects) to measured footprints, its information criterion and its cross-validated error.
//
// Residuals are relative, r = (predicted - measured) / |measured|, one per row and observed
// observable (a zero measurement carries no relative information and is skipped); a traction
// row's drawbar pull and torque are taken against a floor of the load where they cross zero
// (traction_evidence.h), and their zeros are kept. Noise is
// taken as Gaussian with one variance per observable (sinking, length, width and rolling
// resistance are measured with different instruments), profiled out of the likelihood:
//   BIC = sum_o n_o ln(max(RSS_o / n_o, floor^2)) + k ln(N),   N = sum_o n_o,
// floor = 1e-4 (0.01 %, below any footprint measurement) keeps noise-free synthetic data finite.
// Parameters are searched in a bounded transform (logistic in the value, or in its logarithm
// when the range spans two decades or more), so Levenberg-Marquardt never leaves the
// catalogue's [min, max].
#include <Eigen/Dense>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/solve_status.h"
#include "modaltyre/discover/traction_evidence.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::discover {

/// One free parameter of a model variant, in the units of its config key; its range and
/// transform are the specification's fit range (contact/parameter_spec.h).
struct FreeParameter {
  std::string key;  ///< dotted config key, e.g. "tread.modulus_MPa"
  double min = 0, max = 0;
  bool log_scale = false;  ///< SearchTransform::log_logistic, else logistic
  bool of_effect = false;  ///< an effect's parameter (else a baseline scalar)
  contact::EffectId effect = contact::EffectId::inflation_pressure;  ///< when of_effect
  double catalogue_default = 0;  ///< when of_effect: where a new effect's search starts
  std::function<double(const contact::TyreConfig&)> get;
  std::function<void(contact::TyreConfig&, double)> set;
};

/// The baseline's calibrated scalars that every variant re-fits: modal.compliance_scale and, on
/// the 2D patch, tread.modulus_MPa (the two the 2D SF-350 configs declare), on the 3D patch with
/// a circular crown footprint_3d.crown.radius_mm (the two the 3D config declares).
std::vector<FreeParameter> baseline_parameters(const contact::TyreConfig& config);

/// The fitted parameters of an effect (catalogue entries with fitted = true).
std::vector<FreeParameter> effect_parameters(contact::EffectId id);

/// A model variant: the config with extra effects switched on, and what is fitted.
struct Variant {
  std::vector<contact::EffectId> effects;  ///< switched on besides the config's own
  std::vector<FreeParameter> parameters;   ///< baseline scalars, then each effect's
  std::string name() const;                ///< "baseline" or "effect+effect"
};
Variant make_variant(const contact::TyreConfig& config,
                     const std::vector<contact::EffectId>& effects);

/// Evaluates relative residuals of a config on rows of a measurement set.
class Evaluator {
 public:
  /// Predictions on `model` (its mesh and modal basis) with each config's parameters; the
  /// traction rows (if any) by the model's traction on each config's soil (traction_evidence.h,
  /// `flexing` the tyre's flexing loss; null: none).
  Evaluator(const contact::TyreModel& model, const studies::MeasurementSet& data,
            const FlexingLoss& flexing = {});

  struct Entry {
    int row = 0;         ///< index into data.rows
    int observable = 0;  ///< index into data.observables
  };
  /// Entries of the given rows (all observed, non-zero measurements).
  std::vector<Entry> entries(const std::vector<int>& rows) const;
  /// Relative residuals of the entries; a row whose prediction fails contributes `failure`
  /// (1 = 100 %) to each of its entries and counts in `failures`. Entries must be grouped by
  /// row (as entries() gives them). The rows are predicted in parallel (set_threads) when the
  /// call is not already inside a parallel region; the result does not depend on it.
  std::vector<double> residuals(const contact::TyreConfig& config, const std::vector<Entry>& e,
                                int& failures) const;
  std::vector<double> residuals(const contact::TyreConfig& config,
                                const std::vector<Entry>& e) const {
    int failures = 0;
    return residuals(config, e, failures);
  }
  const studies::MeasurementSet& data() const { return data_; }
  const contact::TyreModel& model() const { return model_; }
  /// Threads over rows for calls outside a parallel region (0: OpenMP default).
  void set_threads(int threads) { threads_ = threads; }
  /// Footprints predicted so far (one per row and residuals() call), over all threads.
  long predictions() const { return predictions_.load(std::memory_order_relaxed); }
  /// Traction slip cases run so far (one per traction row's slip and pass and call).
  long traction_cases() const { return traction_ ? traction_->cases() : 0; }
  /// The window each group of traction rows rolls on (traction_evidence.h; empty: no rows).
  std::vector<TractionWindow> traction_windows() const {
    return traction_ ? traction_->windows() : std::vector<TractionWindow>{};
  }
  /// The model's traction for the traction rows among `rows` (traction_evidence.h), on
  /// `modes` (null: the basis identified for the rows).
  std::map<int, contact::TractionResult> traction(
      const contact::TyreConfig& config, const std::vector<int>& rows,
      const modal::ModeIdentification* modes = nullptr) const;

 private:
  const contact::TyreModel& model_;
  const studies::MeasurementSet& data_;
  std::shared_ptr<const TractionRows> traction_;  ///< null without traction rows
  int threads_ = 0;
  mutable std::atomic<long> predictions_{0};
};

struct FitResult {
  std::vector<double> values;  ///< per free parameter, config units
  /// Standard errors (config units) from the Gauss-Newton covariance of the residuals weighted
  /// by each observable's fitted noise level; computed only when asked (full fits).
  std::vector<double> standard_errors;
  /// The Jacobian the standard errors came from (d residual / d value per entry and free
  /// parameter, config units); empty where none were computed. The mesh check reuses it.
  Eigen::MatrixXd jacobian;
  contact::TyreConfig config;  ///< fitted config (effects on, values set)
  std::vector<Evaluator::Entry> entries;
  std::vector<double> residuals;      ///< relative, per entry
  std::map<std::string, double> rms;  ///< per observable
  double rms_all = 0;
  double bic = 0;
  int evaluations = 0;
  int failures = 0;                          ///< rows whose prediction failed at the optimum
  SolveStatus status = SolveStatus::failed;  ///< the search's (converged or max_iterations)
  bool ok() const { return modaltyre::ok(status); }
};

/// Jacobian of the relative residuals of `entries` with respect to the variant's parameters in
/// config units at `values`, by central differences (2 k evaluations; steps 1e-4 relative,
/// clipped to the parameter's range).
Eigen::MatrixXd jacobian(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                         const std::vector<double>& values,
                         const std::vector<Evaluator::Entry>& entries);

/// Standard errors from a Jacobian in config units at a fit's optimum: the Gauss-Newton
/// covariance (J^T W J)^-1, W = 1 / sigma_o^2 per observable (sigma_o the fit's RMS residual of
/// the observable); infinite when the parameters are not identifiable.
std::vector<double> standard_errors(const studies::MeasurementSet& data, const FitResult& fit,
                                    const Eigen::MatrixXd& jacobian);

/// The Jacobian's columns the rows read (a non-zero column; their indices in `read`), each row
/// divided by its observable's noise level (the fit's RMS, floored at 1e-4): the weighted
/// system standard_errors() and the mesh shift (mesh_bias.h) solve; `row_weights` (if given)
/// gets each row's 1 / noise level.
Eigen::MatrixXd weighted_read_columns(const studies::MeasurementSet& data, const FitResult& fit,
                                      const Eigen::MatrixXd& jacobian, std::vector<int>& read,
                                      Eigen::VectorXd* row_weights = nullptr);

/// The search variable of a parameter (bounded logistic transform, in the logarithm when
/// log_scale) and back.
double to_search(const FreeParameter& p, double value);
double from_search(const FreeParameter& p, double u);
/// d value / d u at u.
double search_derivative(const FreeParameter& p, double u);

/// Applies a variant's effects and parameter values to a config.
contact::TyreConfig apply(const contact::TyreConfig& base, const Variant& v,
                          const std::vector<double>& values);

/// Fits a variant on the given rows. `start` (config units) seeds the search; without it the
/// search starts from `base`'s values for the baseline scalars and for effects already on in
/// `base`, and from the best of a small grid around the catalogue defaults for the parameters
/// of effects `base` does not have on.
FitResult fit_variant(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                      const std::vector<int>& rows,
                      std::optional<std::span<const double>> start = std::nullopt,
                      bool standard_errors = false);

/// The FitResult of a variant at given values on given entries (residuals, RMS, BIC; one
/// evaluation; no standard errors).
FitResult evaluate_fit(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                       const std::vector<double>& values,
                       const std::vector<Evaluator::Entry>& entries);

/// BIC of residuals grouped by observable, k free parameters.
double bic(const std::vector<Evaluator::Entry>& entries, const std::vector<double>& residuals,
           int observables, int k);

struct CrossValidation {
  int folds = 0;
  bool one_step = false;  ///< folds re-fitted by one Gauss-Newton step (large_fit.h)
  int evaluations = 0;    ///< model evaluations (all rows of a fold each)
  /// Each fold's re-fitted values (config units; exact folds only): starts the fit on all rows
  /// may not have reached (large_fit.h, refit_from_folds).
  std::vector<std::vector<double>> fold_values;
  std::vector<double> residuals;  ///< held-out relative residual per entry of all rows
  std::vector<Evaluator::Entry> entries;
  std::map<std::string, double> rms;  ///< per observable
  double rms_all = 0;
};

/// k-fold cross-validation (leave-one-out when rows <= 8, else 6 folds by row index mod 6):
/// re-fit on the other rows from the full fit's values, predict the held-out rows.
CrossValidation cross_validate(const Evaluator& ev, const contact::TyreConfig& base,
                               const Variant& v, const FitResult& full);

/// RMS per observable of residuals over entries.
std::map<std::string, double> rms_by_observable(const studies::MeasurementSet& data,
                                                const std::vector<Evaluator::Entry>& entries,
                                                const std::vector<double>& residuals);

}  // namespace modaltyre::discover

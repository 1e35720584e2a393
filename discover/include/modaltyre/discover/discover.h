#pragma once
// The discrepancy workflow (`modaltyre discover`): find where the simulation and the measured
// data disagree, name the missing effect, add it to the model and show the gap shrink.
//
//  1. Locate: fit the baseline (the config's calibrated scalars, modal.compliance_scale and
//     tread.modulus_MPa, or footprint_3d.crown.radius_mm on the 3D patch, re-fitted on all rows)
//     and correlate the relative residual of every observable with every condition variable that
//     varies in the data (branch and surface as 0/1); report the strongest and the rows worst off.
//  2. Name: for every candidate effect the data can reveal (its regime variable varies; for
//     traction rows, traction_evidence.h, the effects acting on soil runs, when the slip varies; on
//     the 3D patch not the effects it refuses, contact_width among them: its width is the model's),
//     fit its parameters together with the baseline scalars, score it by Delta BIC against the
//     current model and by the cross-validated RMS (leave-one-out up to 8 rows, else 6-fold). It is
//     named only if Delta BIC > min_delta_bic AND the cross-validated RMS falls by at least
//     min_cv_gain (relative) on at least one observable while it grows by no more than
//     max_cv_loss on any and not at all pooled over all; else nothing is named. (Per observable
//     because an effect may close the length gap and leave a width gap no candidate explains.) With
//     an effect named, the search repeats on top of it for a further one (up to max_effects) while
//     a residual still correlates clearly with a condition.
//  3. Add and show: the augmented config (effects on, fitted values), the gap before and after
//     per observable, in-sample and cross-validated, per-row residuals for the plot.
//
// Evaluations run on a mesh of discover_unit_length_mm (default 2 mm: sinking within 0.01 % and
// length within 0.2 % of the 0.5 mm mesh on the SF-350, measured in docs/discover.md), in
// parallel over candidates (OpenMP), deterministic for any thread count.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/discover/detection_limit.h"
#include "modaltyre/discover/large_fit.h"
#include "modaltyre/discover/mesh_bias.h"
#include "modaltyre/discover/model_fit.h"
#include "modaltyre/discover/model_uncertainty.h"
#include "modaltyre/discover/profile_band.h"
#include "modaltyre/discover/traction_evidence.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::discover {

struct DiscoverOptions {
  double unit_length_mm = 2;  ///< evaluation mesh (0: the config's own)
  double min_delta_bic = 10;  ///< "very strong" evidence on the Kass-Raftery scale
  double min_cv_gain = 0.25;  ///< cross-validated RMS must fall by at least this fraction
  double max_cv_loss = 0.10;  ///< ... and grow on no observable by more than this fraction
  /// NamingRule::cv_gain_z: the gain asked for falls with the held-out entries n as
  /// min(min_cv_gain, 1 - 1/sqrt(1 + 4 z^2 / n)) (0: min_cv_gain at any number of rows).
  /// z = 2 since issue 23's measurement (docs/discover.md, "The naming rule's power"): no false
  /// name in 50 noise-only sets of 24, 96 and 384 rows, and power that grows with the rows.
  double cv_gain_z = 2;
  int max_effects = 2;
  /// Take the model's own uncertainty (the config's uncertain inputs, propagated) beside the
  /// measurement noise: each candidate's Delta BIC loses the share of its evidence those inputs
  /// could have produced (model_uncertainty.h) before the naming rule. Off: as before.
  bool model_uncertainty = false;
  /// After an effect is named, search for another only if a residual still correlates with a
  /// condition at least this strongly.
  double structure_correlation = 0.5;
  int threads = 0;  ///< 0: OpenMP default
  /// For each named effect, its fitted parameters' shift on half the evaluation unit length
  /// and the bands with it (mesh_bias.h): one evaluation of the rows on the fine mesh.
  bool mesh_check = true;
  /// Detection limits of the candidates left unnamed (detection_limit.h) and the rows to add.
  bool detection_limits = true;
  LimitOptions limits;
  /// Exact fitting and cross-validation up to fit.exact_rows rows, approximations above
  /// (large_fit.h).
  FitOptions fit;
  /// Traction rows: the tyre's flexing loss on the rigid road (traction_evidence.h; the
  /// command hands report::flexing_resistance_N; null: none, as `traction --speed-km-h 0`).
  FlexingLoss traction_flexing;
  /// Called with (phase, done, total) after each fit and each cross-validation: phase
  /// "baseline" (total 2), then "round 1", "round 2", ... (total 2 per testable candidate),
  /// then "detection limits" (one per candidate left unnamed).
  /// Thread-safe; done counts up from 1 within a phase.
  std::function<void(const std::string&, int, int)> progress;

  /// InputError naming the option (as the command line spells it) when discover() cannot use
  /// a value: unit_length_mm not a finite number in [0, 50], max_effects outside [1, 9],
  /// threads outside [0, 4096], fit.exact_rows below 4. discover()
  /// calls it first; the command calls it before reading any file.
  void validate() const;
};

struct RegimeFinding {
  std::string observable;
  std::string variable;      ///< condition column
  double correlation = 0;    ///< Pearson r of the residual with the variable
  double mean_residual = 0;  ///< relative
  std::string summary;       ///< e.g. "sinking_mm under-predicted, more so as hold_s grows"
};

struct CandidateScore {
  std::string name;
  bool testable = false;
  std::string reason;  ///< why it cannot be tested on these data, when !testable
  std::map<std::string, double> parameters;  ///< fitted, config keys (effect's and baseline's)
  double delta_bic = 0;
  /// With DiscoverOptions::model_uncertainty: the evidence the model's uncertain inputs could
  /// have produced, taken off delta_bic before the naming rule (model_uncertainty.h).
  double uncertainty_discount = 0;
  double cv_rms_before = 0, cv_rms_after = 0;         ///< all observables pooled, relative
  std::map<std::string, double> cv_before, cv_after;  ///< per observable
  std::map<std::string, double> standard_errors;      ///< of the fitted parameters
  double rms_after = 0;
  int failures = 0;
  bool significant = false;
  /// In the last round, for a testable candidate the final model does not carry: what these
  /// data could have revealed (detection_limit.h); limit.effect is empty where not computed.
  DetectionLimit limit;
};

/// When the last round names nothing: the rows to add for the candidate most likely to be
/// named at its catalogue default (highest power there).
struct MoreRows {
  std::string effect;
  std::string condition;  ///< the condition column its regime runs through
  double power_at_default = 0;
  int replicas = 0;    ///< times the rows must be repeated (0: more than LimitOptions allow)
  int extra_rows = 0;  ///< rows to add: (replicas - 1) x the rows given
  std::string text;    ///< in words
};

struct NamedEffect {
  std::string name;
  std::map<std::string, double> parameters;  ///< the effect's fitted parameters
  std::map<std::string, double> standard_errors;
  /// Two standard errors either side from the profile likelihood (profile_band.h); up to
  /// DiscoverOptions::fit.exact_rows rows, else the Gauss-Newton value +- 2 standard errors.
  std::map<std::string, ParameterBand> bands;
  /// Parameters that ended at a bound of their range: the data bound them from one side only
  /// (e.g. a stiffness "at least this large"), the value is not a measurement.
  std::vector<std::string> at_bound;
  /// With DiscoverOptions::mesh_check: how far the fitted values move when the rows are
  /// evaluated on half the unit length (mesh_bias.h), and the bands widened by the continuum
  /// estimate (twice that shift) on its side; empty with mesh.note saying why where not made.
  MeshBias mesh;
  std::map<std::string, ParameterBand> bands_with_mesh;
  double delta_bic = 0;
  double cv_rms_before = 0, cv_rms_after = 0;
};

struct RowResidual {
  int row = 0;                                        ///< 1-based
  std::map<std::string, double> before, after;        ///< in-sample, relative
  std::map<std::string, double> cv_before, cv_after;  ///< held-out, relative
};

struct DiscoverReport {
  std::string evaluation_mesh;  ///< e.g. "2 mm units"
  /// The candidate window each group of traction rows rolls on, decided from the data.
  std::vector<TractionWindow> traction_windows;
  std::map<std::string, double> gap_config;  ///< config as given, RMS relative per observable
  std::map<std::string, double> gap_before;  ///< baseline re-fitted, in-sample
  std::map<std::string, double> gap_after;
  std::map<std::string, double> cv_gap_before, cv_gap_after;
  std::vector<RegimeFinding> regimes;               ///< strongest first, one per observable
  std::vector<int> worst_rows;                      ///< 1-based, worst first (baseline)
  std::vector<NamedEffect> effects;                 ///< empty when nothing is significant
  std::vector<std::vector<CandidateScore>> rounds;  ///< candidates of each search round
  std::map<std::string, double> baseline_parameters, final_parameters;
  std::vector<RowResidual> rows;
  MoreRows more_rows;                      ///< effect empty when not computed
  std::vector<std::string> out_overrides;  ///< "key=value" that turn the config into the final one
  std::string conclusion;                  ///< one paragraph in words
  int fits = 0;
  long evaluations = 0;     ///< parameter sets evaluated (each on all rows of its fit)
  long footprints = 0;      ///< footprints predicted (one per row and evaluation)
  long traction_cases = 0;  ///< traction slip cases run (one per slip, pass and evaluation)
  /// "exact" or the approximations used on many rows (large_fit.h), in words.
  std::string method;
  /// With DiscoverOptions::model_uncertainty: the model's uncertain inputs of the last round
  /// (empty: none, the discount is 0).
  std::vector<std::string> uncertainty_inputs;
};

/// Rows discover accepts at most (InputError above: a 1000-row matrix costs ~20 s of CPU time,
/// growing in proportion to the rows).
inline constexpr int kMaxRows = 10000;

DiscoverReport discover(const contact::TyreConfig& config, const studies::MeasurementSet& data,
                        const DiscoverOptions& options = {});

}  // namespace modaltyre::discover

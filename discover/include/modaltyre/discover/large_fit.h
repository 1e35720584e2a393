#pragma once
// Fitting and cross-validating a model variant on many rows at an affordable cost.
//
// The exact procedure (model_fit.h: a multi-start search, then Levenberg-Marquardt, then one
// re-fit per cross-validation fold) evaluates the model ~350 times per candidate, each on every
// row: minutes for a test matrix of a few hundred rows. Above `exact_rows` rows two
// approximations take its place (docs/discover.md, "Many rows", checks them against the exact
// computation):
//
//  - Fit: the search runs on an evenly spread subset of the rows (farthest-point sampling in
//    the rank-scaled condition space), then finishes on all rows by Gauss-Newton steps with the
//    central-difference Jacobian of all rows at the subset's optimum (chord steps, each accepted
//    only when it lowers the cost). Standard errors use the same Jacobian.
//  - Cross-validation: the same 6 folds (rows i mod 6), each fold's re-fit replaced by one
//    Gauss-Newton step from the full fit on its training rows (the influence approximation of
//    the refit), and its held-out rows predicted exactly with the stepped parameters.
//
// Up to `exact_rows` rows, fit_and_cross_validate() is the exact procedure, bit for bit, and
// then refit_from_folds() (below): the fit is refined from a fold's optimum that fits all rows
// better than it.
#include <functional>
#include <vector>

#include "modaltyre/discover/model_fit.h"

namespace modaltyre::discover {

struct FitOptions {
  int exact_rows = 64;   ///< up to this many rows: the exact procedure
  int subset_rows = 40;  ///< rows of the search subset above it (at least 4 per parameter)
  int max_chord_steps = 6;
};

/// `rows` of the data, up to `count` of them spread evenly over the conditions that vary and
/// over which observables each row measures: greedy farthest-point sampling where every
/// condition is scaled by the rank of its value among the distinct values (0..1), so that the
/// levels of a test matrix count alike however they are spaced. Deterministic; sorted.
std::vector<int> spread_subset(const studies::MeasurementSet& data, const std::vector<int>& rows,
                               int count);

struct FitAndCv {
  FitResult fit;
  CrossValidation cv;
};

/// A variant's fit on all rows with standard errors, and its cross-validation: exact up to
/// options.exact_rows rows, else the approximations above. `tick` (optional) is called once
/// after the fit and once after the cross-validation.
FitAndCv fit_and_cross_validate(const Evaluator& ev, const contact::TyreConfig& base,
                                const Variant& v, const FitOptions& options = {},
                                const std::function<void()>& tick = nullptr);

/// The exact procedure's guard against a fit on all rows left worse than a start it already
/// has: each fold's optimum (cv.fold_values) is scored on all rows (one evaluation a fold); when
/// the best lowers the fit's sum of squared residuals by more than kFoldStartGain (relative), the
/// fit is refined from it (fit_variant with standard errors) and, when that lowers the sum,
/// replaces `fc.fit` and is cross-validated again. Returns whether the fit moved. Without it a
/// fit stopped in a worse basin than its own folds reach scores a worse BIC than the evidence
/// gives (bulldozing on LETE sand under the 3D default: 3.28 % in-sample against 1.69 % held out,
/// docs/discover.md "Hidden soil effects on the default tyre").
bool refit_from_folds(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                      FitAndCv& fc);

/// The relative drop of the sum of squares a fold's optimum must bring to count as another basin.
/// A refinement costs a fit and a whole cross-validation again; a drop below 1 % moves the BIC
/// by less than n ln(1.01) ~ 0.01 n (0.3 on 27 traction residuals), far below any naming
/// threshold, and on the soil sets such drops (0.1-0.3 %, fits stopped at their iteration limit
/// inside one basin) were common; the basin the guard exists for is far above it (bulldozing on
/// LETE sand: 3.28 % RMS in-sample against 1.69 % held out, a sum of squares 3.8 times larger).
inline constexpr double kFoldStartGain = 1e-2;

/// The approximate fit on `rows` (subset search, chord Gauss-Newton finish on all of `rows`);
/// `jacobian_search` receives the Jacobian of fit.entries in the search variables.
FitResult fit_variant_many_rows(const Evaluator& ev, const contact::TyreConfig& base,
                                const Variant& v, const std::vector<int>& rows,
                                const FitOptions& options, Eigen::MatrixXd* jacobian_search);

/// The one-step cross-validation of a fit on all rows (`jacobian_search` of its entries in the
/// search variables, as fit_variant_many_rows() gives it).
CrossValidation cross_validate_one_step(const Evaluator& ev, const contact::TyreConfig& base,
                                        const Variant& v, const FitResult& full,
                                        const Eigen::MatrixXd& jacobian_search);

}  // namespace modaltyre::discover

#pragma once
// What run_ema says when it is unsure (issue 38): the DOFs no FRF measured, modes whose shape or
// pole is poorly identified, a band that cuts modes, and an FRF type that most modes contradict.
// Private to ema/src (ema.cc calls it); the thresholds are named in docs/ema.md, "Warnings".
#include <Eigen/Dense>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/ema/ema.h"

namespace modaltyre::ema::detail {

/// A lightly damped tyre's modes are nearly real (proportional damping gives MPC 1; the bundled
/// modes on 80-350 Hz with 1 % noise: MPC >= 0.95). Below 0.9 most of the shape is complex:
/// two close modes merged, or a computational pole.
inline constexpr double kMinMpc = 0.9;
/// A pole found in fewer than a quarter of the upper half of the model orders is not stable in
/// the diagram (the selection keeps poles from 5 %: PoleSelection::min_recurrence).
inline constexpr double kMinRecurrence = 0.25;
/// A band edge closer to a mode than this many half-power bandwidths (2 zeta f) cuts its
/// resonance: the fit sees little more than one flank of the peak (the bundled modes on
/// 80-350 Hz, identified to 0.13 %, keep at least 1.6 bandwidths).
inline constexpr double kEdgeBandwidths = 1.5;
/// The band suggested with the default band reaches this many bandwidths beyond the lowest and
/// the highest identified modes.
inline constexpr double kSuggestedMarginBandwidths = 3.0;

/// One note per point and direction that no FRF measured ("point 7 tangential: no FRF ...");
/// `measured[d][i]`: direction d (0 radial, 1 tangential) at res.points[i].
std::vector<std::string> missing_dof_notes(const EmaResult& res,
                                           const std::vector<std::vector<bool>>& measured);

/// The hammer CSV's reader takes points as equally spaced within 1 % of the spacing
/// (modal/hammer_data.cc); angles from a file's geometry may not be.
inline constexpr double kSpacingTolerance = 0.01;

/// With angles from the geometry: a warning when the points are not equally spaced.
std::optional<std::string> spacing_warning(const EmaResult& res);

/// Warnings on the identified modes: MPC, recurrence, band edges; with the default band a
/// suggested --band around the identified modes.
std::vector<std::string> quality_warnings(const EmaResult& res, bool default_band,
                                          double data_lo_hz, double data_hi_hz);

/// How many of `poles` have a positive driving-point modal constant when the FRFs are read as
/// `type` (the check run_ema applies; channel `driving` is the driving point).
int positive_driving_constants(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                               FrfType type, const std::vector<std::complex<double>>& poles,
                               int driving);

/// When most poles fail the driving-point test (`failed` of `total`), the warning naming the FRF
/// type under which most would pass (read from the data), else nullopt.
std::optional<std::string> frf_type_warning(const std::vector<double>& freq_hz,
                                            const Eigen::MatrixXcd& frf, FrfType type,
                                            const std::vector<std::complex<double>>& poles,
                                            int driving, int failed);

}  // namespace modaltyre::ema::detail

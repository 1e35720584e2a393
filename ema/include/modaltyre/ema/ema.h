#pragma once
// Experimental modal analysis of a hammer test (docs/ema.md): FRFs -> stabilisation diagram
// (LSCF) -> chosen poles -> output-error refinement -> residues (LSFD) -> mass-normalised real
// shapes per point, radial and tangential, in the hammer CSV that modal::read_hammer_csv reads.
//
// Layout of the test: every FRF shares one DOF (the reference: the fixed accelerometer of a
// roving-hammer test or the fixed hammer point of a roving-accelerometer test; by reciprocity
// both give a row of the FRF matrix); the other DOFs are the measured points. Mass
// normalisation needs the driving-point FRF, whose response and reference are that DOF.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/ema/frf_set.h"
#include "modaltyre/ema/lscf.h"

namespace modaltyre::ema {

struct EmaOptions {
  double band_lo_hz = 0, band_hi_hz = 0;  ///< both 0: the data's lines above 0 Hz
  int max_order = 64;                     ///< highest LSCF model order, 4 ... kMaxOrder
  bool unscaled = false;  ///< no driving point: shapes scaled to a largest value of 1
  bool refine = true;     ///< output-error refinement of the chosen poles
  /// A mode whose driving-point value is below this fraction of its largest value cannot be
  /// scaled reliably (the reference sits near a node of it) and is left out, with a note.
  double min_driving_share = 0.1;
  /// A mode whose largest mass-normalised value is below this fraction of the median mode's
  /// (a modal mass over 25 times theirs) is taken for a computational pole and left out;
  /// unscaled, the square root of its peak receptance is compared instead.
  double min_amplitude_share = 0.2;
  StabilityCriteria stability;
  PoleSelection selection;
  void validate() const;  ///< InputError naming the option
};

inline constexpr int kMaxOrder = 200;

struct EmaMode {
  double freq_hz = 0, damping_ratio = 0;
  double mpc = 0;         ///< modal phase collinearity of the complex shape, 1 = real mode
  double complexity = 0;  ///< |imaginary part| / |shape| after the real normalisation
  double recurrence = 0;  ///< in the stabilisation diagram (PoleSelection)
  /// |A| / (2 zeta w^2): the receptance at resonance, root-sum-square over the FRFs [m/N]
  double peak_receptance = 0;
  /// Per point [kg^-1/2] (unscaled: largest = 1); NaN where no FRF measured the DOF.
  std::vector<double> radial, tangential;
  /// Standard deviations from the FRFs' noise (lsfd_covariance.h, docs/uncertainty.md section
  /// 5); NaN without the output-error refinement. The shapes' per point, NaN where unmeasured.
  double freq_std_hz = std::numeric_limits<double>::quiet_NaN();
  double damping_std = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> radial_std, tangential_std;
};

struct DroppedMode {
  double freq_hz = 0, damping_ratio = 0;
  std::string reason;
};

struct EmaResult {
  std::string path;
  FrfType frf_type = FrfType::accelerance;
  Dof reference;
  bool roving_hammer = false;  ///< the shared DOF is the response (reciprocity used)
  bool scaled = true;          ///< shapes are mass-normalised
  double band_lo_hz = 0, band_hi_hz = 0;
  std::vector<int> points;  ///< point numbers, ascending
  /// From the UFF geometry when the file has one, else equally spaced; 0 at the first point.
  std::vector<double> angle_deg;
  bool has_tangential = false, has_radial = false;
  std::vector<EmaMode> modes;  ///< ascending in frequency
  std::vector<DroppedMode> dropped;
  StabilisationDiagram diagram;
  std::vector<double> sum_freq_hz, sum_magnitude;  ///< sum of |H| over the FRFs, in the band
  double synthesis_error = 0;  ///< relative RMS of measured minus re-synthesised FRFs (band)
  std::vector<std::string> notes;
  /// Where the identification is unsure (docs/ema.md, "Warnings"): poor MPC or stabilisation,
  /// a band cutting modes, an FRF type most modes contradict, unevenly spaced points.
  std::vector<std::string> warnings;
};

/// Runs the identification. InputError (exit 2) for a layout it cannot use (no shared DOF, no
/// driving point without `unscaled`, a band with too few lines for the order); ComputationError
/// (exit 1) when no stable pole is found.
EmaResult run_ema(const FrfSet& set, const EmaOptions& options);

/// The hammer CSV of `fit-modes` and the tyre configs:
/// mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential; a DOF no FRF measured is an
/// empty cell. With standard deviations (the refinement on) the optional columns
/// freq_std_hz,damping_std,radial_std,tangential_std follow. Unscaled shapes carry a last column
/// `scaling` = `unscaled` (and a comment line saying so), which modal::read_hammer_csv reads as
/// HammerData::unscaled.
std::string hammer_csv(const EmaResult& result);

/// Resolves the FRF type: the file's when it states one (a different `given` is an InputError
/// naming the file), else `given`, else accelerance.
FrfSet with_frf_type(FrfSet set, std::optional<FrfType> given);

}  // namespace modaltyre::ema

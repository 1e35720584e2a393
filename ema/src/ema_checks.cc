// Warnings and notes of the EMA front end (ema_checks.h).
#include "ema_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "modaltyre/ema/lsfd.h"

namespace modaltyre::ema::detail {
namespace {

std::string hz(double f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f Hz", f);
  return buf;
}

}  // namespace

std::vector<std::string> missing_dof_notes(const EmaResult& res,
                                           const std::vector<std::vector<bool>>& measured) {
  std::vector<std::string> out;
  const bool has[2] = {res.has_radial, res.has_tangential};
  const char* name[2] = {"radial", "tangential"};
  for (int d = 0; d < 2; ++d) {
    if (!has[d]) {
      out.push_back(std::string("no ") + name[d] + " FRFs: the " + name[d] +
                    " shapes are not measured (empty in the hammer CSV, null in --json)");
      continue;
    }
    for (std::size_t i = 0; i < res.points.size(); ++i) {
      if (measured[d][i]) continue;
      out.push_back("point " + std::to_string(res.points[i]) + " " + name[d] +
                    ": no FRF measured; left out of the shapes (empty in the hammer CSV, null "
                    "in --json), not 0");
    }
  }
  return out;
}

std::optional<std::string> spacing_warning(const EmaResult& res) {
  const std::size_t n = res.points.size();
  if (n < 2) return std::nullopt;
  std::vector<std::pair<double, int>> at;
  for (std::size_t i = 0; i < n; ++i) at.emplace_back(res.angle_deg[i], res.points[i]);
  std::sort(at.begin(), at.end());
  const double nominal = 360.0 / double(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double next = i + 1 < n ? at[i + 1].first : at[0].first + 360;
    const double gap = next - at[i].first;
    if (std::abs(gap - nominal) > kSpacingTolerance * nominal) {
      char buf[300];
      std::snprintf(buf, sizeof buf,
                    "the points are not equally spaced: %.2f deg from point %d to point %d, "
                    "%.2f deg for equal spacing; fit-modes and the tyre model need equally "
                    "spaced points (the hammer CSV keeps the measured angles)",
                    gap, at[i].second, at[(i + 1) % n].second, nominal);
      return std::string(buf);
    }
  }
  return std::nullopt;
}

std::vector<std::string> quality_warnings(const EmaResult& res, bool default_band,
                                          double data_lo_hz, double data_hi_hz) {
  std::vector<std::string> out;
  int poor = 0;
  for (const auto& m : res.modes) {
    char buf[300];
    if (m.mpc < kMinMpc) {
      ++poor;
      std::snprintf(buf, sizeof buf,
                    "mode at %.1f Hz: MPC %.2f < %.2f, its shape is mostly complex (two close "
                    "modes merged, or a computational pole): do not use it without checking",
                    m.freq_hz, m.mpc, kMinMpc);
      out.push_back(buf);
    }
    if (m.recurrence < kMinRecurrence) {
      std::snprintf(buf, sizeof buf,
                    "mode at %.1f Hz recurs in %.0f %% of the upper model orders (< %.0f %%): "
                    "its pole is not stable in the diagram; check it with --plot",
                    m.freq_hz, 100 * m.recurrence, 100 * kMinRecurrence);
      out.push_back(buf);
    }
    const double reach = kEdgeBandwidths * 2 * m.damping_ratio * m.freq_hz;
    const bool cut_lo = m.freq_hz - reach < res.band_lo_hz && res.band_lo_hz > data_lo_hz;
    const bool cut_hi = m.freq_hz + reach > res.band_hi_hz;
    if (cut_lo || cut_hi) {
      std::snprintf(buf, sizeof buf,
                    "the band's %s edge (%.1f Hz) is within %.0f half-power bandwidths of the "
                    "mode at %.1f Hz: the band cuts its resonance; widen --band",
                    cut_lo ? "lower" : "upper", cut_lo ? res.band_lo_hz : res.band_hi_hz,
                    kEdgeBandwidths, m.freq_hz);
      out.push_back(buf);
    }
  }
  if (default_band && !res.modes.empty() && poor > 0) {
    // A band around the identified modes, kSuggestedMarginBandwidths bandwidths beyond the
    // lowest and the highest, within the data.
    const auto lowest = std::min_element(res.modes.begin(), res.modes.end(),
                                         [](auto& a, auto& b) { return a.freq_hz < b.freq_hz; });
    const auto highest = std::max_element(res.modes.begin(), res.modes.end(),
                                          [](auto& a, auto& b) { return a.freq_hz < b.freq_hz; });
    const double lo = std::max(
        data_lo_hz, lowest->freq_hz * (1 - kSuggestedMarginBandwidths * 2 * lowest->damping_ratio));
    const double hi = std::min(data_hi_hz, highest->freq_hz * (1 + kSuggestedMarginBandwidths * 2 *
                                                                       highest->damping_ratio));
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "%d of %zu modes have MPC < %.2f with the default band (every line above 0 Hz, "
                  "%s to %s): the lines far from the modes (near 0 Hz, where the residual terms "
                  "dominate) spoil the fit; try --band %.0f:%.0f around the modes",
                  poor, res.modes.size(), kMinMpc, hz(res.band_lo_hz).c_str(),
                  hz(res.band_hi_hz).c_str(), std::floor(lo), std::ceil(hi));
    out.push_back(buf);
  }
  return out;
}

int positive_driving_constants(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                               FrfType type, const std::vector<std::complex<double>>& poles,
                               int driving) {
  const LsfdFit fit = lsfd(freq_hz, frf, type, poles);
  int positive = 0;
  for (std::size_t k = 0; k < poles.size(); ++k) {
    const std::complex<double> a =
        std::complex<double>(0, 2 * poles[k].imag()) * fit.residues(driving, Eigen::Index(k));
    positive += a.real() > 0 ? 1 : 0;
  }
  return positive;
}

std::optional<std::string> frf_type_warning(const std::vector<double>& freq_hz,
                                            const Eigen::MatrixXcd& frf, FrfType type,
                                            const std::vector<std::complex<double>>& poles,
                                            int driving, int failed) {
  const int total = static_cast<int>(poles.size());
  if (total < 2 || 2 * failed <= total) return std::nullopt;
  FrfType best = type;
  int best_pass = total - failed;
  for (FrfType t : {FrfType::receptance, FrfType::mobility, FrfType::accelerance}) {
    if (t == type) continue;
    const int pass = positive_driving_constants(freq_hz, frf, t, poles, driving);
    if (pass > best_pass) best = t, best_pass = pass;
  }
  std::string w = std::to_string(failed) + " of " + std::to_string(total) +
                  " poles fail the driving-point test (modal constant not positive) with the FRFs "
                  "read as " +
                  to_string(type);
  if (best != type) {
    w += std::string("; read as ") + to_string(best) + ", " + std::to_string(best_pass) + " of " +
         std::to_string(total) + " pass: are the FRFs " + to_string(best) +
         "? (--frf-type, or the UFF file's record 9)";
  } else {
    w += "; no other FRF type does better: check the reference DOF's sign and the units";
  }
  return w;
}

}  // namespace modaltyre::ema::detail

#include "modaltyre/ema/ema.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "ema_checks.h"
#include "lsfd_basis.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ema/lsfd.h"
#include "modaltyre/ema/lsfd_covariance.h"

namespace modaltyre::ema {
namespace {

using detail::kTwoPi;  // lsfd_basis.h
using cd = std::complex<double>;

struct Layout {
  Dof shared;
  bool roving_hammer = false;
  std::vector<Dof> moving;  // per channel
  int driving = -1;         // channel whose moving DOF is the shared one
};

Layout layout_of(const FrfSet& set) {
  Layout l;
  const auto& first = set.channels.front();
  const auto all = [&](auto get) {
    for (const auto& c : set.channels) {
      if (!(get(c) == get(first))) return &c;
    }
    return static_cast<const FrfChannel*>(nullptr);
  };
  const FrfChannel* other_ref = all([](const FrfChannel& c) { return c.reference; });
  const FrfChannel* other_resp = all([](const FrfChannel& c) { return c.response; });
  if (other_ref && other_resp) {
    throw InputError({set.path, other_ref->line, ""},
                     "this FRF's reference (" + to_string(other_ref->reference) +
                         ") differs from the first FRF's (" + to_string(first.reference) +
                         "), and the responses differ too; ema needs one DOF shared by every "
                         "FRF (one reference, or one fixed response in a roving-hammer test)");
  }
  l.roving_hammer = other_ref != nullptr;
  l.shared = l.roving_hammer ? first.response : first.reference;
  for (std::size_t c = 0; c < set.channels.size(); ++c) {
    const auto& ch = set.channels[c];
    l.moving.push_back(l.roving_hammer ? ch.reference : ch.response);
    if (l.moving.back() == l.shared) l.driving = static_cast<int>(c);
  }
  return l;
}

// Real normalisation: the angle that puts most of the vector on the real axis.
double principal_angle(const Eigen::VectorXcd& a) {
  return 0.5 * std::arg((a.array() * a.array()).sum());
}

void drop_poles_out_of_bounds(std::vector<cd>& poles, std::vector<double>& recurrence, double lo,
                              double hi, double max_damping) {
  std::vector<cd> kept;
  std::vector<double> rec;
  for (std::size_t k = 0; k < poles.size(); ++k) {
    const double w = std::abs(poles[k]), z = -poles[k].real() / w, f = w / kTwoPi;
    bool twin = false;
    for (const cd& q : kept) twin = twin || std::abs(q - poles[k]) < 1e-4 * w;
    if (f >= lo && f <= hi && z > 0 && z <= max_damping && !twin) {
      kept.push_back(poles[k]);
      rec.push_back(recurrence[k]);
    }
  }
  poles = kept;
  recurrence = rec;
}

double largest_value(const EmaMode& m) {
  double a = 0;
  for (double v : m.radial) a = std::max(a, std::abs(v));
  for (double v : m.tangential) a = std::max(a, std::abs(v));
  return a;
}

// A mass-normalised shape far smaller than the others belongs to a modal mass many times
// theirs: a computational pole that absorbs what the residual terms miss (e.g. a mode just
// outside the band), not a mode of the tyre. Unscaled shapes have no mass; there the square
// root of the peak receptance (proportional to the shape's scale) stands in. Left out, with
// the reason.
void drop_insignificant(EmaResult& res, const EmaOptions& options) {
  if (res.modes.size() < 3) return;
  const auto size = [&](const EmaMode& m) {
    return res.scaled ? largest_value(m) : std::sqrt(m.peak_receptance);
  };
  std::vector<double> a;
  for (const auto& m : res.modes) a.push_back(size(m));
  std::nth_element(a.begin(), a.begin() + a.size() / 2, a.end());
  const double median = a[a.size() / 2];
  std::vector<EmaMode> kept;
  for (const auto& m : res.modes) {
    const double share = size(m) / median;
    if (share >= options.min_amplitude_share) {
      kept.push_back(m);
      continue;
    }
    char why[200];
    std::snprintf(why, sizeof why,
                  "its shape's scale is %.3f of the median mode's: a modal mass %.0f times "
                  "theirs, a computational pole",
                  share, 1 / (share * share));
    res.dropped.push_back({m.freq_hz, m.damping_ratio, why});
  }
  res.modes = kept;
}

}  // namespace

void EmaOptions::validate() const {
  // Up to 1e5 Hz, the FRF lines' limit (frf_set.cc): a band beyond any line is a typing error.
  if (band_lo_hz < 0 || band_hi_hz < 0 || (band_hi_hz > 0 && band_hi_hz <= band_lo_hz) ||
      !std::isfinite(band_lo_hz) || !std::isfinite(band_hi_hz) || band_hi_hz > 1e5) {
    throw InputError({"--band", 0, ""},
                     "the band must be LO:HI with 0 <= LO < HI <= 1e5 [Hz] (the FRF lines' range)");
  }
  if (max_order < 4 || max_order > kMaxOrder) {
    throw InputError({"--max-order", 0, ""},
                     "the model order must be 4 ... " + std::to_string(kMaxOrder));
  }
  if (!(min_driving_share > 0 && min_driving_share < 1)) {
    throw InputError({"min_driving_share", 0, ""}, "must be in (0, 1)");
  }
  if (!(min_amplitude_share > 0 && min_amplitude_share < 1)) {
    throw InputError({"min_amplitude_share", 0, ""}, "must be in (0, 1)");
  }
  stability.validate();
  selection.validate();
}

FrfSet with_frf_type(FrfSet set, std::optional<FrfType> given) {
  if (set.type_from_file) {
    if (given && *given != set.type) {
      throw InputError({set.path, set.channels.empty() ? 0 : set.channels.front().line,
                        "record 9 field 1 (ordinate numerator data type)"},
                       std::string("the file's FRFs are ") + to_string(set.type) +
                           ", --frf-type says " + to_string(*given));
    }
    return set;
  }
  set.type = given.value_or(FrfType::accelerance);
  return set;
}

EmaResult run_ema(const FrfSet& set, const EmaOptions& options) {
  options.validate();
  MODALTYRE_CHECK(!set.channels.empty(), "run_ema: no FRF");
  EmaResult res;
  res.path = set.path;
  res.frf_type = set.type;
  const Layout lay = layout_of(set);
  res.reference = lay.shared;
  res.roving_hammer = lay.roving_hammer;
  if (lay.roving_hammer) {
    res.notes.push_back("roving hammer: the response " + to_string(lay.shared) +
                        " is shared; the forces' DOFs are the points (reciprocity)");
  }
  if (lay.driving < 0 && !options.unscaled) {
    throw InputError({set.path, 0, ""},
                     "no driving-point FRF (response = reference = " + to_string(lay.shared) +
                         "): mass-normalised shapes need it; measure it, or pass --unscaled "
                         "for shapes scaled to a largest value of 1");
  }
  res.scaled = lay.driving >= 0 && !options.unscaled;

  // Points and their angles: from the file's geometry, else equally spaced in point order; 0 at
  // the first point.
  std::set<int> pts;
  for (const auto& d : lay.moving) {
    pts.insert(d.point);
    res.has_radial = res.has_radial || d.dir == Direction::radial;
    res.has_tangential = res.has_tangential || d.dir == Direction::tangential;
  }
  res.points.assign(pts.begin(), pts.end());
  const auto point_index = [&](int point) {
    return static_cast<std::size_t>(std::lower_bound(res.points.begin(), res.points.end(), point) -
                                    res.points.begin());
  };
  for (std::size_t i = 0; i < res.points.size(); ++i) {
    res.angle_deg.push_back(set.point_angle_deg.empty() ? 360.0 * double(i) / double(pts.size())
                                                        : set.point_angle_deg.at(res.points[i]));
  }
  if (!set.point_angle_deg.empty()) {
    res.notes.push_back(
        "point angles and directions from the file's geometry (datasets 15/2411, "
        "2420)");
    if (auto w = detail::spacing_warning(res)) res.warnings.push_back(*w);
  }
  std::vector<std::vector<bool>> measured(2, std::vector<bool>(res.points.size(), false));
  for (const auto& d : lay.moving)
    measured[d.dir == Direction::radial ? 0 : 1][point_index(d.point)] = true;
  for (auto& n : detail::missing_dof_notes(res, measured)) res.notes.push_back(std::move(n));

  // The band's lines (0 Hz is left out: the lower residual is singular there).
  std::vector<int> idx;
  for (std::size_t i = 0; i < set.freq_hz.size(); ++i) {
    const double f = set.freq_hz[i];
    if (f > 0 && (options.band_hi_hz == 0 || (f >= options.band_lo_hz && f <= options.band_hi_hz)))
      idx.push_back(static_cast<int>(i));
  }
  const int need = 2 * (options.max_order + 1);
  if (static_cast<int>(idx.size()) < need) {
    throw InputError({options.band_hi_hz > 0 ? "--band" : "--max-order", 0, ""},
                     "the band has " + std::to_string(idx.size()) +
                         " lines above 0 Hz; model "
                         "order " +
                         std::to_string(options.max_order) + " needs at least " +
                         std::to_string(need) + " (widen the band or lower --max-order)");
  }
  const int nf = static_cast<int>(idx.size()), no = static_cast<int>(set.channels.size());
  std::vector<double> fb(nf);
  Eigen::MatrixXcd h(nf, no), hn(nf, no);
  Eigen::VectorXd weight = Eigen::VectorXd::Ones(no);
  for (int i = 0; i < nf; ++i) fb[i] = set.freq_hz[idx[i]];
  for (int o = 0; o < no; ++o) {
    for (int i = 0; i < nf; ++i) h(i, o) = set.channels[o].values[idx[i]];
    const double rms = h.col(o).norm() / std::sqrt(double(nf));
    // Each FRF weighs the same in the pole estimation (radial and tangential differ in level).
    hn.col(o) = rms > 0 ? (h.col(o) / rms).eval() : h.col(o);
    if (rms > 0) weight(o) = 1 / rms;
  }
  res.band_lo_hz = fb.front();
  res.band_hi_hz = fb.back();
  res.sum_freq_hz = fb;
  for (int i = 0; i < nf; ++i) res.sum_magnitude.push_back(h.row(i).cwiseAbs().sum());

  res.diagram = lscf_diagram(fb, hn, options.max_order, options.stability);
  const auto chosen = select_poles(res.diagram, options.selection);
  if (chosen.empty()) {
    throw ComputationError("no pole of order " + std::to_string(options.max_order) + " recurs in " +
                           std::to_string(options.selection.min_recurrence) +
                           " of the orders above half of it: nothing is stable in the "
                           "stabilisation diagram (raise --max-order or change --band)");
  }
  std::vector<cd> poles;
  std::vector<double> recurrence;
  for (const auto& p : chosen) {
    poles.push_back(p.lambda());
    recurrence.push_back(p.recurrence);
  }
  if (options.refine) {
    const RefinedPoles r = refine_poles(fb, hn, set.type, poles);
    if (r.improved) {
      poles = r.poles;
    } else {
      res.notes.push_back("the output-error refinement did not lower the misfit; LSCF poles kept");
    }
    drop_poles_out_of_bounds(poles, recurrence, res.band_lo_hz, res.band_hi_hz,
                             options.selection.max_damping);
  }

  const LsfdFit fit = lsfd(fb, h, set.type, poles);
  res.synthesis_error = fit.relative_error;
  // The variance of the output-error estimate (docs/uncertainty.md section 5); the LSCF poles
  // alone (no refinement) have another estimator's, not computed.
  std::optional<LsfdCovariance> cov;
  if (options.refine && !poles.empty()) cov = lsfd_covariance(fb, h, set.type, poles, weight);
  int driving_failures = 0;
  for (std::size_t k = 0; k < poles.size(); ++k) {
    const double w = std::abs(poles[k]);
    EmaMode m;
    m.freq_hz = w / kTwoPi;
    m.damping_ratio = -poles[k].real() / w;
    m.recurrence = recurrence[k];
    // Modal constants A_o = phi_o phi_ref = 2 j w_d R_o (lsfd.h).
    const Eigen::VectorXcd a = cd(0, 2 * poles[k].imag()) * fit.residues.col(k);
    const double an = a.norm();
    if (!(an > 0)) {
      res.dropped.push_back({m.freq_hz, m.damping_ratio, "zero residues"});
      continue;
    }
    m.mpc = std::norm((a.array() * a.array()).sum()) / std::pow(a.squaredNorm(), 2);
    m.peak_receptance = an / (2 * m.damping_ratio * w * w);
    double theta = principal_angle(a);
    if (res.scaled && (a(lay.driving) * std::polar(1.0, -theta)).real() < 0) theta += M_PI;
    Eigen::VectorXcd rot = a * std::polar(1.0, -theta);
    m.complexity = rot.imag().norm() / an;
    Eigen::VectorXd real = rot.real();
    double scale = 1, exponent = 0.5;
    int scale_channel = lay.driving;
    if (res.scaled) {
      // A physical mode's driving-point constant phi_ref^2 is positive (phase near 0).
      if (a(lay.driving).real() <= 0) {
        ++driving_failures;
        res.dropped.push_back({m.freq_hz, m.damping_ratio,
                               "driving-point modal constant is not positive: not a physical "
                               "mode"});
        continue;
      }
      const double share = real(lay.driving) / real.cwiseAbs().maxCoeff();
      if (share < options.min_driving_share) {
        char why[160];
        std::snprintf(why, sizeof why,
                      "the reference is near a node of this mode (driving-point share %.3f < "
                      "%.3f): its shape cannot be scaled",
                      share, options.min_driving_share);
        res.dropped.push_back({m.freq_hz, m.damping_ratio, why});
        continue;
      }
      scale = 1.0 / std::sqrt(real(lay.driving));
    } else {
      Eigen::Index at;
      real.cwiseAbs().maxCoeff(&at);
      scale = 1.0 / real(at);
      scale_channel = static_cast<int>(at);
      exponent = 1;
    }
    // A DOF no FRF measured stays NaN: kept out of the shape, never 0 (issue 38).
    m.radial.assign(res.points.size(), std::numeric_limits<double>::quiet_NaN());
    m.tangential.assign(res.points.size(), std::numeric_limits<double>::quiet_NaN());
    for (int o = 0; o < no; ++o) {
      const std::size_t i = point_index(lay.moving[o].point);
      (lay.moving[o].dir == Direction::radial ? m.radial : m.tangential)[i] = real(o) * scale;
    }
    if (cov) {  // phi_o = q_o q_r^-e (lsfd_covariance.h), q = real
      const int mp = static_cast<int>(poles.size()), kk = static_cast<int>(k);
      m.freq_std_hz = m.freq_hz * std::sqrt(cov->pole_cov(kk, kk));
      m.damping_std = m.damping_ratio * std::sqrt(cov->pole_cov(mp + kk, mp + kk));
      const cd z = cd(0, 2 * poles[k].imag()) * std::polar(1.0, -theta);
      const Eigen::VectorXd sd = real_shape_std(*cov, kk, z, real, scale_channel, exponent);
      m.radial_std.assign(res.points.size(), std::numeric_limits<double>::quiet_NaN());
      m.tangential_std = m.radial_std;
      for (int o = 0; o < no; ++o) {
        const std::size_t i = point_index(lay.moving[o].point);
        (lay.moving[o].dir == Direction::radial ? m.radial_std : m.tangential_std)[i] = sd(o);
      }
    }
    res.modes.push_back(m);
  }
  drop_insignificant(res, options);
  std::sort(res.modes.begin(), res.modes.end(),
            [](const EmaMode& a, const EmaMode& b) { return a.freq_hz < b.freq_hz; });
  if (res.scaled) {
    if (auto w = detail::frf_type_warning(fb, h, set.type, poles, lay.driving, driving_failures)) {
      res.warnings.push_back(*w);
    }
  }
  for (auto& w :
       detail::quality_warnings(res, options.band_hi_hz == 0, fb.front(), set.freq_hz.back())) {
    res.warnings.push_back(std::move(w));
  }
  if (res.modes.empty()) {
    std::string why;
    for (const auto& d : res.dropped) {
      why += "; " + std::to_string(d.freq_hz) + " Hz: " + d.reason;
    }
    throw ComputationError("every stable pole was left out" + why);
  }
  return res;
}

std::string hammer_csv(const EmaResult& r) {
  std::string out;
  if (!r.scaled) {
    out +=
        "# shapes UNSCALED (largest value 1, not kg^-1/2): no driving-point FRF; a footprint "
        "from them has no physical scale\n";
  }
  // Standard deviations when every mode has them (the refinement on).
  bool with_std = !r.modes.empty();
  for (const auto& m : r.modes) with_std = with_std && std::isfinite(m.freq_std_hz);
  out += "mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential";
  if (with_std) out += ",freq_std_hz,damping_std,radial_std,tangential_std";
  out += r.scaled ? "\n" : ",scaling\n";
  const auto value = [](double v) {
    if (std::isnan(v)) return std::string();  // not measured
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6e", v);
    return std::string(buf);
  };
  char line[128];
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const auto& m = r.modes[k];
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      std::snprintf(line, sizeof line, "%zu,%.6f,%.6g,%d,%.6f,", k + 1, m.freq_hz, m.damping_ratio,
                    r.points[i], r.angle_deg[i]);
      out += line + value(m.radial[i]) + "," + value(m.tangential[i]);
      if (with_std) {
        out += "," + value(m.freq_std_hz) + "," + value(m.damping_std) + "," +
               value(m.radial_std[i]) + "," + value(m.tangential_std[i]);
      }
      out += r.scaled ? "\n" : ",unscaled\n";
    }
  }
  return out;
}

}  // namespace modaltyre::ema

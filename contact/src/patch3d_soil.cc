// The soil's section law of the 3D patch: see patch3d_soil.h. The reduction's outer iteration
// (patch3d.cc, traction3d.cc) linearises Phi at each section's current approach:
// d = c F + o with c = 1 / Phi'(d_k), o = d_k - c Phi(d_k).
#include "patch3d_soil.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace modaltyre::contact::detail {
namespace {

constexpr double kGapFloor_m = 1e-9;
// approach()'s known approaches answer its bracket's test only beyond this relative margin in
// force: the roots behind a section's force meet a relative 1e-13 (cell()), so the evaluated
// test could not come out otherwise.
constexpr double kKnownMargin = 1e-9;
constexpr double kNoRepeat = std::numeric_limits<double>::quiet_NaN();  ///< equal to no e

}  // namespace

SoilSections::SoilSections(std::vector<double> t, std::vector<double> z, std::vector<double> weight,
                           const ground::PressureSinkage& law, std::vector<double> area,
                           std::vector<double> z_max, SoilRate rate,
                           std::vector<const ground::PressureSinkage*> cell_law)
    : t_(std::move(t)),
      z_(std::move(z)),
      w_(std::move(weight)),
      law_(law),
      cell_law_(std::move(cell_law)),
      area_(std::move(area)),
      zmax_(std::move(z_max)),
      rate_(std::move(rate)),
      keep_starts_(cell_law_.empty()),
      floor_(t_.size()),
      d_(t_.size()) {
  const int S = static_cast<int>(t_.size()), K = classes();
  last_.assign(std::size_t(S) * K, -1.0);
  known_d_.assign(2 * std::size_t(S), std::numeric_limits<double>::infinity());
  known_F_.assign(2 * std::size_t(S), 0.0);
  repeat_e_.assign(std::size_t(S) * K, kNoRepeat);
  repeat_slope_.assign(std::size_t(S) * K, 0.0);
  if (!zmax_.empty()) {
    rut_.resize(zmax_.size());
    pv_.resize(zmax_.size());
    rest_.resize(zmax_.size());
    for (std::size_t a = 0; a < zmax_.size(); ++a) {
      rut_[a] = zmax_[a] > 0 ? this->law(a).rebound_depth_m(zmax_[a]) : 0.0;
      pv_[a] = zmax_[a] > 0 ? this->law(a).loading_Pa(zmax_[a]) : 0.0;
      rest_[a] = rate_.sinkage_m(a, rut_[a]);
    }
  }
  for (int i = 0; i < S; ++i) {
    double lowest = 1e300;
    for (int k = 0; k < K; ++k) lowest = std::min(lowest, z_[k] + rest_depth(i, k));
    floor_[i] = lowest;
    d_[i] = lowest;  // at the floor: F = 0
  }
}

// The cell force at compression e: the root of t f + Z(f / A; z_max) = e, with its derivative
// df/de = 1 / (t + Z'(p) / A). The memory's branch ends where the cell meets its virgin curve,
// at e_v = t A p_v + z_max (p_v = p(z_max)): beyond it the root is on the virgin curve
// (f > A p_v), below it on the branch (for a rigid-plastic soil the vertical branch at z_max:
// f = (e - z_max) / t exactly). Newton from the cell's last root (or the series estimate of tread
// and soil alone), safeguarded by bisection on the branch's bracket. With the rate term,
// t f + w z_a + (1 - w) Z = e is the same root for the spring t / (1 - w) and the compression
// (e - w z_a) / (1 - w), and df/de gains the factor 1 / (1 - w).
double SoilSections::cell(int i, int k, double e, double* dfde) const {
  const std::size_t a = idx(i, k);
  const bool rate = rate_.on();
  const double share = rate ? rate_.scale(a) : 1.0;
  if (e == repeat_e_[a]) {  // the root this cell's last solve ended on, exactly (see below)
    if (dfde) *dfde = rate ? 1.0 / (repeat_slope_[a] * share) : 1.0 / repeat_slope_[a];
    return last_[a];
  }
  if (dfde) *dfde = 0;
  const double e_in = e;
  const double zmax = memory(i, k), rut = rut_.empty() ? 0.0 : rut_[a];
  double t = t_[i];
  if (rate) {
    e = (e - rate_.weight[a] * rate_.start_m[a]) / share;
    t /= share;
  }
  if (!(e > rut)) return 0.0;
  const double A = area_[i];
  const ground::PressureSinkage& soil = law(a);
  const double pv = pv_.empty() ? 0.0 : pv_[a];
  const bool virgin = e >= t * A * pv + zmax;
  if (!virgin && soil.rigid_plastic()) {
    if (dfde) *dfde = 1.0 / (t * share);
    return (e - zmax) / t;
  }
  double lo = virgin ? A * pv : 0, hi = (e - (virgin ? zmax : rut)) / t;
  if (!virgin) hi = std::min(hi, A * pv);
  const double lo0 = lo, hi0 = hi;
  double f = last_[a];
  if (!(f > lo && f < hi)) {
    const double soil_alone = A * soil.pressure_Pa(e, zmax);
    f = soil_alone > 0 ? 1.0 / (1.0 / hi + 1.0 / soil_alone) : hi;
    f = std::clamp(f, lo, hi);
  }
  double slope = t;
  bool root = false;  // ended on the residual test at the f it evaluated
  for (int it = 0; it < 100; ++it) {
    const double p = f / A;
    double dz = 0;
    // On the virgin curve Z(p; z_max) = Z(p; 0): z_max is reached below A p_v.
    const double z = virgin ? soil.virgin_sinkage_m(p, dz) : soil.sinkage_m(p, zmax);
    if (!virgin) dz = soil.compliance_m_per_Pa(p, zmax);
    const double g = t * f + z - e;
    slope = t + dz / A;
    (g > 0 ? hi : lo) = f;
    if ((root = std::abs(g) <= 1e-13 * e) || hi - lo <= 1e-14 * hi) break;
    double next = f - g / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    f = next;
  }
  last_[a] = f;
  // A root strictly inside the fresh bracket that met the residual test is where a solve at the
  // same e restarts (from last_) and stops at its first evaluation, with the same slope: the
  // repeat returns it without the law's evaluation, bit for bit. Any other ending (the bracket
  // collapsed, the iterations ran out) would iterate on: no repeat then.
  const bool repeat = root && f > lo0 && f < hi0;
  repeat_e_[a] = repeat ? e_in : kNoRepeat;
  repeat_slope_[a] = slope;
  if (dfde) *dfde = rate ? 1.0 / (slope * share) : 1.0 / slope;
  return f;
}

// Phi(d) and dPhi/dd in one pass over the classes; at a section just touching, the stiffness of
// the tread of its lowest cells.
double SoilSections::section(int i, double d, double* stiffness) const {
  double F = 0, kk = 0;
  for (int k = 0; k < classes(); ++k) {
    double dfde = 0;
    const double e = d - z_[k];
    F += w_[k] * cell(i, k, e, stiffness ? &dfde : nullptr);
    if (stiffness) {
      const double lowest = z_[k] + rest_depth(i, k);
      kk += w_[k] * (e > lowest - z_[k] ? dfde : (lowest <= floor_[i] ? 1.0 / t_[i] : 0.0));
    }
  }
  if (stiffness) *stiffness = kk;
  return F;
}

double SoilSections::approach(int i, double F) const {
  const double z0 = floor_[i];
  if (!(F > 0)) return z0;
  double lo = z0, hi = z0 + F * t_[i];  // every cell's tread alone at least that long
  // Phi is non-decreasing: an approach known to carry F (with a margin far above the roots'
  // rounding) at or below hi answers the bracket's first test without evaluating it. Only where
  // the bracket keeps the cells' starts (below): otherwise its roots are the next starts.
  bool bracketed = false;
  for (int j = 0; j < 2 && !bracketed && keep_starts_; ++j)
    bracketed = known_d_[2 * i + j] <= hi && known_F_[2 * i + j] >= F * (1 + kKnownMargin);
  if (!bracketed) {
    // The bracket's trial approaches lie beyond the root: their cell roots would be the next
    // solves' Newton starts, far from the roots near d_. The section's own starts are kept.
    const auto first = std::ptrdiff_t(idx(i, 0)), K = std::ptrdiff_t(z_.size());
    if (keep_starts_) {
      saved_.resize(3 * z_.size());
      std::copy_n(last_.begin() + first, K, saved_.begin());
      std::copy_n(repeat_e_.begin() + first, K, saved_.begin() + K);
      std::copy_n(repeat_slope_.begin() + first, K, saved_.begin() + 2 * K);
    }
    double Fhi = 0;
    while ((Fhi = section(i, hi)) < F) hi = z0 + 2 * (hi - z0);
    known_d_[2 * i] = hi, known_F_[2 * i] = Fhi;
    if (keep_starts_) {
      std::copy_n(saved_.begin(), K, last_.begin() + first);
      std::copy_n(saved_.begin() + K, K, repeat_e_.begin() + first);
      std::copy_n(saved_.begin() + 2 * K, K, repeat_slope_.begin() + first);
    }
  }
  double d = std::clamp(d_[i], lo, hi);
  for (int it = 0; it < 100; ++it) {
    double slope = 0;
    const double Fd = section(i, d, &slope), g = Fd - F;
    known_d_[2 * i + 1] = d, known_F_[2 * i + 1] = Fd;
    (g > 0 ? hi : lo) = d;
    if (std::abs(g) <= 1e-12 * F || hi - lo <= 1e-13 * std::max(std::abs(hi), 1e-3)) break;
    double next = d - g / std::max(slope, 1e-300);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    d = next;
  }
  return d;
}

double SoilSections::depth(int i, int k, double f) const {
  return rate_.sinkage_m(idx(i, k), law(idx(i, k)).sinkage_m(f / area_[i], memory(i, k)));
}

void SoilSections::reduced(int i, double& c, double& o) const {
  const double d = std::max(d_[i], floor_[i]);
  double k = 0;
  const double F = section(i, d, &k);
  c = 1.0 / k;
  o = d - c * F;
}

bool SoilSections::consistent(int i, double F, double d, double tol) const {
  if (!(F > 0)) return d <= floor_[i] + tol;
  // The linear model's approach against the section's own at F, within the gap tolerance or
  // 1 nm (the energies the outer line search compares come from root solves: their last digits
  // cannot resolve the relative 1e-10 of the rigid law's exact patterns).
  return std::abs(approach(i, F) - d) <= std::max(tol, kGapFloor_m);
}

void SoilSections::cell_forces(int i, double d, double* f) const {
  for (int k = 0; k < classes(); ++k) f[k] = cell(i, k, d - z_[k]);
}

double SoilSections::energy(int i, double F, bool update) {
  double d = 0;
  const double psi = energy_at(i, F, d);
  if (update) d_[i] = d;
  return psi;
}

double SoilSections::energy_at(int i, double F, double& d) const {
  F = std::max(F, 0.0);
  d = approach(i, F);
  if (!(F > 0)) return 0.0;
  const double A = area_[i];
  double psi = 0;
  for (int k = 0; k < classes(); ++k) {
    const double f = cell(i, k, d - z_[k]);
    if (f > 0) {
      const double W =
          rate_.work_J_m2(idx(i, k), f / A, law(idx(i, k)).work_J_m2(f / A, memory(i, k)));
      psi += w_[k] * (t_[i] * f * f / 2 + A * W + z_[k] * f);
    }
  }
  return psi;
}

std::unique_ptr<SectionLaws> soil_sections(const std::vector<double>& t,
                                           const std::vector<double>& z,
                                           const ground::PressureSinkage& law,
                                           const std::vector<double>& area) {
  // The static footprint: one class per column (its cell forces are read per column), virgin.
  return std::make_unique<SoilSections>(t, z, std::vector<double>(z.size(), 1.0), law, area);
}

}  // namespace modaltyre::contact::detail

// The soil's section law for the 3D patch (patch3d_sections.h, docs/soil.md section 4): each cell
// of section i is its tread spring t_i in series with the soil under it, so a cell compressed by
// e = d - z_j carries f = phi(e), the root of t_i f + Z(f / A_i) = e (Z the soil's sinkage under
// the pressure on the cell's road area A_i, ground/pressure_sinkage.h, virgin soil). The section
// carries Phi(d) = sum_j phi(d - z_j), continuous and increasing; its least energy is
//   Psi(F) = sum_j [t f_j^2 / 2 + A W(f_j / A) + z_j f_j]   at d = Phi^-1(F),
// W the soil's work (int Z dp). The reduction's outer iteration linearises Phi at each section's
// current approach: d = c F + o with c = 1 / Phi'(d_k), o = d_k - c Phi(d_k).
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "modaltyre/ground/pressure_sinkage.h"
#include "patch3d_sections.h"

namespace modaltyre::contact::detail {
namespace {

constexpr double kGapFloor_m = 1e-9;

class Soil final : public SectionLaws {
 public:
  Soil(const std::vector<double>& t, const std::vector<double>& z,
       const ground::PressureSinkage& law, const std::vector<double>& area)
      : t_(t), z_(z), law_(law), area_(area), d_(t.size()) {
    zmin_ = *std::min_element(z_.begin(), z_.end());
    for (std::size_t i = 0; i < t.size(); ++i) d_[i] = zmin_;  // at the lowest drop: F = 0
  }

  // The cell force at compression e: the root of t f + Z(f / A) = e, with its derivative
  // df/de = 1 / (t + Z'(p) / A). Newton from the series estimate of tread and soil alone (the
  // root lies below both e / t and A p_soil(e)), safeguarded by bisection.
  double cell(int i, double e, double* dfde = nullptr) const {
    if (dfde) *dfde = 0;
    if (!(e > 0)) return 0.0;
    const double t = t_[i], A = area_[i];
    double lo = 0, hi = e / t;
    const double soil_alone = A * law_.loading_Pa(e);
    double f = soil_alone > 0 ? 1.0 / (1.0 / hi + 1.0 / soil_alone) : hi;
    double slope = t;
    for (int k = 0; k < 100; ++k) {
      const double p = f / A;
      const double g = t * f + law_.sinkage_m(p, 0.0) - e;
      slope = t + law_.compliance_m_per_Pa(p, 0.0) / A;
      (g > 0 ? hi : lo) = f;
      if (std::abs(g) <= 1e-13 * e || hi - lo <= 1e-14 * hi) break;
      double next = f - g / slope;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      f = next;
    }
    if (dfde) *dfde = 1.0 / slope;
    return f;
  }
  // Phi(d) and dPhi/dd in one pass over the cells; at a section just touching, the stiffness
  // of the tread of its lowest cells.
  double section(int i, double d, double* stiffness = nullptr) const {
    double F = 0, k = 0;
    for (double zj : z_) {
      double dfde = 0;
      F += cell(i, d - zj, stiffness ? &dfde : nullptr);
      if (stiffness) k += d - zj > 0 ? dfde : (zj <= zmin_ ? 1.0 / t_[i] : 0.0);
    }
    if (stiffness) *stiffness = k;
    return F;
  }
  double stiffness(int i, double d) const {
    double k = 0;
    section(i, d, &k);
    return k;
  }
  // The approach at force F: Phi(d) = F by Newton from the last approach, safeguarded by
  // bisection.
  double approach(int i, double F) const {
    if (!(F > 0)) return zmin_;
    double lo = zmin_, hi = zmin_ + F * t_[i];  // every cell's tread alone at least that long
    while (section(i, hi) < F) hi = zmin_ + 2 * (hi - zmin_);
    double d = std::clamp(d_[i], lo, hi);
    for (int k = 0; k < 100; ++k) {
      double slope = 0;
      const double g = section(i, d, &slope) - F;
      (g > 0 ? hi : lo) = d;
      if (std::abs(g) <= 1e-12 * F || hi - lo <= 1e-13 * std::max(std::abs(hi), 1e-3)) break;
      double next = d - g / std::max(slope, 1e-300);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      d = next;
    }
    return d;
  }

  void reduced(int i, double& c, double& o) const override {
    const double d = std::max(d_[i], zmin_);
    double k = 0;
    const double F = section(i, d, &k);
    c = 1.0 / k;
    o = d - c * F;
  }
  bool consistent(int i, double F, double d, double tol) const override {
    if (!(F > 0)) return d <= zmin_ + tol;
    // The linear model's approach against the section's own at F, within the gap tolerance or
    // 1 nm (the energies the outer line search compares come from root solves: their last
    // digits cannot resolve the relative 1e-10 of the rigid law's exact patterns).
    return std::abs(approach(i, F) - d) <= std::max(tol, kGapFloor_m);
  }
  void cell_forces(int i, double d, double* f) const override {
    for (std::size_t j = 0; j < z_.size(); ++j) f[j] = cell(i, d - z_[j]);
  }
  double energy(int i, double F, bool update) override {
    F = std::max(F, 0.0);
    const double d = approach(i, F);
    if (update) d_[i] = d;
    if (!(F > 0)) return 0.0;
    const double A = area_[i];
    double psi = 0;
    for (double zj : z_) {
      const double f = cell(i, d - zj);
      if (f > 0) psi += t_[i] * f * f / 2 + A * law_.work_J_m2(f / A, 0.0) + zj * f;
    }
    return psi;
  }

 private:
  std::vector<double> t_, z_;
  const ground::PressureSinkage& law_;
  std::vector<double> area_;
  std::vector<double> d_;  ///< each section's current approach (its linearisation point)
  double zmin_ = 0;
};

}  // namespace

std::unique_ptr<SectionLaws> soil_sections(const std::vector<double>& t,
                                           const std::vector<double>& z,
                                           const ground::PressureSinkage& law,
                                           const std::vector<double>& area) {
  return std::make_unique<Soil>(t, z, law, area);
}

}  // namespace modaltyre::contact::detail

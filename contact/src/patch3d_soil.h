#pragma once
// The soil's section law of the 3D patch (patch3d_sections.h, docs/soil.md sections 4 and 9),
// internal to the contact library; the static footprint (patch3d.cc, virgin soil) and steady
// rolling (traction3d.cc, the soil's memory per cell) share it.
//
// Each cell of section i is its tread spring t_i in series with the soil under its road area
// A_i, on a ground point that remembers the deepest sinkage z_max it was pressed to
// (ground/pressure_sinkage.h). A cell compressed by e = d - z (d the section's approach, z the
// column's crown drop) carries f = phi(e), the root of t_i f + Z(f / A_i; z_max) = e, and nothing
// while e <= Z(0; z_max) (the rut). The columns come in classes: columns with the same drop and
// the same memory carry the same force (the crown's two halves by symmetry; every column of a
// flat crown), so a class is solved once and counted `weight` times. A section carries
//   Phi(d) = sum_k w_k phi_k(d - z_k),   continuous and non-decreasing,
// with least energy Psi(F) = sum_k w_k [t f_k^2 / 2 + A W(f_k / A; z_max) + z_k f_k] at
// d = Phi^-1(F), W the soil's work (int Z dp, which includes the rut: Z(0; z_max) > 0).
#include <memory>
#include <vector>

#include "modaltyre/contact/soil_rate_term.h"
#include "modaltyre/ground/pressure_sinkage.h"
#include "patch3d_sections.h"

namespace modaltyre::contact::detail {

class SoilSections final : public SectionLaws {
 public:
  /// t: cell tread compliance per section [m/N]; z: drop per class [m]; weight: columns per
  /// class; area: a cell's road area per section [m^2]; z_max: memory per cell at
  /// [i * classes + k] (empty: virgin soil everywhere); rate: a viscous soil's rate term per
  /// cell in steady rolling (soil_rate_term.h: Z = w z_a + (1 - w) Z_el; off: none); cell_law: a
  /// cell's own law in place of `law` at [i * classes + k] (empty or null: `law`; Wong and
  /// Reece's rear region, wong_reece_flexible.h).
  SoilSections(std::vector<double> t, std::vector<double> z, std::vector<double> weight,
               const ground::PressureSinkage& law, std::vector<double> area,
               std::vector<double> z_max = {}, SoilRate rate = {},
               std::vector<const ground::PressureSinkage*> cell_law = {});

  int classes() const { return static_cast<int>(z_.size()); }
  /// A cell's force at compression e [N] (and df/de).
  double cell(int i, int k, double e, double* dfde = nullptr) const;
  /// Phi_i(d) and, if asked, dPhi_i/dd.
  double section(int i, double d, double* stiffness = nullptr) const;
  /// Phi_i^-1(F) by safeguarded Newton from the section's current approach.
  double approach(int i, double F) const;
  /// The approach below which section i carries nothing: min over classes of z + the rut.
  double floor(int i) const { return floor_[i]; }
  /// Start section i's linearisation at approach d (a warm start).
  void set_approach(int i, double d) { d_[i] = d; }
  double current_approach(int i) const { return d_[i]; }
  /// The soil's depth under a cell of section i, class k carrying f [m].
  double depth(int i, int k, double f) const;
  double memory(int i, int k) const { return zmax_.empty() ? 0.0 : zmax_[idx(i, k)]; }
  /// The surface under an unloaded cell: the rut, or with the rate term the surface recovering
  /// from the depth it arrived with.
  double rest_depth(int i, int k) const { return rest_.empty() ? 0.0 : rest_[idx(i, k)]; }

  void reduced(int i, double& c, double& o) const override;
  bool consistent(int i, double F, double d, double tol) const override;
  /// Per class (not per column): f[k] for k < classes().
  void cell_forces(int i, double d, double* f) const override;
  double energy(int i, double F, bool update) override;
  /// Psi_i(F) and the approach d = Phi_i^-1(F) it is taken at (the section's own approach is
  /// left as it is).
  double energy_at(int i, double F, double& d) const;

 private:
  std::size_t idx(int i, int k) const { return std::size_t(i) * z_.size() + k; }
  const ground::PressureSinkage& law(std::size_t a) const {
    return cell_law_.empty() || !cell_law_[a] ? law_ : *cell_law_[a];
  }
  std::vector<double> t_, z_, w_;
  const ground::PressureSinkage& law_;
  std::vector<const ground::PressureSinkage*> cell_law_;
  std::vector<double> area_, zmax_, rut_;  ///< rut per cell (empty: virgin)
  SoilRate rate_;
  /// approach()'s bracket keeps the cells' Newton starts (and may be answered from known
  /// approaches): not with cells of their own law (Wong and Reece's rear region, whose
  /// flow-stress law has a kink: there the roots' last bits follow their starts, and the
  /// rolling fixed point's stopping test turns that into a step more or less, ~1e-4).
  bool keep_starts_;
  std::vector<double> rest_;  ///< Z(0) per cell: the rut through the rate term (empty: virgin)
  std::vector<double> pv_;    ///< virgin pressure at the memory per cell
  mutable std::vector<double> last_;  ///< each cell's last root (Newton's start)
  /// The compression e whose solve ended on last_ by the residual test (NaN: none) and the
  /// slope there: a call at the same e returns them (cell()).
  mutable std::vector<double> repeat_e_, repeat_slope_;
  mutable std::vector<double> saved_;  ///< a section's cell starts kept over approach()'s bracket
  /// Per section, two approaches with the force they were found to carry: approach()'s last
  /// bracket end [2 i] and last Newton iterate [2 i + 1] (d = inf: none).
  mutable std::vector<double> known_d_, known_F_;
  std::vector<double> floor_;  ///< per section
  std::vector<double> d_;      ///< each section's approach (linearisation point)
};

}  // namespace modaltyre::contact::detail

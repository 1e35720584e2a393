#pragma once
// The 3D static footprint: cells on a grid along the road (x, the 2D model's patch units, one
// circumferential section each) and across the tread (y, columns of equal width), against a
// rigid flat road under load control (seed 001 sections 3.2-3.3 extended across the tread).
//
// Geometry: before loading, cell (i, j) is sag_i + z(y_j) above the road at zero sinking, sag_i =
// R0 (1 - cos theta_i) the arc's sag and z the crown drop of the tread profile (crown_profile.h).
// Cells exist only within the tread width (the shoulder limit).
//
// Tread: a spring per cell (seed 001 eq. 6-9 per unit area): k_r = E dy ds / h radially,
// k_t = G dy ds / h tangentially, G = E / (2 (1 + nu)); vertical compliance per cell
// t_i = cos^2 theta_i / k_r + sin^2 theta_i / k_t.
//
// Carcass: the belt section at theta_i is laterally rigid; the modal transfer functions (seed
// 001 eq. 1-5, 12; contact/tyre_model.h) act on the section resultants F_i = sum_j f_ij and move
// the section by w_i = (C F)_i, C the carcass-only vertical compliance of the 2D model.
//
// Contact conditions per cell: g_ij = sag_i + z_j + (C F)_i + t_i f_ij - delta >= 0, f_ij >= 0,
// f_ij g_ij = 0, sum f_ij = F_z.
//
// Reduction (exact for the laterally rigid section): with the section's approach
// d_i = delta - sag_i - (C F)_i the cells of section i are independent springs on the crown,
// f_ij = (d_i - z_j)_+ / t_i, so the section carries F_i = Phi_i(d_i) = sum_j (d_i - z_j)_+ / t_i,
// convex and increasing in d_i. The cell problem becomes one unknown per section: minimise
//   J(F) = 1/2 F^T C F + sag^T F + sum_i Psi_i(F_i),  F >= 0, sum F = F_z,
// Psi_i' = psi_i = Phi_i^-1 (the approach at force F_i). On a fixed lateral pattern (n_i cells in
// contact per section) Psi_i is quadratic and the problem is the 2D one with the section
// compliance t_i / n_i and the gap offset mean(z_j over the pattern): solved exactly by the
// 2D active-set solver. The pattern is updated from psi_i(F_i) (a Newton step on J, damped by a
// backtracking line search on J when a full step does not decrease it) until it is consistent.
// solve_cells() solves the cell problem directly (every cell an unknown) as the reference.
//
// Sidewalls' pneumatic softening (optional, settings.sidewall; sidewall_membrane.h): the
// sections' lost sidewall force e(u_i) ds acts on the carcass beside the contact forces, so the
// gap gains (C e ds)_i and u = C (F + e ds) is the sections' carcass displacement. Solved as a
// fixed point: the contact problem with e fixed (a known gap offset per section), e updated from
// u (Anderson mixing over settings.sidewall_anderson_depth steps), until the offset changes by
// less than settings.sidewall_tolerance x the sinking.
//
// Lateral belt (optional, LateralBelt): the section's belt strip bends across the tread, a beam
// with compliance G between its cells (docs/footprint.md section 7); the gap gains (G f_i)_j.
// The reduction stays exact: a section at approach d is then a small contact problem
// (min 1/2 f^T (G + t_i I) f + z^T f, f >= 0, sum f = F_i), affine in d on a fixed lateral
// pattern (compliance 1 / 1^T M_AA^-1 1 and offset in place of t_i / n_i and the mean drop).
//
// Rolling (Patch3dPhysics::rolling): C is not symmetric, J is no energy of the problem. The
// same pattern steps are a Josephy-Newton method on the sections' complementarity problem
// (each step solves the pattern-linearised problem exactly, by LU); a step that does not lower
// the natural residual sum_i min(c_i F_i, w_i)^2 (w_i = sag_i + (C F)_i + psi_i(F_i) - delta,
// c_i = t_i / columns) is backtracked.
//
// Shear-coupled tread (Patch3dPhysics::tread_coupling_m > 0): the cells are no longer
// independent, no section reduction holds; every cell is an unknown of one contact problem
// (patch3d_coupled.cc), started from the uncoupled reduction's contact cells.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "modaltyre/contact/patch3d_settings.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/solve_status.h"
#include "modaltyre/ground/pressure_sinkage.h"

namespace modaltyre::contact {

namespace detail {
class SectionLaws;   // patch3d_sections.h
class CoupledTread;  // patch3d_operators.h
}  // namespace detail

/// The lateral compliance of one section's belt strip [m/N]: G(k, j) is the mean deflection of
/// column k under a unit force spread over column j, for columns of equal width across the
/// tread and a section of arc length ds. Symmetric positive semi-definite; columns x columns.
Eigen::MatrixXd lateral_belt_compliance(const LateralBelt& belt, double tread_width_m, int columns,
                                        double arc_length_m);

/// One column's extent along the road (the contour per y).
struct ColumnEdges {
  bool contact = false;
  double rear_x_m = 0, front_x_m = 0;
};

/// The pressure map as a footprint image: one row per y (pressure_kPa[j][i] at x_mm[i],
/// y_mm[j]).
struct PressureMap {
  int first_section = 0;  ///< the section of x_mm[0] (the map spans the contact and a margin)
  std::vector<double> x_mm, y_mm;
  std::vector<std::vector<double>> pressure_kPa;
};

struct Patch3dResult {
  double load_N = 0;
  SolveStatus status = SolveStatus::failed;  ///< the contact solver's, or failed (not finite)
  std::string message;
  int pattern_iterations = 0;  ///< outer (lateral pattern) steps; 0 for solve_cells()
  int contact_iterations = 0;  ///< active-set iterations of the contact solver, all steps
  double sinking_m = 0;
  double length_m = 0;  ///< longest column's extent (the centre line for a crowned tread)
  double width_m = 0;   ///< widest section's lateral extent, 2 max_i half_width_m[i]
  double equilibrium_residual = 0;      ///< |sum f - F_z| / F_z
  double complementarity_residual = 0;  ///< max |f_ij g_ij| / (F_z sinking), over every cell
  double max_penetration_m = 0;         ///< max(-g_ij, 0)

  int sections = 0, columns = 0;
  double dy_m = 0;
  std::vector<double> x_m;              ///< deformed belt position of each section along the road
  std::vector<double> dx_m;             ///< road length of each section (ds cos theta)
  std::vector<double> y_m;              ///< centre of each column
  std::vector<double> column_drop_m;    ///< crown drop z_j of each column
  std::vector<double> section_force_N;  ///< F_i
  std::vector<double> section_approach_m;  ///< d_i = delta - sag_i - (C F)_i
  std::vector<double> cell_force_N;        ///< f_ij at [i * columns + j]
  std::vector<double> belt_deflection_m;   ///< lateral belt deflection v_ij (0: rigid belt)
  std::vector<double> half_width_m;        ///< lateral edge |y| per section (contour per x)
  std::vector<ColumnEdges> column_edges;   ///< longitudinal edges per column (contour per y)
  std::vector<char> section_active;        ///< F_i > 0 (warm start of the next load)
  /// sum_ij f_ij x_ij, x_ij the cell's deformed surface along the road: the contact forces'
  /// moment about the axle (rolling_speed: the rolling resistance x the loaded radius).
  double force_moment_Nm = 0;
  /// On a soil (Patch3dPhysics::soil): the soil's sinkage under every cell [m] (at
  /// [i * columns + j]; empty on the rigid road) and its deepest value.
  std::vector<double> soil_depth_m;
  double soil_sinkage_m = 0;
  /// Sidewall softening: the lost sidewall force e(u_i) ds per section [N] (empty: disabled)
  /// and the fixed-point steps taken.
  std::vector<double> sidewall_force_N;
  int sidewall_iterations = 0;

  double cell_force(int i, int j) const { return cell_force_N[std::size_t(i) * columns + j]; }
  double belt_deflection(int i, int j) const {
    return belt_deflection_m[std::size_t(i) * columns + j];
  }
  double pressure_Pa(int i, int j) const { return cell_force(i, j) / (dx_m[i] * dy_m); }
  double vertical_stiffness_N_m() const { return load_N / sinking_m; }
  bool ok() const { return modaltyre::ok(status); }
};

/// What the effects path (predictor.h) changes in the 3D patch against the tyre model's own:
/// the carcass (its kernels scaled, or rebuilt ones) and each cell's local compliance (tread
/// modulus and creep, a Winkler soil under the cell). Defaults: the model's own, bit for bit.
struct Patch3dPhysics {
  const modal::LagKernels* kernels = nullptr;  ///< rebuilt static kernels; null: the model's
  double carcass_scale = 1;                    ///< multiplies every carcass kernel
  const TreadParams* tread = nullptr;          ///< null: the model config's tread
  double tread_creep = 1;                      ///< tread compliance factor (tread_relaxation)
  /// Soil layer depth over its modulus, H / E2 [m/Pa]: a cell of road area A sinks by
  /// f H / (E2 A) more (static part of seed 000 eq. 23, as the 2D patch's soil_compliance).
  double soil_m_per_Pa = 0;
  /// Inflation pressure for the sidewalls' softening [Pa]; negative: the model config's.
  double inflation_pressure_Pa = -1;
  /// A deformable soil under every cell in series with its tread (ground/, docs/soil.md section
  /// 4; virgin soil; not with a lateral belt); null: the rigid road. Must outlive the Patch3d.
  const ground::PressureSinkage* soil = nullptr;
  /// tread_coupling: the Pasternak length l of a shear-coupled tread [m] (patch3d_tread.cc);
  /// 0: independent cell springs and the exact section reduction. With l > 0 every cell is an
  /// unknown (solve_cells' coupled solve); not with a soil or a rolling carcass.
  double tread_coupling_m = 0;
  /// rolling_speed: `kernels` are the steady-rolling ones (not symmetric): the section problem
  /// is a non-symmetric complementarity problem (LU inner solves, the outer steps backtracked
  /// on its natural residual instead of the energy).
  bool rolling = false;
};

/// The 3D patch on a tyre model's sections. Keeps a reference to the model (it must outlive
/// this object). solve() and solve_cells() are const and build their own operators: one
/// Patch3d may serve several threads.
class Patch3d {
 public:
  /// Columns allowed with a lateral belt (its compliance is a dense columns^2 matrix).
  static constexpr int kMaxLateralBeltColumns = 400;
  Patch3d(const TyreModel& model, Patch3dSettings settings, const Patch3dPhysics& physics = {});

  const TyreModel& model() const { return model_; }
  const Patch3dSettings& settings() const { return settings_; }
  int sections() const { return model_.candidates(); }
  int columns() const { return static_cast<int>(y_m_.size()); }
  const std::vector<double>& column_y_m() const { return y_m_; }
  const std::vector<double>& column_drop_m() const { return z_m_; }
  /// The lateral belt compliance of a section (lateral_belt_compliance); empty when rigid.
  const Eigen::MatrixXd& lateral_compliance() const { return G_; }
  /// Vertical tread compliance of one cell of section i [m/N].
  double cell_tread_compliance(int i) const { return t_[i]; }

  /// The laterally rigid reduction (see the top of this file); `warm` is a previous result's
  /// section_active, `warm_cells` its cell_force_N (the sections' lateral patterns start from
  /// the cells it loads; empty or of another size: from every cell). The solution does not
  /// depend on either (to rounding), only the steps to it.
  Patch3dResult solve(double load_N, std::span<const char> warm = {},
                      std::span<const double> warm_cells = {}) const;
  /// The same problem with every cell an unknown (reference for the reduction; slower).
  Patch3dResult solve_cells(double load_N) const;
  /// Loads in order, each warm-started from the previous result.
  std::vector<Patch3dResult> solve_all(const std::vector<double>& loads_N) const;

 private:
  /// `shift`: per cell, what besides its drop and own compression separates it from the road at
  /// the section's approach (the belt's lateral deflection, the coupled tread's neighbours).
  double lateral_half_width(const Patch3dResult& r, int i, const std::vector<double>& shift) const;
  /// The sections' lateral laws (patch3d_sections.h) of this patch, their patterns started
  /// from `warm_cells` (Patch3d::solve).
  std::unique_ptr<detail::SectionLaws> section_laws(std::span<const double> warm_cells = {}) const;
  /// The contact solve with the sections' extra carcass loads `extra` (empty: none), on the
  /// given laws (their lateral patterns carried from a previous solve) or fresh ones (null).
  /// `sections_only`: the result's sections (forces, approaches, contact flags) and cell forces
  /// only, for a fixed-point step (finish() completes the last one). The coupled solve when the
  /// tread is coupled, else the reduction.
  Patch3dResult solve_loaded(double load_N, std::span<const char> warm,
                             const Eigen::VectorXd& extra, detail::SectionLaws* laws = nullptr,
                             bool sections_only = false) const;
  Patch3dResult solve_reduced(double load_N, std::span<const char> warm,
                              const Eigen::VectorXd& extra, detail::SectionLaws* laws,
                              bool sections_only) const;
  /// Every cell an unknown with the coupled tread (patch3d_coupled.cc).
  Patch3dResult solve_coupled(double load_N, std::span<const char> warm,
                              const Eigen::VectorXd& extra, detail::SectionLaws* laws,
                              bool sections_only) const;
  /// For the coupled tread, per cell: its tread's share of the gap u (radial, through the layer,
  /// and its own tangential shear), its compliance to its own force, and its radial compression.
  void coupled_compression(const std::vector<double>& f, std::vector<double>& u,
                           std::vector<double>& own, std::vector<double>& radial) const;
  Patch3dResult finish(double load_N, const std::vector<double>& cell_force, double delta,
                       const Eigen::VectorXd& extra, Patch3dResult r,
                       bool sections_only = false) const;

  const TyreModel& model_;
  Patch3dSettings settings_;
  modal::LagKernels kernels_;  ///< the carcass kernels, scaled
  /// The carcass operator on kernels_; solves use copies (they share its FFT spectra).
  std::shared_ptr<const solvers::WeightedToeplitzCompliance> carcass_;
  std::vector<double> y_m_, z_m_;  ///< column centres and their crown drops
  std::vector<double> t_;          ///< cell tread compliance per section
  double k_radial_cell_ = 0, k_tangential_cell_ = 0;
  Eigen::MatrixXd G_;  ///< lateral belt compliance of a section (empty: laterally rigid)
  const ground::PressureSinkage* soil_ = nullptr;  ///< the soil under the cells (null: none)
  std::vector<double> cell_area_m2_;               ///< road area of a cell of each section
  double pressure_Pa_ = 0;  ///< inflation pressure of the sidewalls' softening
  bool symmetric_ = true;   ///< false: a rolling carcass
  /// The coupled tread (null: independent springs) and each section's tangential tread part.
  std::shared_ptr<const detail::CoupledTread> tread_;
  std::vector<double> t_tangential_;
};

/// The map cropped to the sections in contact and `margin` sections either side.
PressureMap pressure_map(const Patch3dResult& r, int margin = 2);

}  // namespace modaltyre::contact

#pragma once
// The transient on the 3D patch (docs/transient.md section 7): the 2D transient's carcass and hub
// (model.h) under the 3D patch's cells (contact/patch3d.h). A section is one candidate unit of
// the 2D model (a row of cells across the tread); its belt is laterally rigid, so every cell of
// section i sits on the carcass displacement u_i = T_i xi of its unit. Each cell has its own
// tread (seed 001 eq. 6-10 per cell of dy x ds): relaxed stiffness k_i = 1 / t_i (patch3d.h's
// cell compliance), instantaneous spring k_g = ratio k_i in series with a Kelvin-Voigt element
// (k', c'), so that f_ij = k_g max(0, p_ij - e_ij), c' De_ij/Dt + k' e_ij = f_ij, with
// p_ij = z + h(x_i, y_j, t) - s_i - z_j - u_i (z_j the crown drop). The section carries
// F_i = sum_j f_ij on the carcass: generalised forces T^T F, hub m z'' = F(t) - sum F_i.
//
// Column classes (exact reduction): columns with the same crown drop and the same road (the
// mirror pairs +-y of a symmetric crown, a centred cleat) obey the same equations from the same
// initial state, so they keep the same trajectory; one tread state per class and section stands
// for all of them (multiplicity mu_c), F_i = sum_c mu_c f_ic. A flat crown on a full-width road
// is one class of all columns: the 2D transient with the whole tread width.
//
// The residual eigenpairs the 2D model lumps in series with each unit's tread (model.h,
// residual_lumped d_i, per section) are lumped per cell as ny d_i: exact when the section's
// cells carry equal forces (a flat crown: the 2D model), otherwise it moves the section's
// compliance by d_i (ny / n_i - 1) F_i, below 2e-4 of the tread's at the default mesh
// (d_i / (t_i / n_i) = 1.5e-4; docs/transient.md section 7).
#include <Eigen/Dense>
#include <vector>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::transient {

/// The lateral layout: columns of the 3D patch grouped into classes.
struct CellClasses {
  int columns = 0;
  double dy_m = 0, tread_width_m = 0;
  std::vector<double> column_y_m, column_drop_m;
  std::vector<int> column_class;  ///< class of each column
  /// Per class: crown drop, |y| of its columns, multiplicity, whether the cleat covers it.
  std::vector<double> drop_m, abs_y_m;
  std::vector<int> multiplicity;
  std::vector<char> on_cleat;
  int size() const { return static_cast<int>(drop_m.size()); }
};

/// Classes of the columns of `settings` for a cleat of width `cleat_width_m` centred on the
/// tread (0 = the whole width). `merge` false keeps one class per column (the full per-cell
/// model, for tests of the reduction).
CellClasses column_classes(const contact::Patch3dSettings& settings, double cleat_width_m,
                           bool merge = true);

/// The 3D transient model: the 2D carcass model, the 3D patch's settings and the cell tread.
struct CellModel {
  const TransientModel* carcass = nullptr;  ///< not owned
  contact::Patch3dSettings patch;
  CellClasses classes;
  /// One cell of section i: relaxed vertical stiffness 1 / t_i, contact spring (k_g, or k_i
  /// without relaxation, in series with the lumped residual ny d_i), Kelvin-Voigt element.
  Eigen::VectorXd k_relaxed, k_contact, k_kv, c_kv;
  /// One cell's radial and tangential tread springs (seed 001 eq. 6-9, dy x ds).
  double k_radial_cell_N_m = 0, k_tangential_cell_N_m = 0;
  const TransientModel& M() const { return *carcass; }
};

/// The cell model of a transient model whose tyre config has a footprint_3d: section (throws
/// InputError otherwise). `cleat_width_m`: the cleat's width across the tread (0 = whole).
CellModel build_cell_model(const TransientModel& model, double cleat_width_m = 0,
                           bool merge_classes = true);

/// The 3D patch the cell model stands on (the static footprint: initial state, bounds).
contact::Patch3d static_patch(const CellModel& cm);

}  // namespace modaltyre::transient

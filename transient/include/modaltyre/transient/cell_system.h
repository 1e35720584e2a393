#pragma once
// The ODE of the 3D transient (cell_model.h, docs/transient.md section 7) under a scenario.
//
// y = [q | v | r | z, w | e of class 0 over its sections | e of class 1 | ...]: the carcass and
// hub states of the 2D model (model.h, the same layout up to e_index()), then one tread state
// per class and section where the class can touch in the scenario (its range, tread_window.h's
// argument per class; relaxation on only). The road input is that of the 2D model on the
// classes the cleat covers.
#include <Eigen/Dense>
#include <vector>

#include "modaltyre/transient/cell_model.h"
#include "modaltyre/transient/ode_system.h"
#include "modaltyre/transient/scenario.h"
#include "modaltyre/transient/tread_window.h"

namespace modaltyre::transient {

class CellSoil;

/// The static 3D footprint as the transient's initial state: section forces, per-class cell
/// forces (class-major, m per class) and the sinking (zero forces for no load).
struct StaticCells {
  Eigen::VectorXd F;  ///< section forces (m)
  Eigen::MatrixXd f;  ///< cell force per (section, class): m x classes
  Eigen::VectorXd d;  ///< section approach d_i = delta - s_i - (C F)_i (m)
  double sinking_m = 0;
  /// On a soil (cell_soil.h): the soil's depth under each (section, class) (m x classes; empty
  /// on the road).
  Eigen::MatrixXd soil_depth_m;
};
/// Patch3d::solve at `load_N` (ComputationError if it fails); the empty contact at 0.
StaticCells static_cells(const CellModel& cm, double load_N);

/// The sections each class can touch under the bounding static footprint `bound`: where its
/// undeformed-tread penetration d_i - z_c exceeds -(margin + cleat height) (tread_window.h's
/// bound, per class; an empty range: the class never touches).
std::vector<UnitRange> touchable_sections(const CellModel& cm, const ScenarioPlan& plan,
                                          const StaticCells& bound);

class CellSystem {
 public:
  /// `ranges`: the sections of each class that carry forces and tread states (empty: every
  /// section for every class; an empty range: the class never touches).
  /// `soil`: the cells' contact springs in series with a soil (cell_soil.h; not owned; null:
  /// the rigid road).
  CellSystem(const CellModel& cm, const ScenarioPlan& plan, std::vector<UnitRange> ranges = {},
             CellSoil* soil = nullptr);
  const CellSoil* soil() const { return soil_; }
  /// A contact cell's d f / d g (the contact spring; on a soil the series stiffness of the last
  /// forces()).
  double slot_stiffness(int k) const { return soil_ ? kd_soil_(k) : kc_slot_(k); }
  int size() const { return cm_.M().e_index() + ncells_ * (relax_ ? 1 : 0); }
  int cells() const { return ncells_; }  ///< (class, section) slots
  int tread_states() const { return relax_ ? ncells_ : 0; }
  const std::vector<UnitRange>& ranges() const { return ranges_; }
  int offset(int c) const { return offset_[c]; }  ///< first slot of class c
  /// Union of the ranges: the sections whose carcass displacement the forces need.
  UnitRange sections() const { return span_; }
  const CellModel& cell_model() const { return cm_; }
  const ScenarioPlan& plan() const { return plan_; }

  void rhs(double t, const double* y, double* ydot) const;
  /// Cell forces into f (cells() slots) and section forces into F (m; zero outside sections());
  /// with g (and P), also penetration()'s outputs of the same pass.
  void forces(double t, const double* y, Eigen::VectorXd& f, Eigen::VectorXd& F,
              Eigen::VectorXd* g = nullptr, Eigen::VectorXd* P = nullptr) const;
  /// Tip penetration g of every slot (cells()), and P_i = z - s_i - u_i over sections() into P
  /// (m entries; the penetration of the undeformed tread at the crown line).
  void penetration(double t, const double* y, Eigen::VectorXd& g, Eigen::VectorXd& P) const;
  /// d f / d g per slot for Newton's matrix (k_contact in contact and, while cells are
  /// switching, within 2 mm beyond each class's contact ends).
  void jacobian_stiffness(double t, const double* y, Eigen::VectorXd& kd) const;
  /// Cells (with their multiplicity) that entered or left since the last accepted step; flags
  /// the next Jacobian. Also checks the sections just outside each class's range (escaped()).
  int update_contact_set(double t, const double* y) const;
  bool escaped() const { return escaped_; }
  /// The cell forces of the last rhs() (the Newton iterate CVODE evaluated last).
  const Eigen::VectorXd& last_forces() const { return f_; }
  /// The cell and section forces at the state update_contact_set() accepted at t, from the
  /// penetration it computed there (no second pass); false when it accepted no state at t.
  bool accepted_forces(double t, const Eigen::VectorXd*& f, const Eigen::VectorXd*& F) const;
  double spin(double t) const;
  double spin_rate(double t) const;
  /// The hub's displacement z at (t, y): the state's, or the prescribed hub's (scenario.h).
  double hub_z(double t, const double* y) const { return plan_.hub_z(t, y[cm_.M().z_index()]); }
  /// Road height (and slope) under section i for class c at t.
  double road(double t, int i, int c, double* slope = nullptr) const;
  /// road(t, i, c, slope) for the sections i = lo .. lo + n - 1 into h (and slope when given):
  /// the same values, the cleat's rolled distance taken once.
  void road_heights(double t, int lo, int n, int c, double* h, double* slope = nullptr) const;
  std::vector<double> state_from(const StaticCells& s) const;
  std::vector<double> absolute_tolerances() const;

 private:
  void contact_coordinates(const double* y) const;

  /// penetration()'s pass; with f and F (sized), also the rigid road's cell and section forces
  /// (F zeroed by the caller).
  void slots(double t, const double* y, Eigen::VectorXd& g, Eigen::VectorXd& P, Eigen::VectorXd* f,
             Eigen::VectorXd* F) const;
  const CellModel& cm_;
  const ScenarioPlan& plan_;
  bool relax_ = false;
  std::vector<UnitRange> ranges_;
  std::vector<int> offset_;
  UnitRange span_;
  int ncells_ = 0;
  Eigen::MatrixXd CqT_, CrT_, TT_;    ///< Cq^T, Cr^T and T^T (a section's row contiguous)
  Eigen::VectorXd inv_c_, k_over_c_;  ///< per slot: 1 / c', k' / c'
  Eigen::VectorXd kc_slot_;           ///< per slot: contact spring
  Eigen::VectorXd drop_slot_;         ///< per slot: crown drop of its class
  mutable Eigen::VectorXd xi_, P_, f_, F_, phi_, G_, Vf_, g_, road_, g_work_;
  mutable std::vector<char> in_contact_;
  /// rhs()'s modal rows (ode_system.h's ModalRow) at the spin rows_Omega_, rows_dOmega_.
  mutable std::vector<ModalRow> modal_rows_;
  mutable double rows_Omega_ = 0, rows_dOmega_ = 0;
  CellSoil* soil_ = nullptr;
  mutable Eigen::VectorXd kd_soil_, f_acc_;  ///< on a soil: d f / d g per slot of the last forces()
  /// The forces at the last accepted state (update_contact_set(), accepted_forces()).
  mutable Eigen::VectorXd f_step_, F_step_;
  mutable double t_step_ = -1;
  mutable long switches_since_jacobian_ = 0;
  mutable bool escaped_ = false;
};

}  // namespace modaltyre::transient

#pragma once
// The pneumatic share of the vertical load (modal.pneumatic_share, docs/footprint.md section 8):
// a fraction beta of the inflation pressure p carried over the contact area A in parallel with
// the modal carcass, F_z = F_s + beta p A(F_s), F_s the load on the structural tyre (modal
// carcass and tread) whose solution gives A. beta = 1 is the flat pure-pressure membrane
// (contact pressure p on the flattened area); beta = 0 is the modal carcass alone, bit for bit.
// The linearised modes of the inflated tyre already carry the membrane's first-order share, so
// the share that is missing from them is not 1 (docs/footprint.md section 8): off by default.
//
// The area is continuous in the load (the interpolated patch edges), so F_s + beta p A(F_s) is
// continuous and increasing and the split is a bracketed root (Illinois regula falsi).
#include <functional>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/solve_status.h"
#include "modaltyre/contact/patch3d.h"

namespace modaltyre::contact {

/// The 3D patch's contact area [m^2]: over every column, dy times the length of each run of
/// consecutive cells in contact, its edges interpolated on the level function (a column may
/// touch in two runs, e.g. at both ends of the patch: the area stays continuous in the load).
double contact_area_m2(const Patch3dResult& r);
/// The 2D patch's contact area [m^2]: contact length x width.
double contact_area_m2(const FootprintResult& r, double width_m);

/// Adds the pneumatic pressure p_pn [Pa] over the contact area to a 3D result: each run's
/// p_pn dy (front - rear) goes to its cells in proportion to their overlap with [rear, front]
/// (the contact set is the structural one). Updates cell and section forces, the load and the
/// equilibrium residual.
void add_pneumatic_pressure(Patch3dResult& r, double pressure_Pa, double load_N);
/// The same on a 2D result of contact width `width_m`: p_pn width (front - rear) to the units in
/// contact in proportion to their overlap with [rear, front].
void add_pneumatic_pressure(FootprintResult& r, double pressure_Pa, double width_m, double load_N);

struct LoadSplit {
  SolveStatus status = SolveStatus::failed;  ///< converged, or why not (a failed solve: failed)
  double structural_load_N = 0;  ///< F_s (on failure: the last F_s solved)
  double area_m2 = 0;            ///< A(F_s)
  double residual_N = 0;         ///< F_s + p_pn A - F_z (on failure: at the last F_s solved)
  int solves = 0;
  bool ok() const { return modaltyre::ok(status); }
};

/// F_s with F_s + p_pn A(F_s) = F_z (|residual| <= tolerance F_z). `area_at(F_s, area)` solves
/// the structural tyre at F_s and returns false on failure. Bracket [F_z - p_pn A(F_z), F_z],
/// Illinois root (solvers/bracketed_root.h).
LoadSplit split_pneumatic_load(double load_N, double pressure_Pa,
                               const std::function<bool(double, double&)>& area_at,
                               double tolerance = 1e-10, int max_solves = 60);

}  // namespace modaltyre::contact

#include "modaltyre/contact/rolling_radius.h"

#include <cmath>
#include <sstream>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/patch3d.h"
#include "traction_kinematics.h"

namespace modaltyre::contact {
namespace {

// Sums of A a and A b over one row of contact points from its front edge (rear to front are
// points first..last; x_next the position of the first free point ahead).
struct StickSums {
  double a = 0, b = 0;
  void add_row(double R0, const std::vector<double>& theta, const std::vector<double>& x,
               const std::vector<double>& area, int first, int last, double x_front) {
    const double t = (x_front - x[last]) / (x[last + 1] - x[last]);
    const double theta_front = theta[last] + t * (theta[last + 1] - theta[last]);
    // j = a - rho b: the path at rho = 0 gives a, the ground's travel b = (a - j(rho = 1)).
    detail::ContourSlip tread(R0, 0.0, x_front, 0.0, theta_front);
    detail::ContourSlip both(R0, 1.0, x_front, 0.0, theta_front);
    for (int i = last; i >= first; --i) {
      const double ai = tread.advance(x[i], 0.0, theta[i]);
      const double bi = ai - both.advance(x[i], 0.0, theta[i]);
      a += area[i] * ai, b += area[i] * bi;
    }
  }
};

RollingRadius finish(const TyreModel& model, double sinking_m, const StickSums& sums) {
  RollingRadius r;
  const double R0 = model.config.outer_radius_m;
  r.deflection_m = sinking_m;
  r.loaded_radius_m = R0 - sinking_m;
  if (!(sums.b > 0)) {
    r.message = "rolling radius: no contact on the road";
    return r;
  }
  r.radius_m = sums.a / sums.b * R0;
  r.status = SolveStatus::converged;
  std::ostringstream msg;
  msg << "free rolling on the rigid road at r_e = " << r.radius_m * 1e3 << " mm";
  r.message = msg.str();
  return r;
}

RollingRadius failed(const std::string& why, bool window = false) {
  RollingRadius r;
  r.message = "rolling radius: the footprint on the rigid road failed: " + why;
  r.window_exceeded = window;
  return r;
}

}  // namespace

RollingRadius rolling_radius(const TyreModel& model, double load_N) {
  const double R0 = model.config.outer_radius_m;
  StickSums sums;
  if (!model.config.footprint_3d) {
    const FootprintResult f = solve_patch(model, static_matrix_free_operator(model), {load_N, 0.0});
    if (!f.ok()) return failed(f.message, f.window_exceeded);
    const int m = model.candidates();
    std::vector<double> area(m);
    for (int i = 0; i < m; ++i) area[i] = model.unit_length_m * std::cos(model.theta[i]);
    int first = -1, last = -1;
    for (int i = 0; i < m; ++i)
      if (f.active[i]) {
        if (first < 0) first = i;
        last = i;
      }
    if (first < 0) return failed("no unit in contact");
    std::vector<double> a_area(m, 0.0);
    for (int i = first; i <= last; ++i) a_area[i] = f.active[i] ? area[i] : 0.0;
    sums.add_row(R0, model.theta, f.contour_x_m, a_area, first, last, f.front_edge_x_m);
    return finish(model, f.sinking_m, sums);
  }
  const Patch3d patch(model, *model.config.footprint_3d);
  const Patch3dResult p = patch.solve(load_N);
  if (!p.ok()) return failed(p.message, p.message.find("candidate window") != std::string::npos);
  const int S = p.sections, ny = p.columns;
  const TreadSprings k = tread_springs(model.config.tread, p.dy_m, model.unit_length_m);
  std::vector<double> x(S), area(S);
  for (int j = 0; j < ny; ++j) {
    const ColumnEdges& e = p.column_edges[j];
    if (!e.contact) continue;
    int first = -1, last = -1;
    for (int i = 0; i < S; ++i) {
      const double f = p.cell_force(i, j);
      // The cell's tip: its section's belt position and its own tread spring (patch3d.cc).
      const double c = std::cos(model.theta[i]), sn = std::sin(model.theta[i]);
      x[i] = p.x_m[i] + f * sn * c * (1 / k.tangential_N_m - 1 / k.radial_N_m);
      area[i] = f > 0 ? p.dx_m[i] * p.dy_m : 0.0;
      if (f > 0) {
        if (first < 0) first = i;
        last = i;
      }
    }
    if (first <= 0 || last + 1 >= S)
      return failed("a column's contact reached the candidate window's edge", true);
    sums.add_row(R0, model.theta, x, area, first, last, e.front_x_m);
  }
  return finish(model, p.sinking_m, sums);
}

}  // namespace modaltyre::contact

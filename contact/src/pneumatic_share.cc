#include "modaltyre/contact/pneumatic_share.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "modaltyre/solvers/bracketed_root.h"

namespace modaltyre::contact {
namespace {

// Length of [a0, a1] within [b0, b1].
double overlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

// One run of consecutive cells in contact along a column: cells first..last, edges interpolated
// on the level function phi = d_i - z_j - v_ij (tread compression inside, minus the gap outside)
// between the run's end cells and their free neighbours, as the column edges (patch3d.h).
struct Run {
  int first = 0, last = 0;
  double rear_x_m = 0, front_x_m = 0;
};

// The runs of column j. A column may touch in separate runs (the belt's bending lifts the
// centre of an edge column): each is counted on its own, so the area grows continuously when a
// run appears (from zero length) or two merge.
std::vector<Run> runs_of_column(const Patch3dResult& r, int j) {
  const int S = r.sections, ny = r.columns;
  auto phi = [&](int i) {
    return r.section_approach_m[i] - r.column_drop_m[j] - r.belt_deflection(i, j);
  };
  auto edge = [&](int in, int out) {
    if (out < 0 || out >= S) return r.x_m[in];
    const double pin = phi(in), pout = phi(out);
    return r.x_m[in] + pin / (pin - pout) * (r.x_m[out] - r.x_m[in]);
  };
  std::vector<Run> runs;
  for (int i = 0; i < S; ++i) {
    if (!(r.cell_force_N[std::size_t(i) * ny + j] > 0)) continue;
    if (runs.empty() || runs.back().last != i - 1) runs.push_back({i, i});
    runs.back().last = i;
  }
  for (Run& run : runs) {
    run.rear_x_m = edge(run.first, run.first - 1);
    run.front_x_m = edge(run.last, run.last + 1);
  }
  return runs;
}

}  // namespace

double contact_area_m2(const Patch3dResult& r) {
  double area = 0;
  for (int j = 0; j < r.columns; ++j) {
    for (const Run& run : runs_of_column(r, j)) area += r.dy_m * (run.front_x_m - run.rear_x_m);
  }
  return area;
}

double contact_area_m2(const FootprintResult& r, double width_m) {
  return r.contact_length_m * width_m;
}

void add_pneumatic_pressure(Patch3dResult& r, double pressure_Pa, double load_N) {
  const int ny = r.columns;
  std::vector<double> cover;
  for (int j = 0; j < ny; ++j) {
    for (const Run& run : runs_of_column(r, j)) {
      // The run's p dy (front - rear) to its cells by their overlap with [rear, front].
      cover.assign(run.last - run.first + 1, 0.0);
      double sum = 0;
      for (int i = run.first; i <= run.last; ++i) {
        cover[i - run.first] = overlap(r.x_m[i] - 0.5 * r.dx_m[i], r.x_m[i] + 0.5 * r.dx_m[i],
                                       run.rear_x_m, run.front_x_m);
        sum += cover[i - run.first];
      }
      const double run_N = pressure_Pa * r.dy_m * (run.front_x_m - run.rear_x_m);
      for (int i = run.first; i <= run.last; ++i) {
        const double f =
            sum > 0 ? run_N * cover[i - run.first] / sum : run_N / (run.last - run.first + 1);
        r.cell_force_N[std::size_t(i) * ny + j] += f;
        r.section_force_N[i] += f;
      }
    }
  }
  double total = 0;
  for (double f : r.cell_force_N) total += f;
  r.load_N = load_N;
  r.equilibrium_residual = std::abs(total - load_N) / load_N;
}

void add_pneumatic_pressure(FootprintResult& r, double pressure_Pa, double width_m, double load_N) {
  std::vector<double> cover(r.units.size());
  double sum = 0;
  for (std::size_t k = 0; k < r.units.size(); ++k) {
    const PatchUnit& u = r.units[k];
    cover[k] =
        overlap(u.x_m - 0.5 * u.dx_m, u.x_m + 0.5 * u.dx_m, r.rear_edge_x_m, r.front_edge_x_m);
    sum += cover[k];
  }
  double total = 0;
  const double patch_N = pressure_Pa * width_m * r.contact_length_m;
  for (std::size_t k = 0; k < r.units.size(); ++k) {
    PatchUnit& u = r.units[k];
    if (sum > 0) {
      const double f = patch_N * cover[k] / sum;
      u.fz_N += f;
      u.pressure_Pa += f / (u.dx_m * width_m);
    }
    total += u.fz_N;
  }
  r.equilibrium_residual = std::abs(total - load_N) / load_N;
}

LoadSplit split_pneumatic_load(double load_N, double pressure_Pa,
                               const std::function<bool(double, double&)>& area_at,
                               double tolerance, int max_solves) {
  LoadSplit s;
  // h(F_s) = F_s + p A(F_s) - F_z: continuous and increasing, h(F_z) = p A(F_z) >= 0.
  std::vector<std::pair<double, double>> areas;  // (F_s, A) of every solve, for the root's A
  auto h = [&](double F) -> std::optional<double> {
    ++s.solves;
    double area = 0;
    if (!area_at(F, area) || !std::isfinite(area)) return std::nullopt;
    areas.emplace_back(F, area);
    return F + pressure_Pa * area - load_N;
  };
  auto done = [&](double F, double residual_N) {
    s.status = SolveStatus::converged;
    s.structural_load_N = F, s.residual_N = residual_N;
    for (const auto& [at, area] : areas) {
      if (at == F) s.area_m2 = area;
    }
    return s;
  };
  const double tolerance_N = tolerance * load_N;
  const std::optional<double> h_hi = h(load_N);
  if (!h_hi) return s;
  s.structural_load_N = load_N, s.residual_N = *h_hi;
  if (*h_hi <= tolerance_N) return done(load_N, *h_hi);
  // A(F_s) <= A(F_z) below F_z, so h(F_z - p A(F_z)) <= 0 - for the continuous patch. The
  // discrete one's area is not strictly monotone (cells enter in steps, a warm-started lateral
  // pattern settles within its tolerance), so h there may still be > 0: step down by it,
  // F <- F_z - p A(F), until the bracket closes (issue 45: a discover fit threw from here).
  const double floor_N = 1e-9 * load_N;
  double F_lo = std::max(load_N - *h_hi, floor_N);
  std::optional<double> h_lo = h(F_lo);
  while (h_lo && *h_lo > tolerance_N && F_lo > floor_N && s.solves < max_solves) {
    F_lo = std::max(F_lo - *h_lo, floor_N);
    h_lo = h(F_lo);
  }
  if (!h_lo) return s;
  s.structural_load_N = F_lo, s.residual_N = *h_lo;
  if (std::abs(*h_lo) <= tolerance_N) return done(F_lo, *h_lo);
  // No bracket within the solves allowed (or an h that is not a number): failed, F_s and h said.
  if (!(*h_lo < 0) || !(*h_hi > 0)) return s;
  const solvers::RootResult r = solvers::illinois_root(
      h, F_lo, *h_lo, load_N, *h_hi, {tolerance_N, std::max(1, max_solves - s.solves)});
  if (r.iterations > 0) s.structural_load_N = r.x, s.residual_N = r.fx;
  if (r.ok()) return done(r.x, r.fx);
  s.status = r.status;
  return s;
}

}  // namespace modaltyre::contact

// The predictor on the 3D patch (patch3d.h): the effects it takes, Bekker's width iterated on a
// soil, the result as a Prediction.
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include "modaltyre/ground/ground_settings.h"
#include "predictor_paths.h"

namespace modaltyre::contact::predictor_paths {
namespace {

// ---- the 3D patch (patch3d.h) ---------------------------------------------------------------

// A 3D result as a Prediction: the footprint's units are the sections in contact (resultant,
// centre-line pressure), its edges the longest column's, its contour the centre line's.
Prediction from_patch3d(const Patch3d& patch, Patch3dResult r, double elastic_load_N) {
  Prediction p;
  FootprintResult& f = p.footprint;
  f.status = r.status;
  f.message = r.message;
  f.iterations = r.contact_iterations;
  f.sinking_m = r.sinking_m;
  f.contact_length_m = r.length_m;
  f.equilibrium_residual = r.equilibrium_residual;
  f.complementarity_residual = r.complementarity_residual;
  f.active = r.section_active;
  double longest = -1;
  for (const auto& e : r.column_edges) {
    if (e.contact && e.front_x_m - e.rear_x_m > longest) {
      longest = e.front_x_m - e.rear_x_m;
      f.rear_edge_x_m = e.rear_x_m;
      f.front_edge_x_m = e.front_x_m;
    }
  }
  const auto& z = patch.column_drop_m();
  for (int i = 0; i < r.sections; ++i) {
    // Height of the centre line above the road: its gap, 0 in contact.
    const double gap = centre_line(
        r.columns, [&](int j) { return z[j] + r.belt_deflection(i, j) - r.section_approach_m[i]; });
    f.contour_x_m.push_back(r.x_m[i]);
    f.contour_height_m.push_back(std::max(gap, 0.0));
    if (!(r.section_force_N[i] > 0)) continue;
    PatchUnit u;
    u.x_m = r.x_m[i];
    u.dx_m = r.dx_m[i];
    u.fz_N = r.section_force_N[i];
    u.pressure_Pa = centre_line(r.columns, [&](int j) { return r.pressure_Pa(i, j); });
    f.units.push_back(u);
  }
  p.status = r.status;
  p.message = r.message;
  p.sinking_mm = r.sinking_m * 1e3;
  p.length_mm = r.length_m * 1e3;
  p.width_mm = r.width_m * 1e3;
  p.elastic_load_N = elastic_load_N;
  p.patch3d = std::make_shared<const Patch3dResult>(std::move(r));
  return p;
}

}  // namespace

// The 3D patch with the parameters' carcass level and kernels, tread and soil (patch3d.h
// Patch3dPhysics); the effects it cannot take fail with their reason.
Prediction patch3d_path(const TyreModel& m, const TyreParameters& P, const OperatingConditions& c,
                        const PredictOptions& options) {
  const EffectsConfig& E = P.effects;
  if (!(c.load_N > 0)) return failed("load must be greater than 0 N");
  for (const auto& e : effect_catalogue()) {
    if (!e.is_option() && E.enabled(e.id) && !e.refused_with_3d.empty()) {
      return failed(e.name + " cannot be combined with footprint_3d: " + e.refused_with_3d);
    }
  }
  if (c.horizontal_force_N != 0) {
    return failed("the 3D patch (footprint_3d) takes no horizontal force; use a 2D config");
  }
  double elastic = 0;
  std::string why;
  if (!elastic_load(E, c, elastic, why)) return failed(why);
  Patch3dPhysics physics;
  physics.carcass_scale = carcass_scale(m, P, c, elastic);
  modal::LagKernels flattened;
  const bool flattening = E.belt_flattening.enabled && E.belt_flattening.stiffness_MPa > 0;
  physics.rolling = E.rolling_speed.enabled && c.speed_kmh > 0;  // seed 001 eq. 2-5
  if (flattening || physics.rolling || pressure_acts(m, c)) {
    flattened = rebuilt_kernels(m, E, physics.carcass_scale, physics.rolling, flattening,
                                c.speed_m_per_s(), c.pressure_Pa());
    physics.kernels = &flattened;
  }
  if (E.tread_coupling.enabled) physics.tread_coupling_m = E.tread_coupling.coupling_length_m();
  physics.tread = &P.tread;
  physics.tread_creep = tread_creep(E, c);
  physics.inflation_pressure_Pa = c.pressure_Pa();  // the sidewalls' softening (row's pressure)
  if (E.soil_compliance.enabled && c.surface == Surface::soil) {
    physics.soil_m_per_Pa = E.soil_compliance.layer_m() / E.soil_compliance.modulus_Pa();
  }
  try {
    // On a soil: Bekker's b = min(contact width, contact length), iterated with the solution
    // (only k_c / b depends on it; docs/soil.md section 4).
    const ground::GroundSettings& G = m.config.ground;
    const bool soil = G.soil();
    const bool b_acts = G.model == ground::GroundModel::bekker && G.bekker.k_c > 0;
    double b = P.footprint_3d->tread_width_m;
    std::unique_ptr<ground::PressureSinkage> law;
    std::vector<char> warm(options.warm_active.begin(), options.warm_active.end());
    for (int it = 0;; ++it) {
      if (soil) {
        law = G.normal_law(b);
        physics.soil = law.get();
      }
      const Patch3d patch(m, *P.footprint_3d, physics);
      const bool warm_fits = static_cast<int>(warm.size()) == patch.sections();
      Patch3dResult r =
          patch.solve(elastic, warm_fits ? warm : std::vector<char>(), options.warm_cells);
      if (!r.ok()) return failed(r.status, r.message);
      const double next = std::min(r.width_m, r.length_m);
      if (soil && b_acts && std::abs(next - b) > 1e-7 * b) {
        if (it == 50) return failed("Bekker's width b = min(width, length) did not settle");
        warm = r.section_active;
        b = it < 10 ? next : 0.5 * (b + next);
        continue;
      }
      Prediction p = from_patch3d(patch, std::move(r), elastic);
      if (physics.rolling)  // the cells' moment about the axle over the loaded radius
        p.rolling_resistance_N =
            p.patch3d->force_moment_Nm / (m.config.outer_radius_m - p.patch3d->sinking_m);
      if (soil) {
        p.on_soil = p.footprint.on_soil = true;
        p.footprint.soil_sinkage_m = p.patch3d->soil_sinkage_m;
        p.footprint.tyre_deflection_m = p.footprint.sinking_m - p.footprint.soil_sinkage_m;
        p.footprint.bekker_width_m = b;
        p.soil_sinkage_mm = p.footprint.soil_sinkage_m * 1e3;
        p.tyre_deflection_mm = p.footprint.tyre_deflection_m * 1e3;
        p.bekker_width_mm = b * 1e3;
        // Each unit (a section in contact, in order): its deepest cell's soil sinkage.
        const Patch3dResult& q = *p.patch3d;
        std::size_t k = 0;
        for (int i = 0; i < q.sections && k < p.footprint.units.size(); ++i) {
          if (!(q.section_force_N[i] > 0)) continue;
          double deepest = 0;
          for (int j = 0; j < q.columns; ++j)
            deepest = std::max(deepest, q.soil_depth_m[std::size_t(i) * q.columns + j]);
          p.footprint.units[k++].soil_depth_m = deepest;
        }
      }
      if (!std::isfinite(p.sinking_mm) || !std::isfinite(p.length_mm) ||
          !std::isfinite(p.width_mm)) {
        return failed("prediction is not finite");
      }
      return p;
    }
  } catch (const std::invalid_argument& e) {  // settings a calibration or sweep made invalid
    return failed(e.what());
  }
}

}  // namespace modaltyre::contact::predictor_paths

#pragma once
// Shared by the 3D patch tests (patch3d_test.cc, patch3d_lateral_test.cc): the proposed default
// config with overrides, the coarse mesh, the tolerances and the checks every variant must pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::contact::testing {

inline const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";

// A coarse mesh keeps the full cell solve (every cell an unknown) quick.
inline const std::vector<std::string> kCoarse = {
    "contact.unit_length_mm=2", "contact.window_mm=300", "footprint_3d.lateral_cell_mm=5"};
// The mesh-convergence requirement: halving a spacing changes a result by < 0.5 %.
constexpr double kMeshChange = 0.005;
// Active-set solutions are exact on their contact set: agreement to rounding of the inner
// solves (CG to 1e-13).
constexpr double kExact = 1e-9;

inline std::vector<std::string> with(std::vector<std::string> a,
                                     const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

struct Tyre3d {
  TyreConfig tyre;
  Patch3dSettings patch;  ///< the config's footprint_3d: section
  TyreModel model;
  explicit Tyre3d(const std::vector<std::string>& overrides)
      : tyre(load_tyre_config(kConfig, overrides)),
        patch(tyre.footprint_3d.value()),
        model(build_tyre_model(tyre)) {}
};

inline double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// The reduction (solve) against the full cell solve at the given loads: sinking, every cell
/// force, length and width to kExact.
inline void expect_reduction_equals_full_cell_solve(const Patch3d& patch,
                                                    const std::vector<double>& loads_N) {
  for (double F : loads_N) {
    const Patch3dResult red = patch.solve(F);
    const Patch3dResult full = patch.solve_cells(F);
    ASSERT_TRUE(red.ok()) << red.message;
    ASSERT_TRUE(full.ok()) << full.message;
    EXPECT_NEAR(red.sinking_m, full.sinking_m, kExact * full.sinking_m);
    ASSERT_EQ(red.cell_force_N.size(), full.cell_force_N.size());
    const double fmax = max_abs(full.cell_force_N);
    for (std::size_t k = 0; k < red.cell_force_N.size(); ++k) {
      EXPECT_NEAR(red.cell_force_N[k], full.cell_force_N[k], kExact * fmax) << "cell " << k;
    }
    EXPECT_NEAR(red.length_m, full.length_m, kExact * full.length_m);
    EXPECT_NEAR(red.width_m, full.width_m, kExact * full.width_m);
  }
}

/// Halving a spacing (coarse -> fine overrides) changes sinking, length, width by < kMeshChange.
inline void expect_mesh_converged(const std::vector<std::string>& coarse,
                                  const std::vector<std::string>& fine) {
  const Tyre3d c(coarse), f(fine);
  const Patch3d pc(c.model, c.patch), pf(f.model, f.patch);
  const auto rc = pc.solve_all({2131, 8321});
  const auto rf = pf.solve_all({2131, 8321});
  for (std::size_t k = 0; k < rc.size(); ++k) {
    ASSERT_TRUE(rc[k].ok() && rf[k].ok());
    EXPECT_NEAR(rc[k].sinking_m, rf[k].sinking_m, kMeshChange * rf[k].sinking_m);
    EXPECT_NEAR(rc[k].length_m, rf[k].length_m, kMeshChange * rf[k].length_m);
    EXPECT_NEAR(rc[k].width_m, rf[k].width_m, kMeshChange * rf[k].width_m);
  }
}

/// Sum f = F_z, f >= 0, f g = 0 and no penetration on every cell.
inline void expect_equilibrium_and_complementarity(const Patch3dResult& r) {
  ASSERT_TRUE(r.ok()) << r.message;
  double sum = 0;
  for (double f : r.cell_force_N) {
    EXPECT_GE(f, 0.0);
    sum += f;
  }
  EXPECT_NEAR(sum, r.load_N, kExact * r.load_N);
  EXPECT_LT(r.equilibrium_residual, kExact);
  EXPECT_LT(r.complementarity_residual, kExact);
  EXPECT_LT(r.max_penetration_m, kExact * r.sinking_m);
}

/// Mirror symmetry in y: cell forces, belt deflections, column edges.
inline void expect_symmetric_in_y(const Patch3dResult& r) {
  ASSERT_TRUE(r.ok()) << r.message;
  const int ny = r.columns;
  for (int i = 0; i < r.sections; ++i) {
    for (int j = 0; j < ny / 2; ++j) {
      EXPECT_NEAR(r.cell_force(i, j), r.cell_force(i, ny - 1 - j), kExact * r.load_N);
      EXPECT_NEAR(r.belt_deflection(i, j), r.belt_deflection(i, ny - 1 - j), kExact * r.sinking_m);
    }
  }
  for (int j = 0; j < ny; ++j) {
    const ColumnEdges& a = r.column_edges[j];
    const ColumnEdges& b = r.column_edges[ny - 1 - j];
    ASSERT_EQ(a.contact, b.contact);
    EXPECT_NEAR(a.rear_x_m, b.rear_x_m, 1e-12);
    EXPECT_NEAR(a.front_x_m, b.front_x_m, 1e-12);
    EXPECT_NEAR(r.y_m[j], -r.y_m[ny - 1 - j], 1e-15);
  }
}

/// Each (yaml, key): read_patch3d_settings on the yaml's footprint_3d: section refuses it with an
/// InputError that names the key.
template <std::size_t N>
void expect_refused_naming_the_key(const std::pair<const char*, const char*> (&bad)[N]) {
  for (const auto& [yaml, key] : bad) {
    try {
      const ConfigTree t = ConfigTree::from_string(yaml, "patch3d.yaml");
      read_patch3d_settings(t.root().section("footprint_3d"));
      ADD_FAILURE() << "accepted: " << yaml;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

}  // namespace modaltyre::contact::testing

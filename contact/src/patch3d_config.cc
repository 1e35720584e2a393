#include "modaltyre/contact/patch3d.h"

namespace modaltyre::contact {

Patch3dSettings read_patch3d_settings(const ConfigSection& s) {
  Patch3dSettings p;
  p.tread_width_m = s.positive("tread_width_mm", p.tread_width_m * 1e3, 2000) * 1e-3;
  p.lateral_cell_m = s.positive("lateral_cell_mm", p.lateral_cell_m * 1e3, 200) * 1e-3;
  const double columns = p.tread_width_m / p.lateral_cell_m;
  if (columns > 2000) {
    s.fail("lateral_cell_mm", "tread width / lateral cell = " + std::to_string(long(columns)) +
                                  " columns; at most 2000 are supported");
  }
  p.max_pattern_iterations =
      static_cast<int>(s.integer("max_pattern_iterations", p.max_pattern_iterations, 1, 100000));
  p.crown = read_crown_profile(s.section("crown"));
  // The profile must stay a graph over the tread: no vertical tangent inside the shoulders.
  if (0.5 * p.tread_width_m >= p.crown.reach_m()) {
    s.fail("tread_width_mm", "the crown profile turns vertical inside the tread width");
  }
  return p;
}

Tyre3dConfig load_tyre3d_config(const std::string& path,
                                const std::vector<std::string>& overrides) {
  const ConfigTree tree = ConfigTree::load(path, overrides);
  Tyre3dConfig c;
  c.patch = read_patch3d_settings(tree.root().section("footprint_3d"));
  c.tyre = read_tyre_config(tree);
  return c;
}

}  // namespace modaltyre::contact

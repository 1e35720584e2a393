#pragma once
// Tyre and transient models the transient tests build in several files, defined once (the test
// files share translation units in a unity build, docs/ci.md).
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::transient::test {

/// A tyre and its transient model.
struct Built {
  contact::TyreModel tyre;
  TransientModel model;
};
inline Built build(const contact::TyreConfig& cfg) {
  Built b{contact::build_tyre_model(cfg), {}};
  b.model = build_transient_model(b.tyre);
  return b;
}

/// The 2D SF-350 of Table 3 with `overrides`.
inline TransientModel model_with(const std::vector<std::string>& overrides) {
  return build_transient_model(
      contact::build_tyre_model(contact::load_tyre_config(modaltyre_test::kConfig2d, overrides)));
}

/// The 2D SF-350 of Table 3 as configured.
inline TransientModel default_model() { return model_with({}); }

/// The 3D patch's mesh coarsened (2 mm units, 7.5 mm lateral cells), then `extra`.
inline std::vector<std::string> coarse_3d(std::vector<std::string> extra = {}) {
  std::vector<std::string> o = {"contact.unit_length_mm=2", "footprint_3d.lateral_cell_mm=7.5"};
  o.insert(o.end(), extra.begin(), extra.end());
  return o;
}

/// |a / b - 1|.
inline double rel(double a, double b) { return std::abs(a / b - 1.0); }

}  // namespace modaltyre::transient::test

#pragma once
// Steady rolling at slip on the 3D patch (docs/soil.md section 9), internal to the contact
// library: the 2D fixed point of traction.h carried to the laterally rigid section reduction of
// patch3d.h, column by column.
//  1. Normal contact: the reduction with the soil's section law (patch3d_soil.h), every cell's
//     ground with the memory of the cells ahead of it in its column:
//     z_max(i, k) = max(prior_k, max_{i' > i} z(i', k)); the sections' gap offset V f_x (the
//     carcass's vertical displacement under the horizontal forces, vertical_from_horizontal).
//  2. Shear per column: j along each column from its own front edge,
//     j = (s_f - R0 theta_i) - (V / omega R0)(x_f - x_ik), x_ik the cell's deformed position;
//     Janosi-Hanamoto per cell (ground/shear.h) marched from the front; each cell's horizontal
//     force tau A - f tan alpha (alpha the column's surface slope), summed per section into the
//     carcass, the shear's vertical component tau A tan alpha sharing the load.
// Repeated (Anderson-mixed, traction_anderson.h) until the cells' sinkage, the sections'
// horizontal forces, the drawbar pull and the load share settle.
#include <string>
#include <vector>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/contact/traction.h"
#include "wong_reece_flexible.h"

namespace modaltyre::contact::detail {

/// A case's result with its load, slip, pass, status and message (failed by default).
TractionResult case_result(const TractionCase& c, int pass, std::string message,
                           SolveStatus status = SolveStatus::failed);

/// What one slip hands to the next (warm start).
struct Rolling3dState {
  std::vector<double> depth_m;  ///< soil depth per cell class [i * classes + k]
  std::vector<double> fx_N;     ///< horizontal force per section
  double shear_vertical_N = 0;
  double bekker_width_m = 0;
  double sinking_m = 0;            ///< the axle's approach (0: none yet)
  std::vector<char> active;        ///< sections in contact
  std::vector<double> approach_m;  ///< sections' approaches (the soil's linearisation)
  std::vector<double> surface_m;   ///< a viscous soil's rolled surface per cell class
  RearState rear;                  ///< Wong and Reece's rear region (wong_reece_flexible.h)
};

class Rolling3d {
 public:
  /// The model must have footprint_3d (laterally rigid belt, no sidewall softening);
  /// std::invalid_argument otherwise.
  Rolling3d(const TyreModel& model, const ground::GroundSettings& ground);
  int columns() const { return patch_.columns(); }
  /// One pass on a track whose memory per column is prior_m (empty: virgin).
  TractionResult pass(const TractionCase& c, int pass, const std::vector<double>& prior_m,
                      const TractionOptions& options, Rolling3dState& state) const;

 private:
  const TyreModel& model_;
  const ground::GroundSettings& ground_;
  Patch3d patch_;
  Eigen::MatrixXd V_;                 ///< vertical_from_horizontal
  std::vector<double> class_drop_m_;  ///< crown drop per column class
  std::vector<double> class_weight_;  ///< columns per class
  std::vector<int> column_class_;     ///< class of each column
  std::vector<double> area_m2_;       ///< a cell's road area per section
  double k_radial_cell_ = 0, k_tangential_cell_ = 0;
};

}  // namespace modaltyre::contact::detail

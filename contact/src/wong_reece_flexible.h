#pragma once
// Wong and Reece's normal stress on the flexible tyre's steady rolling (docs/soil.md section 10),
// internal to the contact library: the 2D and 3D rolling fixed points (traction.cc,
// traction3d.cc) call it once per rolling step.
//
// Angles are taken on the undeformed tyre of radius R0 from the axle's vertical: a contact point
// at along-road x sits at theta = asin(x / R0) (the rigid wheel's own angle when the tyre is
// rigid). Per column (2D: the one column), from the current iterate:
//   theta1 = asin(x_front / R0)  (the contact's entry),  theta_m = (c1 + c2 s) theta1,
//   theta2 = -c3 theta1,
//   front [theta_m, theta1]: the soil's own law (as without the option),
//   rear  [theta2, theta_m): the soil flows at the front's stress mapped as on the rigid wheel
//     sigma_t(theta) = sigma_front(theta1 - (theta - theta2)(theta1 - theta_m)/(theta_m - theta2))
// (Wong & Reece, J. Terramechanics 4, 1967; Wong, Theory of Ground Vehicles, section 2.7). A rear
// unit's soil is rigid at its surface (the rut its memory leaves) up to sigma_t and flows at
// sigma_t beyond (FlowStressLaw): pressed below its surface it carries sigma_t, touching it the
// pressure the tyre puts there up to sigma_t, and nothing where the tyre's gap is open. The
// targets sigma_t A are part of the rolling fixed point's state (Anderson-mixed with the depth
// profile); the rear set and the flow compliance follow the last image.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "modaltyre/ground/pressure_sinkage.h"
#include "modaltyre/ground/soil_options.h"

namespace modaltyre::contact::detail {

/// A soil that is rigid at its surface z_s up to the flow stress sigma and flows at it beyond:
/// Z(p) = z_s + c max(0, p - sigma), c the flow compliance (large: sigma is prescribed to
/// (depth below z_s) / c). Rigid-plastic: its memory is its surface (pass z_max = z_s).
class FlowStressLaw final : public ground::PressureSinkage {
 public:
  FlowStressLaw(double stress_Pa, double surface_m, double flow_m_per_Pa)
      : sigma_(stress_Pa), zs_(surface_m), c_(flow_m_per_Pa) {}
  double loading_Pa(double z_m) const override;
  double loading_sinkage_m(double p_Pa) const override;
  double unloading_Pa(double z_m, double z_max_m) const override;
  double unloading_sinkage_m(double p_Pa, double z_max_m) const override;
  double rebound_depth_m(double) const override { return zs_; }
  bool rigid_plastic() const override { return true; }
  double compliance_m_per_Pa(double p_Pa, double z_max_m) const override;
  double virgin_sinkage_m(double p_Pa, double& dz_dp_m_per_Pa) const override;
  double work_J_m2(double p_Pa, double z_max_m) const override;

 private:
  double sigma_, zs_, c_;
};

/// What the rolling state carries per cell [section * classes + class] (2D: one class).
struct RearState {
  std::vector<double> target_N;  ///< sigma_t A of the rear cells (Anderson-mixed)
  std::vector<char> rear;        ///< the rear set of the last image
  std::vector<char> behind;      ///< the last image's cells behind theta_m (rear set and beyond)
  std::vector<double> flow_m_per_Pa;  ///< per class: the flow compliance of the last image
  std::vector<double> force_N;        ///< the image's: each cell's force in the solution
  /// Per class, from the last image: the rear region's rearmost cell with a depth and the one
  /// ahead of it (-1: none), and the extrapolation's weight w, so that the depth the rear region
  /// leaves at theta2 is d_last + w (d_last - d_prev) (linear in theta, w in [0, 1]).
  std::vector<int> exit_last, exit_prev;
  std::vector<double> exit_weight;
  /// Per class: that depth from the rolling state's (mixed) depths, set_exit_depths(); the
  /// memory of the cells behind theta2 (0: none).
  std::vector<double> exit_depth_m;
};

class WongReeceRear {
 public:
  /// slip: Wong's slip of the case (the rolling radius's, as the soil's slip sinkage);
  /// exit_reach: how far behind the last rear cell, in its spacing, the rut's level is
  /// extrapolated towards theta2 (set_exit_depths; 0: that cell's depth).
  WongReeceRear(const ground::WongReeceStress& wr, double slip, double R0_m, int sections,
                int classes, double exit_reach = 0);
  /// Off: enabled false, or no rear region at this slip (c3 = 0 and c1 + c2 s <= 0): the soil's
  /// own law everywhere, today's fixed point bit for bit.
  bool on() const { return on_; }
  /// Entries it adds to the fixed point's state (0 when off).
  Eigen::Index size() const { return on_ ? Eigen::Index(cells_) : 0; }
  /// The state sized (and zero) if it is not.
  void prepare(RearState& st) const;
  /// st.exit_depth_m from the rolling state's cell depths (the Anderson-mixed ones, so that the
  /// rut behind theta2 converges with the depth profile rather than jumping to each image's).
  void set_exit_depths(RearState& st, const std::vector<double>& depth_m) const;
  /// Per cell the law under it (null: the soil's own) from the state (area_m2: a cell's road
  /// area per section); the memory of an
  /// overridden cell set to its surface (the soil's rut at its memory), as FlowStressLaw takes it;
  /// the memory of a cell behind theta2 no shallower than the state's exit depth.
  std::vector<const ground::PressureSinkage*> laws(const RearState& st,
                                                   const ground::PressureSinkage& soil,
                                                   const std::vector<double>& area_m2,
                                                   std::vector<double>& z_max_m);
  /// The image of a rolling step's solution: per cell its along-road position x [m], vertical
  /// force [N] and soil depth [m]; per section a cell's road area [m^2]; per class its front
  /// edge x [m] (NaN: not in contact).
  RearState image(const std::vector<double>& x_m, const std::vector<double>& force_N,
                  const std::vector<double>& depth_m, const std::vector<double>& area_m2,
                  const std::vector<double>& front_x_m) const;
  /// The track under the cells behind theta_m that carry nothing (depth_m 0 there on entry):
  /// the rut the deepest cell ahead of them in this solution leaves (prior_m per class: the
  /// incoming track), so that a cell touching or leaving the floor behind the peak does not move
  /// the depth profile by its whole sinkage, nor a free cell's lagging memory feed back.
  void fill_track(const RearState& st, const ground::PressureSinkage& soil,
                  const std::vector<double>& prior_m, std::vector<double>& depth_m) const;
  /// Appends the state's and the image's targets to the fixed point's vectors from index `at`: a
  /// cell entering or leaving the rear region enters with the force it carried, so that the map
  /// stays continuous where the region's edge passes a cell.
  void pack(const RearState& st, const RearState& img, Eigen::VectorXd& state,
            Eigen::VectorXd& image, Eigen::Index at) const;
  /// The mixed targets from `next`, the rear set and flow compliance from the image.
  void unpack(const Eigen::VectorXd& next, Eigen::Index at, RearState img, RearState& st) const;
  /// Largest change of a target between state and image [N].
  double change(const RearState& st, const RearState& img) const;

 private:
  ground::WongReeceStress wr_;
  double slip_, R0_;
  double exit_reach_ = 0;
  int sections_, classes_;
  std::size_t cells_;
  bool on_ = false;
  std::vector<std::unique_ptr<FlowStressLaw>> flow_;
};

}  // namespace modaltyre::contact::detail

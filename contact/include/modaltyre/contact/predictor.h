#pragma once
// Footprint predictions for any calibrated scalars, effects (effects.h) and operating conditions
// on one patch mesh: the evaluator behind `footprint`/`validate`/`sweep` when effects are on and
// behind `discover`, which calls it thousands of times with changing parameters.
//
// The modal basis and static kernels are built once (TyreModel). A prediction scales the carcass
// compliance (modal.compliance_scale relative to the model's, inflation_pressure,
// load_stiffening), rebuilds the kernels only when an effect changes them (rolling_speed at a
// speed > 0, belt_flattening), and assembles the tread (tread.modulus_MPa, tread_relaxation,
// tread_coupling, contact_width) and soil (soil_compliance) parts in O(m^2).
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"

namespace modaltyre::contact {

struct Prediction {
  bool ok = false;
  std::string message;  ///< reason when !ok
  double sinking_mm = 0;
  double length_mm = 0;
  double width_mm = 0;              ///< config width, or the crown-profile width (contact_width)
  double rolling_resistance_N = 0;  ///< sum f_z x / (R0 - sinking): 0 for a standing tyre
  double elastic_load_N = 0;        ///< load on the elastic tyre (dry_friction moves it)
  FootprintResult footprint;

  /// Observable by its measurement-column name (sinking_mm, length_mm, width_mm,
  /// rolling_resistance_N).
  double observable(const std::string& name) const;
};

/// A plain solve_footprint() result as a Prediction (no effect on: the config's width, no
/// rolling resistance), for callers that keep the effect-free path bit for bit.
Prediction prediction_from(FootprintResult result, const TyreConfig& config);

/// The observable columns a prediction provides, in CSV order.
const std::vector<std::string>& observable_names();

class FootprintPredictor {
 public:
  explicit FootprintPredictor(TyreModel model);

  const TyreModel& model() const { return model_; }

  /// `params` supplies modal.compliance_scale, tread and effects; everything that defines the
  /// modal basis and the mesh (hammer data, extension, contact.*) is the model's.
  Prediction predict(const TyreConfig& params, const OperatingConditions& conditions,
                     const std::vector<char>* warm_active = nullptr) const;

 private:
  TyreModel model_;
  Eigen::MatrixXd carcass_vertical_;  ///< carcass-only vertical compliance, static kernels
  std::vector<double> cos_, sin_;     ///< of each candidate unit's angle (assembly hot path)
};

/// Tread radial compliance between units l apart for a Pasternak (shear-coupled) tread layer
/// discretised with units of length ds: k_r (u_i - a (u_{i-1} - 2 u_i + u_{i+1})) = f_i with
/// a = (coupling_length / ds)^2. On an unbounded line the inverse is g_l = rho^|l| /
/// (k_r sqrt(1 + 4a)), rho = (1 + 2a - sqrt(1 + 4a)) / (2a); sum_l g_l = 1 / k_r (a uniform
/// load compresses it like independent springs). Entries below 1e-12 g_0 are dropped.
std::vector<double> pasternak_tread_lags(double k_radial_N_m, double coupling_length_m,
                                         double unit_length_m, int max_lags);

}  // namespace modaltyre::contact

#pragma once
// The model's own vertical and contact-patch behaviour, sampled for the .tir bridge: footprints
// at a set of loads through the one prediction entry point (contact::predict), at the config's
// default conditions (its inflation pressure, standing, rigid road).
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"

namespace modaltyre::tir {

struct ModelPoint {
  double load_N = 0;
  double sinking_m = 0;           ///< deflection rho: approach of axle and road
  double length_m = 0;            ///< contact length 2a
  std::optional<double> width_m;  ///< contact width 2b, when the prediction has one
};

struct ModelCurve {
  std::vector<ModelPoint> points;  ///< in load order
  std::string width_reason;        ///< why points carry no width (empty when they do)
};

/// Empty when the config's predictions carry a predicted width, else the reason they do not.
std::string model_width_reason(const contact::TyreConfig& config);

/// The nominal load: `fnomin_N` when given, else the middle of the config's loads_N
/// ((min + max) / 2). Throws InputError (key --fnomin, or loads_N) for a nominal load outside
/// [100, 1e7] N.
double model_fnomin_N(const contact::TyreConfig& config, std::optional<double> fnomin_N);

/// `count` loads evenly spaced over [lo, hi] x fnomin (count >= 2).
std::vector<double> load_grid(double fnomin_N, double lo, double hi, int count);

/// Footprints at the loads (each > 0, at most kMaxModelLoads) at the config's conditions, with
/// the inflation pressure replaced by `pressure_Pa` when > 0. A case that does not converge
/// is a ComputationError with its reason.
ModelCurve sample_model(const contact::TyreModel& model, const std::vector<double>& loads_N,
                        double pressure_Pa = 0);

/// Tangent vertical stiffness dF/drho at a load, by central differences at load (1 +- 2 %).
double model_tangent_stiffness_N_m(const contact::TyreModel& model, double load_N,
                                   double pressure_Pa = 0);

inline constexpr int kMaxModelLoads = 200;

}  // namespace modaltyre::tir

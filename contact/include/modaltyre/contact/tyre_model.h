#pragma once
// The immutable tyre model: modal basis, carcass kernels on the patch mesh and tread stiffness.
// Built once per configuration, shared read-only by every load case (and thread).
//
// Patch mesh (seed 001 eq. 11): the circumference is divided into n equal units of arc length
// ~unit_length; the candidate units are those within +-window/2 of the contact centre
// (theta = 0 at the bottom, theta positive forward, x = R0 sin theta along the road).
//
// Carcass and tread in series (seed 001 eq. 13-19, linearised for displacements small against
// R0): a vertical force f on unit j (upward on the tyre) has radial (inward) component
// f cos theta_j and tangential component f sin theta_j (eq. 12 with f_x = 0); the carcass moves
// unit i by the transfer functions of eq. (1); the tread unit compresses by f_r / k_r and shears
// by f_t / k_t (eq. 6). The upward displacement of unit i is u_r cos theta_i + u_t sin theta_i.
// Tread springs per unit (eq. 6-9, static limit: storage modulus):
//   k_r = E_tr b ds / h,   k_t = G_tr b ds / h,  G_tr = E_tr / (2 (1 + nu)).
#include <Eigen/Dense>
#include <memory>
#include <mutex>
#include <vector>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/modal/carcass_kernel.h"
#include "modaltyre/modal/mode_identification.h"
#include "modaltyre/solvers/toeplitz_compliance.h"

namespace modaltyre::contact {

/// What the effects' predictions (predictor.h) assemble from besides the kernels: the carcass-only
/// vertical compliance with the static kernels and the projections of every candidate unit.
struct CarcassAssembly {
  Eigen::MatrixXd carcass_vertical;  ///< carcass_vertical_compliance(kernels, theta) [m/N]
  std::vector<double> cos_theta, sin_theta;
};

/// Built on first use, once, under a lock: a model that only ever takes the effect-free path
/// never pays for the m x m matrix. A copy of a model starts without it (a copy may change the
/// members it was built from).
template <class T>
class LazyValue {
 public:
  LazyValue() = default;
  LazyValue(const LazyValue&) {}
  LazyValue& operator=(const LazyValue&) {
    const std::lock_guard<std::mutex> lock(mutex_);
    value_.reset();
    return *this;
  }
  template <class Build>
  const T& get(Build build) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!value_) value_ = std::make_shared<const T>(build());
    return *value_;
  }

 private:
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const T> value_;
};

/// The radial (compression) and tangential (shear) springs of a tread block.
struct TreadSprings {
  double radial_N_m = 0;
  double tangential_N_m = 0;
};

/// Tread springs of a block of area width_m x length_m (seed 001 eq. 6-9, static limit:
/// storage modulus): k_r = E_tr A / h, k_t = G_tr A / h, G_tr = E_tr / (2 (1 + nu)). The 2D
/// model's unit (tread width x unit length), the effects path's unit at the contact width and
/// the 3D patch's cell all take their springs from here.
TreadSprings tread_springs(const TreadParams& tread, double width_m, double length_m);

struct TyreModel {
  TyreConfig config;
  modal::ModalBasis basis;
  CarcassDerivation carcass;  ///< how the basis was scaled (ring fit, mass, tension, pressures)
  int units_around = 0;       ///< n, units on the whole circumference
  double dtheta_rad = 0;      ///< 2 pi / n
  double unit_length_m = 0;   ///< R0 dtheta
  int half_window = 0;        ///< candidate units are -half_window .. +half_window
  std::vector<double> theta;  ///< angle of each candidate unit
  modal::LagKernels kernels;  ///< lags 0 .. 2 half_window
  double k_radial_N_m = 0;    ///< tread radial stiffness per unit
  double k_tangential_N_m = 0;
  /// Vertical compliance of the candidate units under vertical forces [m/N] (symmetric).
  Eigen::MatrixXd vertical_compliance;
  Eigen::VectorXd sag;  ///< R0 (1 - cos theta): gap to the road at zero sinking [m]

  int candidates() const { return static_cast<int>(theta.size()); }
  /// The carcass assembly of the effects' predictions (thread-safe, built on first use).
  const CarcassAssembly& carcass_assembly() const;
  /// The operators below are copies of one instance per model (built on first use): the
  /// copies share the kernels' FFT spectra, so successive solves do not transform them again.
  const solvers::WeightedToeplitzCompliance& vertical_operator_prototype() const;
  const solvers::WeightedToeplitzCompliance& carcass_operator_prototype() const;

 private:
  LazyValue<CarcassAssembly> carcass_assembly_;
  LazyValue<solvers::WeightedToeplitzCompliance> vertical_operator_, carcass_operator_;
};

/// Vertical compliance of the carcass alone (no tread) between the candidate units at angles
/// `theta`, from the transfer-function kernels (seed 001 eq. 1, 12) [m/N].
Eigen::MatrixXd carcass_vertical_compliance(const modal::LagKernels& kernels,
                                            const std::vector<double>& theta);

/// TyreModel::vertical_compliance as a matrix-free operator: the carcass kernels (symmetrised,
/// as the matrix is) between the candidates' cos/sin projections plus the tread diagonal. Equal
/// to the matrix to rounding; block products by FFT in O(m log m). Not thread-safe (work
/// arrays): one per solve; a copy of the model's prototype (its spectra are shared).
solvers::WeightedToeplitzCompliance vertical_compliance_operator(const TyreModel& model);

/// The same with the tread springs rigid (no diagonal): the carcass alone between the
/// candidates' vertical forces, on `kernels` (the model's when null, then sharing the model's
/// spectra). Symmetrised (the static kernels are symmetric to rounding), unless `as_given`:
/// steady-rolling kernels, whose asymmetry is the rolling resistance.
solvers::WeightedToeplitzCompliance carcass_compliance_operator(
    const TyreModel& model, const modal::LagKernels* kernels = nullptr, bool as_given = false);

/// Vertical displacement at i per unit horizontal (+x) force at j [m/N]; built on demand (only
/// load cases with a horizontal force need it).
Eigen::MatrixXd vertical_from_horizontal(const TyreModel& model);

/// Builds the model from a configuration and the identified modes of its hammer data.
TyreModel build_tyre_model(const TyreConfig& config, const modal::ModeIdentification& modes);

/// Reads the hammer data named in the config, identifies its modes and builds the model.
TyreModel build_tyre_model(const TyreConfig& config);

}  // namespace modaltyre::contact

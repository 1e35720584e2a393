#pragma once
// The evaluation mesh's share of a named effect's fitted parameters. Discover fits on a coarse
// mesh (DiscoverOptions::unit_length_mm); its standard errors and profile bands are the
// measurement noise's alone, so an estimate the mesh biases sits off its band (issue 45: the
// soil rate eta2 fitted at 4 mm on data rolled at 1 mm lay 8.5 of its standard errors off).
//
// The shift: with residuals r_c at the optimum on the fit's mesh and r_f on a mesh of half the
// unit length (same parameters), one Gauss-Newton step of the fine mesh's least squares from
// the optimum, with the coarse mesh's Jacobian J and the fit's noise weights W = diag(1/s_o^2):
//   d = -(J^T W J)^-1 J^T W (r_f - r_c)
// (subtracting r_c removes what is left of the coarse gradient J^T W r_c, zero at an exact
// optimum; for a model linear in the parameters d is exactly the fine optimum minus the coarse).
// The continuum: a discretisation error of order p in the unit length h moves the estimate by
// d (2^p)/(2^p - 1) from h to 0 (Richardson); p = 1 (the soil rate term's entry jump, docs/soil.md
// 9.1, and the footprint length's unit quantisation are first order) gives 2 d, the larger of the
// usual orders, so the band with the mesh (bands_with_mesh) reaches from the noise band to the
// noise band moved by 2 d: a conservative band, not a correction of the estimate.
#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

#include "modaltyre/discover/model_fit.h"
#include "modaltyre/discover/profile_band.h"

namespace modaltyre::discover {

/// d = -(J^T W J)^-1 J^T W dr over the columns the rows read (a zero column gets 0), W from the
/// fit's RMS per observable as standard_errors() weighs them; empty when J^T W J is singular.
std::vector<double> gauss_newton_shift(const studies::MeasurementSet& data, const FitResult& fit,
                                       const Eigen::MatrixXd& jacobian,
                                       const std::vector<double>& residual_change);

struct MeshBias {
  double unit_length_mm = 0;       ///< the fit's mesh
  double fine_unit_length_mm = 0;  ///< half of it
  /// Per fitted parameter (config key): the estimate on the fine mesh minus the fit's (d).
  std::map<std::string, double> shift;
  /// RMS over the fit's entries of the predictions' change on the fine mesh, in the residuals'
  /// relative units (-1: not evaluated), and the fit's own residual RMS: a change near the
  /// residual (to the continuum, at first order, twice the change) says the mesh, not only the
  /// noise, is in the gap the fit leaves.
  double change_rms = -1;
  double residual_rms = 0;
  std::string note;  ///< why there is no shift (empty when computed)
};

/// Whether the mesh's share of the predictions (2 x change_rms, to the continuum at first order)
/// reaches half the fit's residual RMS: the fit should be repeated on a finer mesh.
bool mesh_is_coarse(const MeshBias& b);

/// The shift of every fitted parameter of `fit` (a full fit of `v` on all rows of `coarse`)
/// when the rows are evaluated on `fine` (the same data, half the unit length) with the
/// configs' mesh set to `fine_unit_length_m`: one evaluation on the fine mesh, the Jacobian the
/// fit's standard errors came from (2k evaluations where it kept none); a note instead of a
/// shift when a fine row fails or the information is singular.
MeshBias mesh_bias(const Evaluator& coarse, const Evaluator& fine, double fine_unit_length_m,
                   const contact::TyreConfig& base, const Variant& v, const FitResult& fit);

/// The noise band moved by the continuum estimate 2 d and joined with the band itself, clipped
/// to the parameter's range (the side flags kept where the band already reached the range).
ParameterBand band_with_mesh(const ParameterBand& band, double shift, const FreeParameter& p);

}  // namespace modaltyre::discover

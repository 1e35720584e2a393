#include "modaltyre/contact/tyre_model.h"

#include <array>
#include <cmath>
#include <utility>

#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"

namespace modaltyre::contact {

namespace {

/// The kernels of C's symmetric part: K_ab(l) -> (K_ab(l) + K_ba(-l)) / 2. Reciprocity (H_tr(l)
/// = H_rt(-l), docs/footprint.md section 1) makes this a change at rounding level only; it makes
/// C_ij = sum_ab w_a(i) K_ab(i - j) w_b(j) symmetric.
std::array<std::vector<double>, 4> symmetrised_kernels(const modal::LagKernels& K) {
  const std::vector<double>* k[4] = {&K.r_from_r, &K.r_from_t, &K.t_from_r, &K.t_from_t};
  std::array<std::vector<double>, 4> s;
  const int n = 2 * K.lags - 1;
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      const auto& ab = *k[2 * a + b];
      const auto& ba = *k[2 * b + a];
      auto& out = s[2 * a + b];
      out.resize(static_cast<std::size_t>(n));
      for (int p = 0; p < n; ++p) out[p] = 0.5 * (ab[p] + ba[n - 1 - p]);
    }
  }
  return s;
}

/// Tread in series (seed 001 eq. 6), only under the unit's own force.
std::vector<double> tread_diagonal(const TyreModel& m) {
  std::vector<double> d(m.theta.size());
  for (std::size_t j = 0; j < d.size(); ++j) {
    const double cj = std::cos(m.theta[j]), sj = std::sin(m.theta[j]);
    d[j] = cj * cj / m.k_radial_N_m + sj * sj / m.k_tangential_N_m;
  }
  return d;
}

/// The assembled vertical compliance (exactly symmetric): the lower triangle from the
/// symmetrised kernels, mirrored. One pass over the m x m array, no temporaries.
Eigen::MatrixXd assembled_vertical_compliance(const TyreModel& m) {
  const int cand = m.candidates();
  const auto K = symmetrised_kernels(m.kernels);
  const std::vector<double> d = tread_diagonal(m);
  std::vector<double> cosv(cand), sinv(cand);
  for (int i = 0; i < cand; ++i) cosv[i] = std::cos(m.theta[i]), sinv[i] = std::sin(m.theta[i]);
  Eigen::MatrixXd C(cand, cand);
  const int mid = m.kernels.lags - 1;
  for (int j = 0; j < cand; ++j) {
    const double cj = cosv[j], sj = sinv[j];
    for (int i = j; i < cand; ++i) {
      const int l = mid + i - j;
      // Unit vertical force at j: f_r = cos theta_j, f_t = sin theta_j (seed 001 eq. 12).
      const double ur = K[0][l] * cj + K[1][l] * sj;
      const double ut = K[2][l] * cj + K[3][l] * sj;
      C(i, j) = ur * cosv[i] + ut * sinv[i];
    }
    C(j, j) += d[j];
  }
  C.triangularView<Eigen::StrictlyUpper>() = C.transpose();
  return C;
}

}  // namespace

TreadSprings tread_springs(const TreadParams& tread, double width_m, double length_m) {
  const double G = tread.modulus_Pa / (2 * (1 + tread.poisson));
  return {tread.modulus_Pa * width_m * length_m / tread.thickness_m,
          G * width_m * length_m / tread.thickness_m};
}

TyreModel build_tyre_model(const TyreConfig& config, const modal::ModeIdentification& modes) {
  TyreModel m;
  m.config = config;
  const double R0 = config.outer_radius_m;
  // n is rounded to the nearest 2^a 3^b 5^c so that the kernel is one FFT; the unit length
  // moves by less than 1 % from the configured one.
  m.units_around = modal::fft_friendly_size(
      static_cast<int>(std::lround(2 * M_PI * R0 / config.mesh.unit_length_m)));
  m.dtheta_rad = 2 * M_PI / m.units_around;
  m.unit_length_m = R0 * m.dtheta_rad;
  m.half_window = static_cast<int>(std::lround(0.5 * config.mesh.window_m / m.unit_length_m));
  const int cand = 2 * m.half_window + 1;

  const int max_order = config.mesh.max_order > 0 ? config.mesh.max_order : m.units_around / 2;
  m.basis = carcass_basis(config, modes, max_order, m.carcass);
  for (const auto& w : m.carcass.warnings) m.basis.warnings.push_back(w);
  if (2 * (cand - 1) >= m.units_around) {
    throw InputError({config.source, 0, "contact.window_mm"},
                     "candidate window longer than half the circumference");
  }
  m.kernels = max_order * 2 <= m.units_around
                  ? modal::build_periodic_kernels(m.basis, m.units_around, cand)
                  : modal::build_lag_kernels(m.basis, m.dtheta_rad, cand);

  const TreadSprings k = tread_springs(config.tread, config.tread.width_m, m.unit_length_m);
  m.k_radial_N_m = k.radial_N_m;
  m.k_tangential_N_m = k.tangential_N_m;

  m.theta.resize(cand);
  m.sag.resize(cand);
  for (int i = 0; i < cand; ++i) {
    m.theta[i] = (i - m.half_window) * m.dtheta_rad;
    m.sag(i) = R0 * (1 - std::cos(m.theta[i]));
  }
  // Exactly symmetric so that Cholesky sees a symmetric matrix. Solves of the model's own load
  // cases use vertical_compliance_operator() instead; the matrix is for other users (transient,
  // export) and costs one O(m^2) pass here.
  m.vertical_compliance = assembled_vertical_compliance(m);
  return m;
}

namespace {

/// C_ij = sum_ab w_a(i) Ks_ab(i - j) w_b(j) + d_i delta_ij, Ks the symmetrised kernels.
solvers::WeightedToeplitzCompliance weighted_operator(const modal::LagKernels& kernels,
                                                      const std::vector<double>& theta,
                                                      std::vector<double> diagonal,
                                                      bool as_given = false) {
  std::vector<double> cosv(theta.size()), sinv(theta.size());
  for (std::size_t i = 0; i < theta.size(); ++i) {
    cosv[i] = std::cos(theta[i]);
    sinv[i] = std::sin(theta[i]);
  }
  // Projections of seed 001 eq. (12): a vertical force has radial part f cos theta and
  // tangential part f sin theta; the upward displacement is u_r cos theta + u_t sin theta.
  return solvers::WeightedToeplitzCompliance(
      solvers::LagConvolution2x2(
          as_given ? std::array<std::vector<double>, 4>{kernels.r_from_r, kernels.r_from_t,
                                                        kernels.t_from_r, kernels.t_from_t}
                   : symmetrised_kernels(kernels),
          kernels.lags),
      std::move(cosv), std::move(sinv), std::move(diagonal));
}

}  // namespace

const solvers::WeightedToeplitzCompliance& TyreModel::vertical_operator_prototype() const {
  return vertical_operator_.get(
      [this] { return weighted_operator(kernels, theta, tread_diagonal(*this)); });
}

const solvers::WeightedToeplitzCompliance& TyreModel::carcass_operator_prototype() const {
  return carcass_operator_.get(
      [this] { return weighted_operator(kernels, theta, std::vector<double>(theta.size(), 0.0)); });
}

solvers::WeightedToeplitzCompliance vertical_compliance_operator(const TyreModel& m) {
  return m.vertical_operator_prototype();
}

solvers::WeightedToeplitzCompliance carcass_compliance_operator(const TyreModel& m,
                                                                const modal::LagKernels* kernels,
                                                                bool as_given) {
  if (kernels == nullptr) return m.carcass_operator_prototype();
  return weighted_operator(*kernels, m.theta, std::vector<double>(m.theta.size(), 0.0), as_given);
}

Eigen::MatrixXd carcass_vertical_compliance(const modal::LagKernels& K,
                                            const std::vector<double>& theta) {
  const int cand = static_cast<int>(theta.size());
  Eigen::MatrixXd C(cand, cand);
  std::vector<double> cosv(cand), sinv(cand);
  for (int i = 0; i < cand; ++i) cosv[i] = std::cos(theta[i]), sinv[i] = std::sin(theta[i]);
  const int mid = K.lags - 1;
  for (int j = 0; j < cand; ++j) {
    const double cj = cosv[j], sj = sinv[j];
    for (int i = 0; i < cand; ++i) {
      const int l = mid + i - j;
      // Unit vertical force at j: f_r = cos theta_j, f_t = sin theta_j (seed 001 eq. 12).
      const double ur = K.r_from_r[l] * cj + K.r_from_t[l] * sj;
      const double ut = K.t_from_r[l] * cj + K.t_from_t[l] * sj;
      C(i, j) = ur * cosv[i] + ut * sinv[i];
    }
  }
  return C;
}

Eigen::MatrixXd vertical_from_horizontal(const TyreModel& m) {
  const int cand = m.candidates();
  Eigen::MatrixXd C(cand, cand);
  for (int j = 0; j < cand; ++j) {
    const double cj = std::cos(m.theta[j]), sj = std::sin(m.theta[j]);
    for (int i = 0; i < cand; ++i) {
      const double ci = std::cos(m.theta[i]), si = std::sin(m.theta[i]);
      const modal::Transfer2x2 h = m.kernels.at(i - j);
      // Unit horizontal force (+x) at j: f_r = -sin theta_j, f_t = cos theta_j.
      const double ur = -h.r_from_r * sj + h.r_from_t * cj;
      const double ut = -h.t_from_r * sj + h.t_from_t * cj;
      C(i, j) = ur * ci + ut * si;
    }
    C(j, j) += cj * (-sj) / m.k_radial_N_m + sj * cj / m.k_tangential_N_m;
  }
  return C;
}

const CarcassAssembly& TyreModel::carcass_assembly() const {
  return carcass_assembly_.get([this] {
    CarcassAssembly a;
    a.carcass_vertical = carcass_vertical_compliance(kernels, theta);
    for (double th : theta)
      a.cos_theta.push_back(std::cos(th)), a.sin_theta.push_back(std::sin(th));
    return a;
  });
}

TyreModel build_tyre_model(const TyreConfig& config) {
  return build_tyre_model(config, config_modes(config));
}

}  // namespace modaltyre::contact

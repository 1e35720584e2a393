#include "modaltyre/rheology/free_vibration.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/linear_least_squares.h"

namespace modaltyre::rheology {
namespace {

constexpr double kMinLogDecrement = 0.01;

// Model and Jacobian in p = (h0, A, B, alpha, omega).
Eigen::VectorXd model(const Eigen::VectorXd& p, const Eigen::VectorXd& tau) {
  Eigen::VectorXd y(tau.size());
  for (Eigen::Index i = 0; i < tau.size(); ++i) {
    const double e = std::exp(-p(3) * tau(i));
    y(i) = p(0) + e * (p(1) * std::cos(p(4) * tau(i)) + p(2) * std::sin(p(4) * tau(i)));
  }
  return y;
}

Eigen::MatrixXd jacobian(const Eigen::VectorXd& p, const Eigen::VectorXd& tau) {
  Eigen::MatrixXd J(tau.size(), 5);
  for (Eigen::Index i = 0; i < tau.size(); ++i) {
    const double t = tau(i), e = std::exp(-p(3) * t);
    const double c = std::cos(p(4) * t), s = std::sin(p(4) * t);
    J(i, 0) = 1.0;
    J(i, 1) = e * c;
    J(i, 2) = e * s;
    J(i, 3) = -t * e * (p(1) * c + p(2) * s);
    J(i, 4) = t * e * (-p(1) * s + p(2) * c);
  }
  return J;
}

}  // namespace

DecaySignal read_free_vibration_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"t_s", "deflection_mm"};
  const CsvTable t = read_csv(path, schema);
  DecaySignal s;
  s.path = path;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double ts = t.number(r, "t_s");
    if (!s.t_s.empty() && ts <= s.t_s.back()) {
      const std::string before =
          "line " + std::to_string(s.line.back()) + " has t_s = " + t.text(r - 1, "t_s");
      throw InputError({path, t.line(r), "t_s"},
                       "time must increase strictly (" + before +
                           "): the decay is a sampled signal in time order");
    }
    s.t_s.push_back(ts);
    s.deflection_m.push_back(t.number(r, "deflection_mm") * 1e-3);
    s.line.push_back(t.line(r));
  }
  return s;
}

double decay_value(const DecayFit& f, double t_s) {
  const double tau = t_s - f.t_start_s;
  return f.equilibrium_m + std::exp(-f.alpha_per_s * tau) * (f.A_m * std::cos(f.omega_rad_s * tau) +
                                                             f.B_m * std::sin(f.omega_rad_s * tau));
}

DecayFit fit_free_decay(const DecaySignal& s) {
  const std::size_t n = s.t_s.size();
  if (n < 10)
    throw InputError({s.path, 0, ""},
                     "free-vibration needs a sampled decay signal (at least 10 "
                     "rows, got " +
                         std::to_string(n) + ")");
  if (s.deflection_m.size() != n) throw InputError({s.path, 0, ""}, "t_s and deflection differ");
  DecayFit f;
  f.samples = static_cast<int>(n);
  f.t_start_s = s.t_s.front();

  // 1. Extrema above the noise: lobes separated by hysteresis at 10 % of the largest swing
  //    about the mean of the second half (a first guess of h_Z0).
  const double h0g = std::accumulate(s.deflection_m.begin() + static_cast<long>(n / 2),
                                     s.deflection_m.end(), 0.0) /
                     static_cast<double>(n - n / 2);
  double amax = 0;
  for (double y : s.deflection_m) amax = std::max(amax, std::abs(y - h0g));
  if (amax <= 0) throw InputError({s.path, 0, "deflection_mm"}, "the signal is constant");
  const double thr = 0.1 * amax;
  std::vector<std::size_t> ext;
  int state = 0;
  std::size_t best = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = s.deflection_m[i] - h0g;
    if (state == 0) {
      if (std::abs(d) > thr) state = d > 0 ? 1 : -1, best = i;
      continue;
    }
    if (state * d > state * (s.deflection_m[best] - h0g)) best = i;
    if (state * d < -thr) {
      ext.push_back(best);
      state = -state;
      best = i;
    }
  }
  if (ext.size() < 4)
    throw InputError({s.path, 0, "deflection_mm"},
                     "fewer than two oscillation cycles above 10 % of the largest swing: cannot "
                     "find the period and the decrement (is this a free damped vibration?)");
  const double T_guess =
      2.0 * (s.t_s[ext.back()] - s.t_s[ext.front()]) / static_cast<double>(ext.size() - 1);
  // Peak-to-peak ranges decay as exp(-alpha t) whatever the equilibrium: slope of ln(range).
  Eigen::MatrixXd A(ext.size() - 1, 2);
  Eigen::VectorXd b(ext.size() - 1);
  for (std::size_t k = 0; k + 1 < ext.size(); ++k) {
    const double r = std::abs(s.deflection_m[ext[k]] - s.deflection_m[ext[k + 1]]);
    A(static_cast<Eigen::Index>(k), 0) = 0.5 * (s.t_s[ext[k]] + s.t_s[ext[k + 1]]) - f.t_start_s;
    A(static_cast<Eigen::Index>(k), 1) = 1.0;
    b(static_cast<Eigen::Index>(k)) = std::log(std::max(r, 1e-300));
  }
  const double alpha_guess = -solvers::solve_linear_least_squares(A, b).coef(0);
  if (!(alpha_guess * T_guess >= kMinLogDecrement))
    throw InputError({s.path, 0, "deflection_mm"},
                     "the oscillation does not decay (log decrement " +
                         std::to_string(alpha_guess * T_guess) + " < " +
                         std::to_string(kMinLogDecrement) +
                         " per cycle): eq. (22) needs a free damped vibration");

  // 2. Linear least squares for (h0, A, B) at the guessed alpha, omega; then Levenberg-Marquardt.
  Eigen::VectorXd tau(n), y(n);
  for (std::size_t i = 0; i < n; ++i) tau(i) = s.t_s[i] - f.t_start_s, y(i) = s.deflection_m[i];
  Eigen::VectorXd p(5);
  p << 0, 0, 0, alpha_guess, 2 * M_PI / T_guess;
  {
    Eigen::MatrixXd L = jacobian(p, tau).leftCols(3);
    p.head(3) = solvers::solve_linear_least_squares(L, y).coef;
  }
  double lambda = 1e-3;
  Eigen::VectorXd r = model(p, tau) - y;
  double cost = r.squaredNorm();
  bool converged = false;
  for (int it = 0; it < 200 && !converged; ++it) {
    const Eigen::MatrixXd J = jacobian(p, tau);
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      Eigen::MatrixXd M = JtJ;
      M.diagonal() += lambda * JtJ.diagonal();
      const Eigen::VectorXd step = M.ldlt().solve(-g);
      const Eigen::VectorXd q = p + step;
      const Eigen::VectorXd rq = model(q, tau) - y;
      const double cq = rq.squaredNorm();
      if (std::isfinite(cq) && cq <= cost) {
        converged =
            (cost - cq) <= 1e-14 * cost ||
            step.cwiseAbs().cwiseQuotient(p.cwiseAbs().array().max(1e-12).matrix()).maxCoeff() <
                1e-10;
        p = q, r = rq, cost = cq;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) converged = true;  // no step lowers the cost: at the minimum
  }
  if (!(p(4) > 0 && std::isfinite(cost)))
    throw ComputationError("free-vibration: the damped-sine fit did not converge");

  f.equilibrium_m = p(0);
  f.A_m = p(1);
  f.B_m = p(2);
  f.alpha_per_s = p(3);
  f.omega_rad_s = p(4);
  f.period_s = 2 * M_PI / p(4);
  f.log_decrement = p(3) * f.period_s;
  if (!(f.log_decrement >= kMinLogDecrement))
    throw InputError({s.path, 0, "deflection_mm"},
                     "the oscillation does not decay (fitted log decrement " +
                         std::to_string(f.log_decrement) + "): eq. (22) needs a damped vibration");
  f.residual_rms_m = std::sqrt(cost / static_cast<double>(n));
  const Eigen::MatrixXd J = jacobian(p, tau);
  const Eigen::MatrixXd cov = cost / static_cast<double>(n - 5) * (J.transpose() * J).inverse();
  f.equilibrium_se_m = std::sqrt(std::max(0.0, cov(0, 0)));
  f.period_se_s = 2 * M_PI / (p(4) * p(4)) * std::sqrt(std::max(0.0, cov(4, 4)));
  // delta = 2 pi alpha / omega: gradient (2 pi / omega, -2 pi alpha / omega^2)
  Eigen::Vector2d grad(2 * M_PI / p(4), -2 * M_PI * p(3) / (p(4) * p(4)));
  f.log_decrement_se = std::sqrt(std::max(0.0, grad.dot(cov.block<2, 2>(3, 3) * grad)));

  // Measured amplitudes a_i about the fitted equilibrium; same-side pairs one period apart.
  for (std::size_t k : ext) {
    f.extremum_t_s.push_back(s.t_s[k]);
    f.amplitude_m.push_back(std::abs(s.deflection_m[k] - f.equilibrium_m));
  }
  double sum = 0;
  int cnt = 0;
  for (std::size_t k = 0; k + 2 < f.amplitude_m.size(); ++k) {
    if (f.amplitude_m[k] > 0 && f.amplitude_m[k + 2] > 0) {
      sum += std::log(f.amplitude_m[k] / f.amplitude_m[k + 2]);
      ++cnt;
    }
  }
  f.log_decrement_peaks = cnt ? sum / cnt : f.log_decrement;
  return f;
}

}  // namespace modaltyre::rheology

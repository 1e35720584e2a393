#pragma once
// FRFs synthesised from a planted modal model, for the EMA tests: receptance
//   H_ij(w) = sum_k phi_ik phi_jk / (w_k^2 - w^2 + 2 j zeta_k w_k w)
// (mass-normalised real shapes, viscous modal damping), turned into mobility or accelerance by
// (j w)^p, with optional additive complex Gaussian noise of a fixed seed.
#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <vector>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre_test {

struct PlantedMode {
  double freq_hz = 0, damping_ratio = 0;
  std::vector<double> radial, tangential;  ///< per point, kg^-1/2
};

struct PlantedModel {
  std::vector<PlantedMode> modes;
  int points = 0;
  std::vector<int> point_numbers;  ///< empty: 1 ... points
};

struct SynthOptions {
  double f_lo_hz = 0, f_hi_hz = 400, df_hz = 0.25;
  modaltyre::ema::FrfType type = modaltyre::ema::FrfType::accelerance;
  modaltyre::ema::Dof reference{1, modaltyre::ema::Direction::radial};
  bool tangential = true;      ///< also the tangential responses
  bool roving_hammer = false;  ///< response fixed at `reference`, the force moves (reciprocity)
  double noise = 0;            ///< noise std as a fraction of each FRF's RMS magnitude
  unsigned seed = 19;
};

inline double shape_at(const PlantedMode& m, const PlantedModel& model,
                       const modaltyre::ema::Dof& d) {
  for (int i = 0; i < model.points; ++i) {
    const int num = model.point_numbers.empty() ? i + 1 : model.point_numbers[i];
    if (num == d.point) {
      return d.dir == modaltyre::ema::Direction::radial ? m.radial[i] : m.tangential[i];
    }
  }
  return 0;
}

inline modaltyre::ema::FrfSet synthesise(const PlantedModel& model, const SynthOptions& o) {
  using namespace modaltyre::ema;
  constexpr double kTwoPi = 6.283185307179586;
  FrfSet set;
  set.path = "synthetic";
  set.type = o.type;
  set.type_from_file = true;
  for (double f = o.f_lo_hz; f <= o.f_hi_hz + 1e-9; f += o.df_hz) set.freq_hz.push_back(f);
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (const Direction dir : {Direction::radial, Direction::tangential}) {
    if (dir == Direction::tangential && !o.tangential) continue;
    for (int i = 0; i < model.points; ++i) {
      const int num = model.point_numbers.empty() ? i + 1 : model.point_numbers[i];
      const Dof moving{num, dir};
      FrfChannel ch{
          o.roving_hammer ? o.reference : moving, o.roving_hammer ? moving : o.reference, {}, 0};
      double power = 0;
      for (double f : set.freq_hz) {
        const double w = kTwoPi * f;
        std::complex<double> h = 0;
        for (const auto& m : model.modes) {
          const double wk = kTwoPi * m.freq_hz;
          h += shape_at(m, model, moving) * shape_at(m, model, o.reference) /
               std::complex<double>(wk * wk - w * w, 2 * m.damping_ratio * wk * w);
        }
        h *= std::pow(std::complex<double>(0, w), static_cast<int>(o.type));
        ch.values.push_back(h);
        power += std::norm(h);
      }
      const double sigma = o.noise * std::sqrt(power / set.freq_hz.size() / 2);
      for (auto& v : ch.values) v += std::complex<double>(sigma * gauss(rng), sigma * gauss(rng));
      set.channels.push_back(ch);
    }
  }
  return set;
}

}  // namespace modaltyre_test

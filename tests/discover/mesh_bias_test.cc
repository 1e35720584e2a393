// The evaluation mesh's share of a named effect's fitted values (discover/mesh_bias.h): the
// Gauss-Newton shift against exact least squares on a linear model, and on a planted effect the
// shift against a fit made on the fine mesh.
#include "modaltyre/discover/mesh_bias.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "modaltyre/discover/discover.h"
#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

// A fit of a model linear in its parameters, r(theta) = A theta - b, with two observables of
// different noise levels (the weights the shift uses are the fit's RMS per observable).
struct LinearFit {
  studies::MeasurementSet data;
  FitResult fit;
  Eigen::MatrixXd A;
  Eigen::VectorXd w;  // 1 / sigma^2 per entry
};

LinearFit linear_fit(int m, int k, unsigned seed) {
  LinearFit l;
  l.data.observables = {"length_mm", "sinking_mm"};
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  l.A = Eigen::MatrixXd(m, k);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < k; ++j) l.A(i, j) = g(rng);
  l.fit.rms = {{"length_mm", 0.02}, {"sinking_mm", 0.005}};
  l.w = Eigen::VectorXd(m);
  for (int i = 0; i < m; ++i) {
    l.fit.entries.push_back({i / 2, i % 2});
    l.w(i) = i % 2 ? 1 / (0.005 * 0.005) : 1 / (0.02 * 0.02);
  }
  return l;
}

Eigen::VectorXd weighted_optimum(const LinearFit& l, const Eigen::VectorXd& b) {
  const Eigen::MatrixXd W = l.w.asDiagonal();
  return (l.A.transpose() * W * l.A).ldlt().solve(l.A.transpose() * W * b);
}

TEST(MeshBias, OnALinearModelTheShiftIsTheFineOptimumMinusTheCoarse) {
  const LinearFit l = linear_fit(12, 3, 7);
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 0.01);
  Eigen::VectorXd b_coarse(12), b_fine(12);
  for (int i = 0; i < 12; ++i) {
    b_coarse(i) = g(rng);
    b_fine(i) = b_coarse(i) + 0.3 * g(rng) + 0.002;  // the fine mesh moves every prediction
  }
  const Eigen::VectorXd coarse = weighted_optimum(l, b_coarse);
  const Eigen::VectorXd fine = weighted_optimum(l, b_fine);
  // Residuals r = A theta - b, so the measured side of the change is b_coarse - b_fine at the
  // coarse optimum.
  std::vector<double> change(12);
  for (int i = 0; i < 12; ++i) change[i] = b_coarse(i) - b_fine(i);
  const std::vector<double> d = gauss_newton_shift(l.data, l.fit, l.A, change);
  ASSERT_EQ(d.size(), 3u);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(d[j], fine(j) - coarse(j), 1e-12 * (1 + std::abs(fine(j))));
    EXPECT_GT(std::abs(d[j]), 1e-5);  // a real move, not a vacuous match at 0
  }
}

TEST(MeshBias, AParameterNoRowReadsMovesByZeroAndLeavesTheOthers) {
  LinearFit l = linear_fit(10, 2, 3);
  Eigen::MatrixXd J(10, 3);
  J << l.A.col(0), Eigen::VectorXd::Zero(10), l.A.col(1);
  std::vector<double> change(10);
  for (int i = 0; i < 10; ++i) change[i] = 0.001 * (i + 1);
  const std::vector<double> with_zero = gauss_newton_shift(l.data, l.fit, J, change);
  const std::vector<double> without = gauss_newton_shift(l.data, l.fit, l.A, change);
  ASSERT_EQ(with_zero.size(), 3u);
  ASSERT_EQ(without.size(), 2u);
  EXPECT_EQ(with_zero[1], 0.0);
  EXPECT_NEAR(with_zero[0], without[0], 1e-14);
  EXPECT_NEAR(with_zero[2], without[1], 1e-14);
  // Two columns alike: not identifiable, no shift.
  J.col(1) = J.col(0);
  EXPECT_TRUE(gauss_newton_shift(l.data, l.fit, J, change).empty());
}

TEST(MeshBias, TheBandWithTheMeshReachesTheContinuumEstimateOnItsSide) {
  FreeParameter p;
  p.min = 0;
  p.max = 10;
  ParameterBand b;
  b.lower = 2, b.upper = 4;
  const ParameterBand up = band_with_mesh(b, 0.5, p);  // continuum 2 x 0.5 above
  EXPECT_DOUBLE_EQ(up.lower, 2);
  EXPECT_DOUBLE_EQ(up.upper, 5);
  const ParameterBand down = band_with_mesh(b, -1.5, p);
  EXPECT_DOUBLE_EQ(down.lower, 0);  // clipped to the range, and said
  EXPECT_TRUE(down.lower_at_bound);
  EXPECT_DOUBLE_EQ(down.upper, 4);
  EXPECT_FALSE(down.upper_at_bound);
}

// The mesh is called coarse when its share to the continuum (twice the change on half the unit
// length) reaches half the residual the fit leaves; a check that did not run says nothing.
TEST(MeshBias, TheMeshIsCoarseWhenItsShareReachesHalfTheResidual) {
  MeshBias b;
  EXPECT_FALSE(mesh_is_coarse(b));  // not evaluated
  b.residual_rms = 0.02;
  b.change_rms = 0.004;  // 0.8 % to the continuum against 2 %: the noise's gap
  EXPECT_FALSE(mesh_is_coarse(b));
  b.change_rms = 0.006;  // 1.2 % against 2 %
  EXPECT_TRUE(mesh_is_coarse(b));
}

// The 2D SF-350's tread coupling hidden in footprints made on 0.5 mm units, fitted on 4 mm: the
// coupling length is the parameter the mesh moves most (the units' shear links are the
// coupling's discretisation).
TEST(MeshBias, OnAPlantedEffectTheShiftMatchesAFitOnTheFineMesh) {
  Planted p;
  p.truth = [](auto& e) {
    e.tread_coupling.enabled = true;
    e.tread_coupling.coupling_length_mm = 25;
  };
  p.noise = 0.002;
  p.unit_length_mm = 0.5;
  p.rows = grid(kLoads9, nullptr, 1);
  const studies::MeasurementSet data = make_data(p, "mesh_bias");
  const TyreConfig cfg = contact::load_tyre_config(kConfig);
  DiscoverOptions opt;
  opt.unit_length_mm = 4;
  opt.max_effects = 1;
  opt.detection_limits = false;
  const DiscoverReport r = discover(cfg, data, opt);
  ASSERT_EQ(r.effects.size(), 1u);
  ASSERT_EQ(r.effects[0].name, "tread_coupling");
  const std::string key = "effects.tread_coupling.coupling_length_mm";
  const auto& e = r.effects[0];
  ASSERT_TRUE(e.mesh.note.empty()) << e.mesh.note;
  const double l4 = e.parameters.at(key), d = e.mesh.shift.at(key);
  // The same variant fitted on 2 mm units from the 4 mm optimum.
  TyreConfig c2 = cfg;
  c2.mesh.unit_length_m = 2e-3;
  const contact::TyreModel m2 = contact::build_tyre_model(c2);
  const Evaluator ev2(m2, data);
  const Variant v = make_variant(c2, {contact::EffectId::tread_coupling});
  std::vector<int> all(data.rows.size());
  std::iota(all.begin(), all.end(), 0);
  const FitResult f2 = fit_variant(ev2, c2, v, all);
  double l2 = 0;
  for (std::size_t i = 0; i < v.parameters.size(); ++i)
    if (v.parameters[i].key == key) l2 = f2.values[i];
  // Measured (seed 1): l = 28.38 +- 1.18 mm on 4 mm units, 27.08 on 2 mm, shift -0.97.
  // The shift is one Gauss-Newton step of the fine least squares: the fine fit's move in sign
  // and within a third of its size.
  ASSERT_GT(std::abs(l2 - l4), e.standard_errors.at(key) / 2);  // the mesh matters here
  EXPECT_GT(d * (l2 - l4), 0);
  EXPECT_NEAR(d, l2 - l4, 0.35 * std::abs(l2 - l4));
  // The planted 25 mm lies outside the noise's band and inside the band with the mesh; the
  // continuum estimate l + 2d is nearer to it than the fit.
  const double truth = 25;
  EXPECT_FALSE(e.bands.at(key).lower <= truth && truth <= e.bands.at(key).upper);
  EXPECT_LE(e.bands_with_mesh.at(key).lower, truth);
  EXPECT_GE(e.bands_with_mesh.at(key).upper, truth);
  EXPECT_LT(std::abs(l4 + 2 * d - truth), std::abs(l4 - truth));
  // Measured: the predictions move by 2.01 % RMS on 2 mm units against the 4 mm fit's residual
  // 0.88 % (its noise is 0.2 %): the mesh, not the noise, leaves the gap, and the check says so.
  EXPECT_GT(e.mesh.change_rms, e.mesh.residual_rms);
  EXPECT_TRUE(mesh_is_coarse(e.mesh));
  // The baseline scalars move too and are reported (not banded).
  EXPECT_EQ(e.mesh.shift.size(), v.parameters.size());
  EXPECT_EQ(e.bands_with_mesh.size(), e.bands.size());
}

}  // namespace
}  // namespace modaltyre::discover

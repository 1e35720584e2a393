// `discover --uncertainty` on traction rows (issue 45; discover/model_uncertainty.h,
// docs/uncertainty.md section 9): the tyre's and the soil's uncertain inputs propagated to the
// rows' drawbar pull, sinkage and torque as discover's residuals divide them; a Bekker soil's
// stated scatter (ground.bekker.uncertainty) as inputs, read and validated with file, line and
// key; without a stated scatter the report is the same bit for bit. The rigid wheel
// (tyre.rigid=true) on LETE sand keeps every run cheap (Bekker-Wong in closed form).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/discover/discover.h"
#include "modaltyre/discover/model_uncertainty.h"
#include "modaltyre/uncertainty/inputs.h"
#include "traction_data.h"

namespace modaltyre::discover {
namespace {

namespace td = traction_data;

// LETE sand with `soil_sets` under the rigid wheel, and its rows: three loads, slips from near
// the self-propelled point (the pull's 0.1 F_z floor acts there) to 0.5.
contact::TyreConfig rigid_lete(const std::vector<std::string>& soil_sets) {
  contact::TyreConfig c = td::lete_config(soil_sets);
  c.rigid = true;
  return c;
}

contact::TractionOptions rigid_rolling() {
  contact::TractionOptions o;
  o.rigid = true;
  return o;
}

// One round, no detection limits or mesh shift: what the decision needs, at its least cost.
DiscoverOptions one_round() {
  DiscoverOptions o;
  o.unit_length_mm = td::kUnit_mm;
  o.max_effects = 1;
  o.detection_limits = false;
  o.mesh_check = false;
  return o;
}

const std::vector<td::Row> kRigidRows = td::curve_rows({2500, 4000, 5500}, {0.05, 0.2, 0.5});

TEST(TractionUncertainty, TheSoilsScatterMovesTheRowsResidualsAsTheirOwnDifferences) {
  // Each stated input's column of C is the central difference of discover's own residuals at
  // +-1 sigma (the rows run by the Evaluator, divided by residual_scale); the rigid wheel reads
  // none of the baseline's tyre scalars, so nothing is projected out and C = sum_u j_u j_u^T.
  const auto c = rigid_lete({"ground.bekker.uncertainty.friction_angle_std_deg=2",
                             "ground.bekker.uncertainty.shear_modulus_K_std_percent=20"});
  const auto data = td::make_traction_data(c, kRigidRows, 0, 1, "unc_rigid", rigid_rolling());
  const contact::TyreModel model = contact::build_tyre_model(c);
  const Evaluator ev(model, data);
  std::vector<int> all(data.rows.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const Variant v = make_variant(c, {});
  const FitResult fit = fit_variant(ev, c, v, all);
  const ModelUncertainty mu = model_uncertainty(ev, c, v, fit);

  const auto inputs = uncertainty::collect_inputs(fit.config, contact::config_modes(fit.config));
  const auto m = static_cast<Eigen::Index>(fit.entries.size());
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd friction;
  int soil_inputs = 0;
  for (const auto& in : inputs) {
    if (in.kind != uncertainty::InputKind::soil_friction_angle &&
        in.kind != uncertainty::InputKind::soil_shear_modulus)
      continue;  // a tyre input: the rigid wheel does not read it (checked below: C is soil's)
    ++soil_inputs;
    auto at = [&](double x) {
      contact::TyreConfig p = fit.config;
      modal::ModeIdentification unused;
      uncertainty::apply(in, x, p, unused);
      const auto r = ev.residuals(p, fit.entries);
      return Eigen::Map<const Eigen::VectorXd>(r.data(), m).eval();
    };
    const Eigen::VectorXd j = 0.5 * (at(in.rel_std) - at(-in.rel_std));
    expected += j * j.transpose();
    if (in.kind == uncertainty::InputKind::soil_friction_angle) friction = j;
  }
  ASSERT_EQ(soil_inputs, 2);
  ASSERT_EQ(mu.cov.rows(), m);
  const double scale = expected.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 1e-4);  // a 2 degree scatter moves the pull by more than 1 %
  EXPECT_LT((mu.cov - expected).cwiseAbs().maxCoeff(), 1e-6 * scale);
  // A gap exactly one sigma of a stated input makes is all the inputs' to produce (the fit's
  // noise levels here are the grouped-against-cold-start runs', ~1e-3: a >> 1).
  EXPECT_GT(uncertain_share(mu, friction), 0.95);
}

// The soil's inputs move their parameters by the stated deviations at +-1 sigma: n and the
// friction angle by the absolute n_std and friction_angle_std_deg, the others by their
// percentages; none is collected off a Bekker soil.
TEST(TractionUncertainty, EachSoilInputMovesItsParameterByTheStatedDeviation) {
  const auto c = rigid_lete({"ground.bekker.uncertainty.k_c_std_percent=5",
                             "ground.bekker.uncertainty.k_phi_std_percent=10",
                             "ground.bekker.uncertainty.n_std=0.03",
                             "ground.bekker.uncertainty.cohesion_std_percent=20",
                             "ground.bekker.uncertainty.friction_angle_std_deg=2",
                             "ground.bekker.uncertainty.shear_modulus_K_std_percent=15"});
  const modal::ModeIdentification modes = contact::config_modes(c);
  const auto& b = c.ground.bekker;
  const auto& sh = c.ground.bekker_shear;
  using K = uncertainty::InputKind;
  const std::map<K, std::pair<std::function<double(const contact::TyreConfig&)>, double>> moved = {
      {K::soil_k_c, {[](const auto& x) { return x.ground.bekker.k_c; }, 0.05 * b.k_c}},
      {K::soil_k_phi, {[](const auto& x) { return x.ground.bekker.k_phi; }, 0.10 * b.k_phi}},
      {K::soil_n, {[](const auto& x) { return x.ground.bekker.n; }, 0.03}},
      {K::soil_cohesion,
       {[](const auto& x) { return x.ground.bekker_shear.cohesion_kPa; }, 0.2 * sh.cohesion_kPa}},
      {K::soil_friction_angle,
       {[](const auto& x) { return x.ground.bekker_shear.friction_angle_deg; }, 2.0}},
      {K::soil_shear_modulus,
       {[](const auto& x) { return x.ground.bekker_shear.shear_modulus_K_mm; },
        0.15 * sh.shear_modulus_K_mm}}};
  int soil_inputs = 0;
  for (const auto& in : uncertainty::collect_inputs(c, modes)) {
    const auto it = moved.find(in.kind);
    if (it == moved.end()) continue;
    ++soil_inputs;
    contact::TyreConfig up = c;
    modal::ModeIdentification m = modes;
    uncertainty::apply(in, in.rel_std, up, m);
    EXPECT_NEAR(it->second.first(up) - it->second.first(c), it->second.second,
                1e-12 * std::abs(it->second.first(c)))
        << in.name;
  }
  EXPECT_EQ(soil_inputs, 6);
  contact::TyreConfig road = c;
  road.ground.model = ground::GroundModel::rigid;
  for (const auto& in : uncertainty::collect_inputs(road, modes))
    EXPECT_EQ(moved.count(in.kind), 0u) << in.name;
}

// C of `csv`'s rows at `c` as given (no search: the same noise levels on any subset of the
// rows), with the entries' rows.
struct RowsCovariance {
  Eigen::MatrixXd cov;
  std::vector<int> entry_rows;  ///< the CSV's row number of each entry
};
RowsCovariance covariance_of(const contact::TyreConfig& c, const std::string& csv,
                             const std::string& name) {
  const auto data = td::as_measurements(csv, c, name);
  const contact::TyreModel model = contact::build_tyre_model(c);
  const Evaluator ev(model, data);
  std::vector<int> all(data.rows.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  // No free parameter: C as propagated, nothing projected out.
  Variant v = make_variant(c, {});
  v.parameters.clear();
  const FitResult fit = evaluate_fit(ev, c, v, {}, ev.entries(all));
  RowsCovariance out{model_uncertainty(ev, c, v, fit).cov, {}};
  for (const auto& e : fit.entries) out.entry_rows.push_back(data.rows[e.row].row);
  return out;
}

TEST(TractionUncertainty, MixedRowsKeepEachKindsSensitivities) {
  // The rigid wheel's footprints (the cylinder pressed into the soil, contact/predictor.h) and
  // its traction rows on LETE sand, one CSV with the kinds interleaved, the soil's k_phi stated
  // to scatter by 10 % (it moves both kinds; the wheel reads none of the tyre's inputs, so C is
  // its j j^T): each kind's block of C is the one its rows give alone, and the cross block's
  // elements are +-sqrt(C_ii C_kk) of those blocks' diagonals.
  const auto c = rigid_lete({"ground.bekker.uncertainty.k_phi_std_percent=10"});
  const contact::TyreModel model = contact::build_tyre_model(c);
  const std::string head =
      "load_N,sinking_mm,length_mm,slip,drawbar_pull_N,soil_sinkage_mm,torque_Nm\n";
  std::vector<std::string> footprint, traction;
  for (double load : {2500.0, 4000.0, 5500.0}) {
    contact::OperatingConditions oc;
    oc.load_N = load;
    const contact::Prediction p = contact::predict(model, oc);
    ASSERT_TRUE(p.ok()) << p.message;
    std::ostringstream f;
    f.precision(10);
    f << load << "," << p.sinking_mm << "," << p.length_mm << ",,,,\n";
    footprint.push_back(f.str());
    const auto t = contact::steady_traction(model, c.ground, {{load, 0.2}}, rigid_rolling());
    ASSERT_TRUE(t.back().ok()) << t.back().message;
    std::ostringstream r;
    r.precision(10);
    r << load << ",,,0.2," << t.back().drawbar_pull_N << "," << t.back().soil_sinkage_m * 1e3 << ","
      << t.back().torque_Nm << "\n";
    traction.push_back(r.str());
  }
  std::string mixed = head, footprints = head, tractions = head;
  for (std::size_t k = 0; k < footprint.size(); ++k) {
    mixed += traction[k] + footprint[k];  // a traction row first: the cases must be mapped
    footprints += footprint[k];
    tractions += traction[k];
  }
  const RowsCovariance all = covariance_of(c, mixed, "unc_mixed");
  const RowsCovariance fp = covariance_of(c, footprints, "unc_fp");
  const RowsCovariance tr = covariance_of(c, tractions, "unc_tr");
  ASSERT_EQ(all.cov.rows(), fp.cov.rows() + tr.cov.rows());
  // Mixed entry i is the k-th footprint or traction entry (the rows keep their order per kind).
  std::vector<int> kind(all.entry_rows.size()), index(all.entry_rows.size());
  int nf = 0, nt = 0;
  for (std::size_t i = 0; i < all.entry_rows.size(); ++i) {
    kind[i] = all.entry_rows[i] % 2;  // CSV rows 1, 3, 5 traction; 2, 4, 6 footprints
    index[i] = kind[i] ? nt++ : nf++;
  }
  ASSERT_EQ(nf, fp.cov.rows());
  const double scale = std::max(fp.cov.cwiseAbs().maxCoeff(), tr.cov.cwiseAbs().maxCoeff());
  ASSERT_GT(fp.cov.cwiseAbs().maxCoeff(), 0);
  ASSERT_GT(tr.cov.cwiseAbs().maxCoeff(), 0);
  for (std::size_t i = 0; i < kind.size(); ++i)
    for (std::size_t k = 0; k < kind.size(); ++k) {
      const auto& own = kind[i] ? tr.cov : fp.cov;
      if (kind[i] == kind[k]) {
        EXPECT_NEAR(all.cov(i, k), own(index[i], index[k]), 1e-9 * scale) << i << " " << k;
        continue;
      }
      const auto& other = kind[k] ? tr.cov : fp.cov;
      const double cross = std::sqrt(own(index[i], index[i]) * other(index[k], index[k]));
      EXPECT_NEAR(std::abs(all.cov(i, k)), cross, 1e-9 * scale) << i << " " << k;
    }
}

TEST(TractionUncertainty, SoilRowsWithoutAStatedScatterGiveTheSameReportBitForBit) {
  // No ground.bekker.uncertainty: no soil input; the tyre's inputs (the hammer shapes' noise)
  // are there, but the rigid wheel reads none of them (its sensitivities are exactly 0). The
  // report with --uncertainty is the one without, number for number.
  const auto c = rigid_lete({});
  EXPECT_EQ(c.ground.bekker_scatter.k_phi_rel_std, 0);
  for (const auto& in : uncertainty::collect_inputs(c, contact::config_modes(c)))
    EXPECT_EQ(in.source.rfind("ground.", 0), std::string::npos) << in.name;
  auto truth = c;
  truth.ground.bekker_shear.shear_modulus_K_mm *= 1.3;
  const auto rows = td::curve_rows({2500, 4000}, {0.05, 0.2, 0.5});
  const auto data = td::make_traction_data(truth, rows, 0.01, 3, "unc_none", rigid_rolling());
  DiscoverOptions o = one_round();
  const DiscoverReport plain = discover(c, data, o);
  o.model_uncertainty = true;
  const DiscoverReport with = discover(c, data, o);
  EXPECT_EQ(with.conclusion, plain.conclusion);
  ASSERT_EQ(with.rounds.size(), plain.rounds.size());
  for (std::size_t k = 0; k < plain.rounds.size(); ++k) {
    ASSERT_EQ(with.rounds[k].size(), plain.rounds[k].size());
    for (std::size_t i = 0; i < plain.rounds[k].size(); ++i) {
      const auto &a = plain.rounds[k][i], &b = with.rounds[k][i];
      EXPECT_EQ(a.name, b.name);
      EXPECT_EQ(a.delta_bic, b.delta_bic) << a.name;
      EXPECT_EQ(b.uncertainty_discount, 0.0) << a.name;
      EXPECT_EQ(a.significant, b.significant) << a.name;
      EXPECT_EQ(a.parameters, b.parameters) << a.name;
    }
  }
  EXPECT_EQ(with.gap_after, plain.gap_after);
  EXPECT_EQ(with.final_parameters, plain.final_parameters);
}

TEST(TractionUncertainty, AGapOneStatedSigmaOfTheSoilMakesIsNotNamed) {
  // LETE sand whose shear modulus K is stated to scatter by 11 % (the soil file's
  // ground.bekker.uncertainty), curves made at K + 1 sigma (12 -> 13.32 mm) with 1 % noise:
  // without the model's uncertainty the pull's gap the baseline cannot absorb is named
  // bulldozing (a false name: the soil is LETE sand one sigma off); with it, the share of that
  // evidence the stated K could produce is taken off and nothing is named.
  const auto c = rigid_lete({"ground.bekker.uncertainty.shear_modulus_K_std_percent=11"});
  auto truth = c;
  truth.ground.bekker_shear.shear_modulus_K_mm *= 1.11;
  const auto rows = td::curve_rows({2500, 4000, 5500}, {0.05, 0.1, 0.2, 0.35, 0.5});
  const auto data = td::make_traction_data(truth, rows, 0.01, 3, "unc_k", rigid_rolling());
  DiscoverOptions o = one_round();
  const DiscoverReport plain = discover(c, data, o);
  ASSERT_EQ(plain.effects.size(), 1u) << plain.conclusion;  // the false name guarded against
  o.model_uncertainty = true;
  const DiscoverReport with = discover(c, data, o);
  EXPECT_TRUE(with.effects.empty()) << with.conclusion;
  // The tyre's inputs (the hammer shapes' noise) are there too; the rigid wheel reads none.
  const auto& names = with.uncertainty_inputs;
  EXPECT_NE(std::find(names.begin(), names.end(), "soil shear modulus K"), names.end());
  const CandidateScore& first = with.rounds.front().front();
  EXPECT_EQ(first.name, plain.effects.front().name);
  EXPECT_EQ(first.delta_bic, plain.rounds.front().front().delta_bic);  // the fit is the same
  // The candidate fits the pull's share of the gap, not the torque's: the inputs could
  // produce about half of its evidence (f = cos^2 of its change and K's, D-weighted).
  const double lr = first.delta_bic + std::log(static_cast<double>(3 * rows.size()));
  EXPECT_GT(first.uncertainty_discount, 0.4 * lr) << first.delta_bic;
  EXPECT_LT(first.delta_bic - first.uncertainty_discount, 10) << first.uncertainty_discount;
}

// A soil file with `block` as ground.bekker.uncertainty's lines (line 10 on), read.
void read_soil_with(const std::string& block) {
  const auto p = std::filesystem::temp_directory_path() /
                 ("modaltyre_scatter_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(p) << "ground:\n  model: bekker\n  bekker:\n    n: 0.79\n    k_c: 102\n"
                      "    k_phi: 5301\n    cohesion_kPa: 0\n    friction_angle_deg: 31.1\n"
                      "    shear_modulus_K_mm: 12\n    uncertainty:\n"
                   << block;
  struct Remove {
    std::filesystem::path p;
    ~Remove() { std::filesystem::remove(p); }
  } remove{p};
  (void)ground::load_ground_file(p.string());
}

TEST(TractionUncertainty, TheSoilScatterKeysAreRefusedWithFileLineAndKey) {
  struct Case {
    std::string block, key;
    int line;
  };
  const std::vector<Case> bad = {
      {"      k_phi_std_percent: -5\n", "ground.bekker.uncertainty.k_phi_std_percent", 11},
      {"      k_phi_std_percent: 10\n      k_c_std_percent: 80\n",
       "ground.bekker.uncertainty.k_c_std_percent", 12},
      {"      n_std: 0.5\n", "ground.bekker.uncertainty.n_std", 11},  // above half of n
      {"      cohesion_std_percent: 20\n", "ground.bekker.uncertainty.cohesion_std_percent",
       11},  // a percentage of a zero cohesion
      {"      friction_angle_std_deg: 16\n", "ground.bekker.uncertainty.friction_angle_std_deg",
       11},
      {"      k_phi_std_pct: 10\n", "ground.bekker.uncertainty.k_phi_std_pct", 11},  // unknown
  };
  for (const auto& b : bad) {
    try {
      read_soil_with(b.block);
      ADD_FAILURE() << "accepted: " << b.block;
    } catch (const InputError& e) {
      EXPECT_NE(e.where().file.find("modaltyre_scatter_"), std::string::npos) << e.what();
      EXPECT_EQ(e.where().line, b.line) << e.what();
      EXPECT_EQ(e.where().key, b.key) << e.what();
    }
  }
  // Stated well: read, in the inputs' units (relative, n and the angle as stated).
  read_soil_with("      k_phi_std_percent: 10\n      n_std: 0.03\n");
  const auto g = ground::load_ground_file(
      td::kSource + "/configs/soils/lete_sand.yaml",
      {"ground.bekker.uncertainty.k_phi_std_percent=10", "ground.bekker.uncertainty.n_std=0.03"});
  EXPECT_DOUBLE_EQ(g.bekker_scatter.k_phi_rel_std, 0.1);
  EXPECT_DOUBLE_EQ(g.bekker_scatter.n_std, 0.03);
}

}  // namespace
}  // namespace modaltyre::discover

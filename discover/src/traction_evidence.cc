#include "modaltyre/discover/traction_evidence.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/studies/traction_rows.h"

namespace modaltyre::discover {

double residual_scale(const studies::MeasuredRow& row, const std::string& observable,
                      double measured, double outer_radius_m) {
  const double load = row.conditions.load_N;
  if (observable == "drawbar_pull_N") return std::max(std::abs(measured), kTractionFloor * load);
  if (observable == "torque_Nm")
    return std::max(std::abs(measured), kTractionFloor * load * outer_radius_m);
  return std::abs(measured);
}

bool acts_on_soil_runs(const contact::EffectInfo& info) {
  auto soil_key = [](const std::string& k) { return k.rfind("ground.", 0) == 0; };
  if (soil_key(info.switch_keys())) return true;
  for (const auto& p : info.parameters)
    if (soil_key(info.key(p))) return true;
  return false;
}

double traction_observable(const contact::TractionResult& r, const std::string& name) {
  if (name == "drawbar_pull_N") return r.drawbar_pull_N;
  if (name == "soil_sinkage_mm") return r.soil_sinkage_m * 1e3;
  if (name == "torque_Nm") return r.torque_Nm;
  throw std::invalid_argument("unknown traction observable " + name);
}

TractionRows::TractionRows(const contact::TyreConfig& config, const studies::MeasurementSet& data,
                           const FlexingLoss& flexing)
    : data_(data), group_of_(data.rows.size(), -1) {
  for (std::size_t r = 0; r < data.rows.size(); ++r) {
    const auto& row = data.rows[r];
    if (!row.traction) continue;
    const double load = row.conditions.load_N, speed = row.conditions.speed_kmh;
    auto it = std::find_if(groups_.begin(), groups_.end(), [&](const Group& g) {
      return g.load_N == load && g.speed_kmh == speed;
    });
    if (it == groups_.end()) it = groups_.insert(groups_.end(), Group{load, speed, {}, {}});
    it->rows.push_back(static_cast<int>(r));
    group_of_[r] = static_cast<int>(it - groups_.begin());
  }
  if (groups_.empty()) return;
  if (!config.ground.soil())
    throw InputError({config.source, 0, "ground.model"},
                     "the traction rows of " + data.path +
                         " need a soil to roll on: give --ground SOIL.yaml or a config with a "
                         "ground: section of model bekker or kelvin_voigt");
  modes_ = contact::config_modes(config);
  decide_windows(config);
  if (!flexing || config.rigid) return;  // the rigid wheel has no flexing loss
  // The flexing loss per speed over that speed's loads, once, at the config as given.
  const contact::TyreModel model = contact::build_tyre_model(config, modes_);
  std::map<double, std::set<double>> loads;
  for (const auto& g : groups_) loads[g.speed_kmh].insert(g.load_N);
  for (const auto& [speed, set] : loads) {
    if (!(speed > 0)) continue;
    const auto f = flexing(model, {set.begin(), set.end()}, speed / 3.6);
    for (const auto& [load, value] : f) flex_[{speed, load}] = value;
  }
}

void TractionRows::decide_windows(const contact::TyreConfig& config) {
  // Each group's largest measured sinkage; the tyre's deflection on the rigid road at the
  // group's load bounds its deflection on the soil (evidence_window.h). Once, at the config as
  // given: the window then stays the same for every parameter set a fit tries.
  std::vector<double> sinkage_m(groups_.size(), 0.0);
  for (std::size_t k = 0; k < groups_.size(); ++k)
    for (int r : groups_[k].rows) {
      const auto& obs = data_.rows[r].observed;
      const auto it = obs.find("soil_sinkage_mm");
      if (it != obs.end()) sinkage_m[k] = std::max(sinkage_m[k], it->second * 1e-3);
    }
  std::optional<contact::TyreModel> road;
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    Group& g = groups_[k];
    if (config.rigid) {  // rolled as the Bekker-Wong wheel (contact/traction.h): no units
      g.window = config_window(config, "the rigid wheel rolls on no candidate window");
      continue;
    }
    double deflection_m = 0;
    if (sinkage_m[k] > 0) {
      if (!road) {
        contact::TyreConfig on_road = config;
        on_road.ground = ground::GroundSettings{};  // the rigid flat road
        road.emplace(contact::build_tyre_model(on_road, modes_));
      }
      contact::OperatingConditions c = data_.rows[g.rows.front()].conditions;
      c.surface = contact::Surface::rigid;
      c.slip = c.speed_kmh = c.horizontal_force_N = 0;  // standing, the static deflection
      const contact::Prediction p = contact::predict(*road, c);
      if (!p.ok()) {
        g.window = config_window(config,
                                 "the measured sinkage not used: the tyre's road "
                                 "footprint at " +
                                     number_text(g.load_N) + " N failed: " + p.message);
        continue;
      }
      deflection_m = p.sinking_mm * 1e-3;
    }
    g.window = evidence_window(config, sinkage_m[k], deflection_m);
  }
}

std::vector<TractionWindow> TractionRows::windows() const {
  std::vector<TractionWindow> out;
  for (const auto& g : groups_) out.push_back({g.load_N, g.speed_kmh, g.window});
  return out;
}

std::map<int, contact::TractionResult> TractionRows::predict(
    const contact::TyreConfig& config, const std::vector<int>& rows, int threads,
    const modal::ModeIdentification* modes) const {
  const modal::ModeIdentification& basis = modes ? *modes : modes_;
  std::vector<std::vector<int>> wanted(groups_.size());
  for (int r : rows)
    if (group_of_[r] >= 0) wanted[group_of_[r]].push_back(r);
  std::vector<int> run;
  for (std::size_t g = 0; g < groups_.size(); ++g)
    if (!wanted[g].empty()) run.push_back(static_cast<int>(g));
  std::map<int, contact::TractionResult> out;
  if (run.empty()) return out;
  // The rigid cylinder of a 3D config rolls at the 3D patch's tread width, as `traction` rolls
  // it (report/traction_run.cc, use_2d_patch_of_3d); it reads no modes.
  const bool cylinder_of_3d = config.rigid && config.footprint_3d;
  contact::TyreConfig rolled;
  if (cylinder_of_3d) {
    rolled = config;
    rolled.tread.width_m = rolled.footprint_3d->tread_width_m;
    rolled.footprint_3d.reset();
  }
  const contact::TyreConfig& base = cylinder_of_3d ? rolled : config;
  // The model on the config's window, for the groups that keep it; the others build their own.
  auto own_window = [&](const Group& g) { return g.window.window_m > base.mesh.window_m; };
  std::optional<contact::TyreModel> model;
  if (std::any_of(run.begin(), run.end(), [&](int g) { return !own_window(groups_[g]); }))
    model.emplace(contact::build_tyre_model(base, basis));
  std::vector<std::vector<contact::TractionResult>> results(run.size());
  std::vector<std::vector<double>> slips(run.size());
  const int n = static_cast<int>(run.size());
#pragma omp parallel for num_threads(std::max(threads, 1)) \
    schedule(dynamic, 1) if (n >= 2 && !omp_in_parallel())
  for (int k = 0; k < n; ++k) {
    const Group& g = groups_[run[k]];
    contact::TractionOptions opt;  // ISTVS slip against the rolling radius, as `traction`
    // The row's speed, as `traction --speed-km-h` gives it: a Kelvin-Voigt soil's rate term
    // (soil_viscosity) acts at it (docs/soil.md 3.2); the Bekker soils do not read it.
    opt.speed_m_per_s = g.speed_kmh / 3.6;
    opt.rigid = config.rigid;  // tyre.rigid=true: the rigid cylinder, as `traction` rolls it
    std::set<double> s;
    for (int r : wanted[run[k]]) {
      s.insert(data_.rows[r].traction->slip);
      opt.passes = std::max(opt.passes, data_.rows[r].traction->pass);
    }
    slips[k].assign(s.begin(), s.end());  // increasing: each slip warm-starts the next
    const auto f = flex_.find({g.speed_kmh, g.load_N});
    if (f != flex_.end()) opt.flexing_resistance_N[g.load_N] = f->second;
    std::vector<contact::TractionCase> cases;
    for (double slip : slips[k]) cases.push_back({g.load_N, slip});
    // The group's window, decided once from its measured sinkage (decide_windows), not grown
    // per evaluation as `traction` grows it: growing it for every parameter set a fit tries
    // made the soil fits 6.6 times dearer (TractionDiscover's unloading set 44 -> 297 s of CPU),
    // for trial sets whose sinkage runs away, and made the objective jump where a trial set's
    // contact reached an edge; a window fixed over the fit keeps it continuous in the
    // parameters. A trial set whose contact outgrows the window fails the row (100 %), as a
    // set sinking far deeper than the data should (docs/discover.md, "Hidden soil effects").
    if (own_window(g)) {
      contact::TyreConfig c = base;
      c.mesh.window_m = g.window.window_m;
      const contact::TyreModel grown = contact::build_tyre_model(c, basis);
      results[k] = contact::steady_traction(grown, config.ground, cases, opt);
    } else {
      results[k] = contact::steady_traction(*model, config.ground, cases, opt);
    }
    cases_.fetch_add(static_cast<long>(results[k].size()), std::memory_order_relaxed);
  }
  for (int k = 0; k < n; ++k) {
    // steady_traction's rows: case by case, pass by pass from 1 (a failed pass ends its case).
    std::map<std::pair<double, int>, const contact::TractionResult*> by_case;
    int c = -1;
    for (const auto& r : results[k]) {
      if (r.pass == 1) ++c;
      if (c >= 0 && c < static_cast<int>(slips[k].size())) by_case[{slips[k][c], r.pass}] = &r;
    }
    for (int r : wanted[run[k]]) {
      const auto& t = *data_.rows[r].traction;
      const auto it = by_case.find({t.slip, t.pass});
      if (it != by_case.end()) {
        out[r] = *it->second;
      } else {
        contact::TractionResult failed;
        failed.message = "an earlier pass of this slip failed";
        out[r] = failed;
      }
    }
  }
  return out;
}

}  // namespace modaltyre::discover

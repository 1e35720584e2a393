// `tir compare`: a .tir's laws against the model's footprints (tir_compare.h).
#include "modaltyre/tir/tir_compare.h"

#include <cmath>
#include <cstdio>

#include "modaltyre/core/errors.h"

namespace modaltyre::tir {
namespace {

std::string percent(double ratio) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.1f %%", 100 * (ratio - 1));
  return buf;
}

// RMS relative difference over the rows where both values exist; nullopt when none do.
std::optional<double> rms(const std::vector<std::optional<double>>& model,
                          const std::vector<std::optional<double>>& tir) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (!model[i] || !tir[i]) continue;
    const double r = (*tir[i] - *model[i]) / *model[i];
    sum += r * r;
    ++n;
  }
  if (n == 0) return std::nullopt;
  return std::sqrt(sum / n);
}

void decide_basis(const contact::TyreConfig& c, const MfTyre& tir, TirComparison& out) {
  const double r_ratio = tir.unloaded_radius_m / c.outer_radius_m;
  const bool width_known = c.section_width_m > 0 && tir.width_m;
  const double w_ratio = width_known ? *tir.width_m / c.section_width_m : 1;
  const bool same = std::abs(r_ratio - 1) <= 0.03 && std::abs(w_ratio - 1) <= 0.05;
  out.dimensionless = !same;
  std::string sizes = "UNLOADED_RADIUS " + percent(r_ratio) + " of the config's outer radius";
  sizes += width_known ? ", WIDTH " + percent(w_ratio) + " of tyre.section_width_mm"
                       : " (WIDTH not compared: " +
                             std::string(c.section_width_m > 0 ? "the file states none"
                                                               : "the config states no "
                                                                 "tyre.section_width_mm") +
                             ")";
  out.basis =
      same ? "absolute units: the same tyre size (" + sizes + ")"
           : "dimensionless (load/FNOMIN, rho/R0, 2a/R0, 2b/W): another tyre size (" + sizes + ")";
}

}  // namespace

TirComparison compare_tir(const contact::TyreModel& model, const MfTyre& tir,
                          const CompareOptions& options) {
  if (options.points < 3 || options.points > kMaxModelLoads) {
    throw InputError({"--points", 0, ""},
                     "give 3 to " + std::to_string(kMaxModelLoads) + " points");
  }
  if (options.slip.enabled) check_slip_options(options.slip);  // before the footprints
  const contact::TyreConfig& c = model.config;
  TirComparison out;
  out.tir = tir;
  out.model_fnomin_N = model_fnomin_N(c, options.fnomin_N);
  out.model_radius_m = c.outer_radius_m;
  out.model_section_width_m = c.section_width_m;
  decide_basis(c, tir, out);
  const ModelCurve curve =
      sample_model(model, load_grid(out.model_fnomin_N, 0.25, 2, options.points));

  // Scales from the .tir's size to the model's (1 in absolute units).
  const double r_scale = out.dimensionless ? c.outer_radius_m / tir.unloaded_radius_m : 1;
  const double f_scale = out.dimensionless ? out.model_fnomin_N / tir.vertical.fnomin_N : 1;
  const bool width_scalable = !out.dimensionless || (c.section_width_m > 0 && tir.width_m);
  const double w_scale = out.dimensionless && width_scalable ? c.section_width_m / *tir.width_m : 1;

  std::vector<std::optional<double>> m_load, t_load, m_len, t_len, m_w, t_w;
  for (const auto& p : curve.points) {
    CompareRow row;
    row.rho_m = p.sinking_m;
    row.load_N = p.load_N;
    row.model_length_m = p.length_m;
    row.model_width_m = p.width_m;
    if (const auto load = tir.load_N(p.sinking_m / r_scale)) {
      row.tir_load_N = *load * f_scale;
      if (const auto len = tir.length_m(*load)) row.tir_length_m = *len * r_scale;
      if (const auto w = tir.width_at_m(*load); w && width_scalable) {
        row.tir_width_m = *w * w_scale;
      }
    }
    m_load.push_back(row.load_N);
    t_load.push_back(row.tir_load_N);
    m_len.push_back(row.model_length_m);
    t_len.push_back(row.tir_length_m);
    m_w.push_back(row.model_width_m);
    t_w.push_back(row.tir_width_m);
    out.rows.push_back(row);
  }
  out.rms_load = rms(m_load, t_load);
  out.rms_length = rms(m_len, t_len);
  out.rms_width = rms(m_w, t_w);
  const std::string outside = "the model's deflections lie outside the .tir's vertical law";
  if (!out.rms_load) out.load_reason = outside;
  if (!out.rms_length) out.length_reason = !tir.length_reason.empty() ? tir.length_reason : outside;
  if (!out.rms_width) {
    out.width_reason = !curve.width_reason.empty() ? "model: " + curve.width_reason
                       : !tir.width_reason.empty() ? tir.width_reason
                       : !width_scalable ? "the config states no tyre.section_width_mm to scale "
                                           "2b/W to"
                                         : outside;
  }
  if (options.slip.enabled) {
    const SlipRuns runs = run_slip(model, out.model_fnomin_N, options.slip);
    out.slip =
        compare_slip_runs(tir, runs, out.dimensionless, out.model_fnomin_N, c.outer_radius_m);
  }
  return out;
}

}  // namespace modaltyre::tir

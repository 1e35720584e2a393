// steady_traction with the candidate window grown where the contact reaches its edge, as
// `traction` (report/traction_run.cc) rolls it. discover's traction rows do not grow it per
// evaluation (discover/traction_evidence.cc says why).
#include <utility>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::contact {
namespace {

// steady_traction's rows split per case (each case's rows start with pass 1).
std::vector<std::vector<TractionResult>> by_case(std::vector<TractionResult> results) {
  std::vector<std::vector<TractionResult>> out;
  for (auto& r : results) {
    if (r.pass == 1 || out.empty()) out.emplace_back();
    out.back().push_back(std::move(r));
  }
  return out;
}

bool window_exceeded(const std::vector<TractionResult>& rows) {
  for (const auto& r : rows)
    if (r.window_exceeded) return true;
  return false;
}

}  // namespace

std::vector<TractionResult> steady_traction_growing_window(const TyreModel& model,
                                                           const modal::ModeIdentification& modes,
                                                           const ground::GroundSettings& ground,
                                                           const std::vector<TractionCase>& cases,
                                                           const TractionOptions& options) {
  std::vector<std::vector<TractionResult>> per_case =
      by_case(steady_traction(model, ground, cases, options));
  // The cases whose contact reached the window's edge run again on a window 1.5 times longer
  // (suggested_window_mm), up to the largest the config reader accepts (half the circumference,
  // 20000 units); the model is rebuilt on the same modes.
  TyreConfig config = model.config;
  const double first_window_m = config.mesh.window_m;
  for (int growth = 0; growth < 20; ++growth) {
    std::vector<std::size_t> again;
    for (std::size_t k = 0; k < per_case.size(); ++k)
      if (window_exceeded(per_case[k])) again.push_back(k);
    if (again.empty() || config.mesh.window_m >= max_window_m(config) * (1 - 1e-9)) break;
    config.mesh.window_m = suggested_window_mm(config) * 1e-3;
    const TyreModel grown = build_tyre_model(config, modes);
    std::vector<TractionCase> redo;
    for (std::size_t k : again) redo.push_back(cases[k]);
    std::vector<std::vector<TractionResult>> rerun =
        by_case(steady_traction(grown, ground, redo, options));
    for (std::size_t n = 0; n < again.size() && n < rerun.size(); ++n)
      per_case[again[n]] = std::move(rerun[n]);
  }
  std::vector<TractionResult> results;
  for (auto& rows : per_case)
    for (auto& r : rows) {
      if (r.window_exceeded && config.mesh.window_m > first_window_m)
        r.message += " (the window grew from " + number_text(first_window_m * 1e3) + " to " +
                     number_text(config.mesh.window_m * 1e3) + " mm, the largest allowed)";
      results.push_back(std::move(r));
    }
  return results;
}

}  // namespace modaltyre::contact

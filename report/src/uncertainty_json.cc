#include "modaltyre/report/uncertainty_json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "modaltyre/core/number_format.h"

namespace modaltyre::report {

nlohmann::json bands_json(const std::vector<std::string>& names,
                          const std::vector<uncertainty::Band>& bands) {
  nlohmann::json u = nlohmann::json::object();
  for (std::size_t q = 0; q < names.size() && q < bands.size(); ++q) {
    const auto& b = bands[q];
    u[names[q]] = {{"value", round_sig(b.value)},
                   {"std", round_sig(b.std)},
                   {"p025", round_sig(b.p025)},
                   {"p975", round_sig(b.p975)}};
  }
  return u;
}

void add_uncertainty_method_json(nlohmann::json& document,
                                 const uncertainty::PropagationResult& r) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const auto& e : r.inputs) {
    inputs.push_back({{"name", e.input.name},
                      {"rel_std", round_sig(e.input.rel_std)},
                      {"source", e.input.source},
                      {"nonlinearity", round_sig(e.nonlinearity, 3)}});
  }
  document["uncertainty_method"] = r.method;
  document["uncertainty_check"] = r.check;
  document["uncertainty_inputs"] = inputs;
  document["uncertainty_evaluations"] = r.evaluations;
}

void add_uncertainty_json(nlohmann::json& document, const uncertainty::PropagationResult& r) {
  auto& cases = document["cases"];
  for (std::size_t c = 0; c < r.cases.size() && c < cases.size(); ++c) {
    cases[c]["uncertainty"] = bands_json(uncertainty::output_names(), r.cases[c].bands);
  }
  add_uncertainty_method_json(document, r);
}

std::string plus_minus(double value, double two_sigma, int plain_decimals) {
  char b[96];
  if (!(two_sigma > 0) || !std::isfinite(two_sigma)) {
    std::snprintf(b, sizeof b, "%.*f", plain_decimals, value);
    return b;
  }
  const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(two_sigma))), 0, 6);
  std::snprintf(b, sizeof b, "%.*f +- %.*f", decimals, value, decimals, two_sigma);
  return b;
}

std::string band_text(const uncertainty::Band& b, int plain_decimals) {
  char t[160];
  const double half = 0.5 * (b.p975 - b.p025);
  if (!(half > 0) || !std::isfinite(half)) {
    std::snprintf(t, sizeof t, "%.*f (fixed: no uncertain input moves it)", plain_decimals,
                  b.value);
    return t;
  }
  const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(half))), 0, 6);
  std::snprintf(t, sizeof t, "%.*f [%.*f, %.*f]", decimals, b.value, decimals, b.p025, decimals,
                b.p975);
  return t;
}

}  // namespace modaltyre::report

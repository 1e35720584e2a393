#include "modaltyre/report/init_json.h"

#include "modaltyre/core/number_format.h"

namespace modaltyre::report {
namespace {

nlohmann::json proposal_json(const modal::OrderProposal& p) {
  return {{"orders", p.orders},
          {"score", round_sig(p.score, 6)},
          {"rms_rel_error", round_sig(p.rms_rel_error, 4)},
          {"mass_per_length_kg_m", round_sig(p.mass_per_length_kg_m, 4)},
          {"missing_orders", p.missing}};
}

nlohmann::json ring_fit_json(const contact::CarcassDerivation& c) {
  nlohmann::json fit = {{"valid", c.fit.valid}};
  if (c.fit.valid) {
    fit["radial_foundation_rad2_s2"] = round_sig(c.fit.coefficients.radial_foundation);
    fit["tension_rad2_s2"] = round_sig(c.fit.coefficients.tension);
    fit["bending_rad2_s2"] = round_sig(c.fit.coefficients.bending);
    fit["tangential_foundation_rad2_s2"] = round_sig(c.fit.coefficients.tangential_foundation);
    fit["rms_rel_error"] = round_sig(c.fit.rms_rel_error, 4);
  } else {
    fit["reason"] = c.fit.reason;
  }
  return fit;
}

}  // namespace

nlohmann::json init_json(const init::InitResult& r, const std::string& output) {
  nlohmann::json alternatives = nlohmann::json::array();
  for (const auto& p : r.alternatives) alternatives.push_back(proposal_json(p));
  nlohmann::json decisions = nlohmann::json::array();
  for (const auto& d : r.decisions)
    decisions.push_back({{"key", d.key}, {"value", d.value}, {"source", d.source}});
  const auto& c = r.carcass;
  nlohmann::json j = {{"orders", r.orders},
                      {"orders_proposed", r.orders_proposed},
                      {"alternatives", alternatives},
                      {"mass_per_length_kg_m", round_sig(c.mass_per_length_kg_m, 6)},
                      {"mass_source", c.mass_source},
                      {"implied_tension_N", round_sig(c.tension_N, 6)},
                      {"membrane_tension_N", round_sig(c.membrane_tension_N, 6)},
                      {"ring_fit", ring_fit_json(c)},
                      {"decisions", decisions},
                      {"warnings", r.warnings}};
  if (output.empty()) {
    j["config"] = r.yaml;
  } else {
    j["output"] = output;
  }
  return j;
}

}  // namespace modaltyre::report

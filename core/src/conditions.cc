#include "modaltyre/core/conditions.h"

#include <cstdio>

#include "modaltyre/core/csv.h"

namespace modaltyre {

namespace {

std::vector<ConditionInfo> make_catalogue() {
  using Id = ConditionId;
  return {
      // [1e-6, 1e7] N: contact::kMinLoad_N, kMaxLoad_N (below 1e-6 N the 3D patch divides by 0).
      {Id::load_N, "load_N", "N", "load", 1e-6, 1e7},
      {Id::pressure_kPa, "pressure_kPa", "kPa", "gauge inflation pressure", 0, 2000, true},
      {Id::hold_s, "hold_s", "s", "hold time", 0, 1e7},
      {Id::speed_kmh, "speed_kmh", "km/h", "speed", 0, 400},
      {Id::branch,
       "branch",
       "",
       "branch",
       0,
       0,
       false,
       {{"load", "loading"}, {"unload", "unloading"}}},
      {Id::surface, "surface", "", "surface", 0, 0, false, {{"rigid"}, {"soil"}}},
      {Id::horizontal_force_N, "horizontal_force_N", "N", "horizontal force", -1e7, 1e7},
      {Id::slip, "slip", "", "slip", -1, 1},
  };
}

// A limit as people write it: 2000, -1e7 ("%g" with the exponent's "+0" dropped).
std::string limit_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  std::string s = buf;
  const auto e = s.find('e');
  if (e != std::string::npos) {
    std::size_t k = e + 1;
    if (s[k] == '+') s.erase(k, 1);
    if (s[k] == '-') ++k;
    while (k + 1 < s.size() && s[k] == '0') s.erase(k, 1);
  }
  return s;
}

}  // namespace

std::string ConditionInfo::range_text() const {
  if (is_text()) {
    std::string s;
    for (const auto& w : words) s += (s.empty() ? "" : ", ") + w.front();
    return s;
  }
  return (min_open ? "(" : "[") + limit_text(min) + ", " + limit_text(max) + "]" +
         (unit.empty() ? "" : " " + unit);
}

std::optional<int> ConditionInfo::value_of(const std::string& word) const {
  for (std::size_t i = 0; i < words.size(); ++i) {
    for (const auto& w : words[i]) {
      if (w == word) return static_cast<int>(i);
    }
  }
  return std::nullopt;
}

std::string ConditionInfo::refusal(const std::string& given) const {
  if (!is_text()) return meaning + " must be in " + range_text() + ", got " + printable(given);
  std::string also;
  for (const auto& w : words) {
    for (std::size_t k = 1; k < w.size(); ++k) also += (also.empty() ? "" : ", ") + w[k];
  }
  return "'" + printable(given) + "' is not one of: " + range_text() +
         (also.empty() ? "" : " (or " + also + ")");
}

const std::vector<ConditionInfo>& condition_catalogue() {
  static const std::vector<ConditionInfo> c = make_catalogue();
  return c;
}

const ConditionInfo& condition_info(ConditionId id) {
  return condition_catalogue().at(static_cast<int>(id));
}

const ConditionInfo* find_condition(const std::string& name) {
  for (const auto& c : condition_catalogue()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

}  // namespace modaltyre

// Detection limits of discover's report (issue 23) in text and JSON.
#include "discover_limits.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli_support.h"

namespace modaltyre::app {
namespace {}  // namespace

// "tread_relaxation: not named; these data would reveal creep_ratio >= 0.21 (sinking_mm RMS
// >= 2.1 %) with 80 % probability", for the last round's candidates left unnamed.
void print_limits(const discover::DiscoverReport& r) {
  if (r.rounds.empty()) return;
  bool header = false;
  for (const auto& c : r.rounds.back()) {
    const discover::DetectionLimit& l = c.limit;
    if (l.effect.empty()) continue;
    if (!header) std::cout << "\nDetection limits (what these rows at their noise would name):\n";
    header = true;
    std::cout << "  " << c.name << ": not named; ";
    if (!l.computed()) {
      std::cout << "no limit: " << l.reason << "\n";
      continue;
    }
    std::vector<std::pair<double, std::string>> obs;
    for (const auto& kv : l.observable_rms_rel) obs.emplace_back(kv.second, kv.first);
    std::sort(obs.rbegin(), obs.rend());
    const std::string name = l.parameter.substr(l.parameter.rfind('.') + 1);
    std::ostringstream value;
    value.precision(3);
    value << l.value;
    std::cout << "these data would reveal " << name << " " << (l.at_most ? "<=" : ">=") << " "
              << value.str() << (l.unit == "-" ? "" : " " + l.unit) << " (";
    for (std::size_t i = 0; i < obs.size(); ++i) {
      std::cout << (i ? ", " : "") << obs[i].second << " RMS " << (i ? "" : ">= ")
                << pct(obs[i].first);
    }
    std::cout << ") with 80 % probability; at its default: "
              << std::lround(100 * l.power_at_default) << " %\n";
    if (l.two_sided) {  // the side below the neutral value (detection_limit.h)
      std::ostringstream lower;
      lower.precision(3);
      lower << l.lower_value;
      std::cout << "    below its neutral value: "
                << (l.lower_reason.empty() ? name + " <= " + lower.str() : l.lower_reason)
                << "; at " << l.lower_reference_value << ": "
                << std::lround(100 * l.power_at_lower_reference) << " %\n";
    }
  }
  if (!r.more_rows.effect.empty()) std::cout << "Rows to add: " << r.more_rows.text << ".\n";
}

}  // namespace modaltyre::app

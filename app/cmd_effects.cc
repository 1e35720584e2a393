// modaltyre effects [--json]
// Lists the switchable model effects of section `effects:` (contact/effects.h): what each one
// changes, the operating condition it acts through and its parameters with the exact config keys,
// so that a user can write `--set effects.NAME.PARAM=...` without reading the source.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/contact/effects.h"
#include "modaltyre/report/effects_json.h"

namespace modaltyre::app {
namespace {

using contact::EffectInfo;
using contact::EffectParameterInfo;

using report::enabled_key;

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : ", ") + w;
  return s;
}

// %g keeps stated values such as 1e4 or 0.25 exactly as the catalogue has them.
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Width of the key column: the longest key of the whole catalogue, so that every effect's
// table lines up with the others.
int key_width() {
  std::size_t w = 3;
  for (const auto& e : contact::effect_catalogue()) {
    for (const auto& p : e.parameters) w = std::max(w, e.key(p).size());
  }
  return static_cast<int>(w);
}

void print_effect(const EffectInfo& e, int width) {
  std::cout << e.name << "\n"
            << "  " << e.description << "\n"
            << "  regime variable: " << condition_info(e.regime).name
            << "   changes: " << joined(e.observables) << "\n"
            << "  switch on: " << e.switch_keys() << "\n"
            << "  acts on: " << e.acts_on << "   with the 3D patch (footprint_3d): "
            << (e.refused_with_3d.empty() ? "composes" : "refused, " + e.refused_with_3d)
            << (e.is_option() && e.option->needs_3d ? "; needs it (an option of footprint_3d)" : "")
            << "\n";
  char line[512];
  std::snprintf(line, sizeof line, "  %-*s  %-5s %9s %9s %9s  %-7s %s\n", width, "key", "unit",
                "default", "min", "max", "status", "meaning");
  std::cout << line;
  for (const auto& p : e.parameters) {
    std::snprintf(line, sizeof line, "  %-*s  %-5s %9s %9s %9s  %-7s ", width, e.key(p).c_str(),
                  p.unit.c_str(), number(p.default_value).c_str(), number(p.min).c_str(),
                  number(p.max).c_str(), p.fitted ? "fitted" : "stated");
    std::cout << line << p.meaning << "\n";
  }
}

void print_table() {
  const auto& catalogue = contact::effect_catalogue();
  const int width = key_width();
  std::cout << catalogue.size()
            << " switchable effects, all off by default (docs/effects.md): those of section "
               "effects: and options of the config (switched by their own keys). \"stated\" "
               "parameters are reference values that discover does not fit.\n";
  for (const auto& e : catalogue) {
    std::cout << "\n";
    print_effect(e, width);
  }
}

}  // namespace

void register_effects(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand(
      "effects",
      "List the switchable model effects (config section effects:): what each changes, the "
      "condition it acts through, its parameters with keys, units, defaults and ranges.");
  cmd->add_flag("--json", *json, "print JSON instead of a table");
  cmd->callback([json] {
    if (*json) {
      print_json(report::effects_json());
    } else {
      print_table();
    }
  });
}

}  // namespace modaltyre::app

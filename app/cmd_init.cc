// modaltyre init --size 195/60R14 --test-pressure-kPa P0 [--pressure-kPa P]
//                (--frequencies F1,F2,... [--damping Z1,...] [--orders K1,...] | --hammer FILE)
//                [--belt-mass-kg M] [--boundary free|rim-fixed] [--wheel-mass-kg M] ...
//                [--output tyre.yaml] [--json]
#include <iostream>
#include <memory>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/init/init_tyre.h"
#include "modaltyre/report/init_json.h"

namespace modaltyre::app {
namespace {

struct InitArgs {
  init::InitInputs in;
  std::vector<std::string> frequencies, damping, orders;  // split here: an empty item is named
  std::string output;
  bool json = false;
};

// "96,112,,135" as its items, empty ones kept (CLI11's own splitting drops them, and a dropped
// frequency moves every later one to the wrong order).
std::vector<std::string> items_of(const std::vector<std::string>& words) {
  std::vector<std::string> out;
  for (const auto& w : words) {
    std::size_t at = 0;
    while (true) {
      const std::size_t comma = w.find(',', at);
      out.push_back(w.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
      if (comma == std::string::npos) break;
      at = comma + 1;
    }
  }
  return out;
}

// Every item a finite decimal number, else an InputError naming the option and the item.
std::vector<double> numbers_of(const std::vector<std::string>& words, const std::string& option) {
  std::vector<double> out;
  const auto items = items_of(words);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto v = parse_finite_double(items[i]);
    if (!v) {
      throw InputError({option, 0, ""},
                       "item " + std::to_string(i + 1) + " of " + std::to_string(items.size()) +
                           (items[i].empty() ? " is empty (two commas in a row?)"
                                             : ": '" + printable(items[i]) +
                                                   "' is not a finite decimal number"));
    }
    out.push_back(*v);
  }
  return out;
}

// "2,3,r,4": orders >= 0, "r" for the rigid rotation mode (-1).
std::vector<int> parse_orders(const std::vector<std::string>& words) {
  std::vector<int> out;
  for (const auto& w : items_of(words)) {
    if (w == "r" || w == "R") {
      out.push_back(-1);
      continue;
    }
    const bool digits =
        !w.empty() && w.size() <= 3 && w.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) {
      throw InputError({"--orders", 0, ""},
                       "'" + w + "' is not an order (0-999) or r (the rotation mode)");
    }
    out.push_back(std::stoi(w));
  }
  return out;
}

}  // namespace

void register_init(CLI::App& app) {
  auto a = std::make_shared<InitArgs>();
  CLI::App* cmd = app.add_subcommand(
      "init",
      "Write a commented tyre config from a size designation, the modal test's and the "
      "operating pressure and the modal data (frequencies, or a hammer CSV): modal masses from "
      "the ring relations, orders proposed when not given (docs/ring_model.md). Nothing is "
      "calibrated.");
  auto& in = a->in;
  cmd->add_option("--size", in.size, "size designation, e.g. 195/60R14")->required();
  cmd->add_option("--test-pressure-kPa", in.test_pressure_kPa, "the modal test's pressure [kPa]")
      ->required();
  cmd->add_option("--pressure-kPa", in.pressure_kPa,
                  "operating pressure [kPa] (default: the test's)");
  cmd->add_option("--frequencies", a->frequencies, "natural frequencies [Hz], e.g. 96,112,135");
  cmd->add_option("--damping", a->damping, "damping ratios, one per frequency");
  cmd->add_option("--orders", a->orders,
                  "harmonic orders, one per frequency (r: the rotation mode); default: proposed");
  cmd->add_option("--hammer", in.hammer_csv, "a hammer CSV (fit-modes format, e.g. ema --output)");
  cmd->add_option("--belt-mass-kg", in.belt_mass_kg, "the belt's mass as its maker states it [kg]");
  cmd->add_option("--boundary", in.boundary, "the modal test's wheel: free (default) or rim-fixed")
      ->check(CLI::IsMember({"free", "rim-fixed"}));
  cmd->add_option("--wheel-mass-kg", in.wheel_mass_kg, "the wheel's mass in a free test [kg]");
  cmd->add_option("--belt-width-mm", in.belt_width_mm, "belt width [mm] (default: tread width)");
  cmd->add_option("--tread-depth-mm", in.tread_depth_mm, "tread depth [mm] (default 8)");
  cmd->add_option("--tread-width-mm", in.tread_width_mm,
                  "tread width [mm] (default 0.77 x section)");
  cmd->add_option("--fnomin", in.fnomin_N, "nominal load [N] for loads_N (default 4000)");
  cmd->add_option("--name", in.name, "tyre.name (default: size and pressure)");
  cmd->add_flag("--2d", in.two_d, "a 2D patch config (no footprint_3d:)");
  cmd->add_option("--output", a->output, "write the config here (default: standard output)");
  cmd->add_flag("--json", a->json, "print what init decided as JSON");
  cmd->callback([a, cmd] {
    if (cmd->count("--orders")) a->in.orders = parse_orders(a->orders);
    if (cmd->count("--frequencies"))
      a->in.frequencies_hz = numbers_of(a->frequencies, "--frequencies");
    if (cmd->count("--damping")) a->in.damping_ratios = numbers_of(a->damping, "--damping");
    CommandFiles files;  // the config must not replace the hammer data it names
    files.input(a->in.hammer_csv, "--hammer");
    if (cmd->count("--output")) files.output(a->output, "--output");
    files.check();
    a->in.output_path = a->output;
    const init::InitResult r = init::init_tyre(a->in);
    const nlohmann::json j = report::init_json(r, a->output);
    check_finite(j);
    if (!a->output.empty()) write_file_atomically(a->output, r.yaml);
    if (a->json) {
      print_json(j);
      return;
    }
    for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
    if (a->output.empty()) {
      std::cout << r.yaml;
      return;
    }
    std::cout << "wrote " << a->output << "\n  orders "
              << (r.orders_proposed ? "(proposed)" : "(given)");
    for (int k : r.orders) std::cout << " " << (k < 0 ? std::string("r") : std::to_string(k));
    std::cout << "\n  modal mass " << fixed(r.carcass.mass_per_length_kg_m, 3) << " kg/m from the "
              << r.carcass.mass_source << "; hoop tension " << fixed(r.carcass.tension_N, 0)
              << " N (net of the sidewalls' pull, share x p b R = "
              << fixed(r.carcass.membrane_tension_N, 0) << " N)\n";
    if (r.orders_proposed && r.alternatives.size() > 1) {
      std::cout << "  alternatives (score, lower is better):\n";
      for (const auto& p : r.alternatives) {
        std::cout << "   ";
        for (int k : p.orders) std::cout << " " << k;
        std::cout << "   score " << fixed(p.score, 1) << ", RMS " << fixed(100 * p.rms_rel_error, 2)
                  << " %, mu " << fixed(p.mass_per_length_kg_m, 2) << " kg/m\n";
      }
    }
  });
}

}  // namespace modaltyre::app

#include "cli_support.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/report/check_finite.h"

namespace modaltyre::app {

void print_json(const nlohmann::json& j) {
  check_finite(j);
  std::cout << j.dump(2) << std::endl;
}

CLI::Validator physical_range(double lo, double hi, const std::string& unit, const std::string& why,
                              bool lo_inclusive) {
  auto number = [](double v) {  // 1e+07 -> 1e7
    std::ostringstream s;
    s << v;
    std::string t = s.str();
    for (const char* from : {"e+0", "e+", "e-0"}) {
      const auto at = t.find(from);
      if (at != std::string::npos)
        t.replace(at, std::string(from).size(), from[1] == '-' ? "e-" : "e");
    }
    return t;
  };
  const std::string text =
      std::string(lo_inclusive ? "[" : "(") + number(lo) + ", " + number(hi) + "] " + unit;
  return CLI::Validator(
      [=](std::string& input) -> std::string {
        const auto parsed = parse_finite_double(input);
        if (!parsed) {
          return "'" + printable(input) + "' is not a finite number (range " + text + ")" +
                 decimal_hint(input);
        }
        const double v = *parsed;
        if (!(lo_inclusive ? v >= lo : v > lo) || !(v <= hi)) {
          return printable(input) + " is outside " + text + ": " + why;
        }
        return "";
      },
      text);
}

void require_decimal_numbers(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    const std::string type = opt->get_type_name();
    const std::string base = type.substr(0, type.find(':'));
    if (base != "FLOAT" && base != "INT" && base != "UINT") continue;
    opt->check(CLI::Validator(
        [](std::string& input) -> std::string {
          if (parse_finite_double(input)) return "";
          return "'" + printable(input) + "' is not a decimal number" + decimal_hint(input);
        },
        ""));
  }
  for (CLI::App* sub : app.get_subcommands({})) require_decimal_numbers(*sub);
}

void check_output_paths(CLI::App& app) {
  static const char* outputs[] = {"--output",  "--plot",       "--csv",
                                  "--map-csv", "--out-config", "--write-config"};
  for (const char* name : outputs) {
    CLI::Option* opt = nullptr;
    try {
      opt = app.get_option(name);
    } catch (const CLI::OptionNotFound&) {
      continue;
    }
    opt->check(CLI::Validator(
        [](std::string& input) -> std::string {
          namespace fs = std::filesystem;
          if (input.empty()) return "an empty path: give the file to write";
          const fs::path p(input);
          std::error_code ec;
          if (fs::is_directory(p, ec))
            return "'" + printable(input, 4096) + "' is a directory, not a file";
          const fs::path folder = fs::absolute(p, ec).parent_path();
          if (!fs::is_directory(folder, ec)) {
            return "'" + printable(input, 4096) + "': output folder '" +
                   printable(folder.string(), 4096) + "' does not exist";
          }
          return "";
        },
        ""));
  }
  for (CLI::App* sub : app.get_subcommands({})) check_output_paths(*sub);
}

std::string pct(double rel) { return fixed(100 * rel, 2) + " %"; }

double unsigned_zero(double v, int decimals) {
  return std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  // A value that rounds to zero prints without a sign: "-0.0" reads as a negative result.
  if (buf[0] == '-' && std::string(buf).find_first_not_of("-0.") == std::string::npos) {
    return buf + 1;
  }
  return buf;
}

uncertainty::PropagationOptions UncertaintyMethodArgs::options() const {
  uncertainty::PropagationOptions o;
  o.method = method == "linear"    ? uncertainty::Method::linear
             : method == "sampled" ? uncertainty::Method::sampled
                                   : uncertainty::Method::automatic;
  o.samples = samples;
  return o;
}

void add_uncertainty_method_options(CLI::App* cmd, UncertaintyMethodArgs& a) {
  cmd->add_option("--uncertainty-method", a.method,
                  "linear, sampled or auto (default: linear unless its curvature check fails)")
      ->check(CLI::IsMember({"linear", "sampled", "auto"}));
  cmd->add_option("--samples", a.samples,
                  "Monte Carlo samples of the sampled method (default 200, at most 2000)")
      ->check(physical_range(uncertainty::kMinSamples, uncertainty::kMaxSamples, "samples",
                             "below 20 no 2.5 % point exists; above 2000 the band's ends "
                             "move by less than their sampling scatter for hours of work "
                             "(docs/uncertainty.md)",
                             true));
}

std::function<void(int, int)> UncertaintyProgress::callback() {
  return [this](int done, int total) {
    if (!bar_ || total != phase_total_) {
      if (bar_) bar_->finish();
      bar_ = std::make_unique<ProgressBar>(static_cast<std::size_t>(total), "uncertainty");
      phase_total_ = total, shown_done_ = 0;
    }
    if (done > shown_done_) bar_->tick(static_cast<std::size_t>(done - shown_done_));
    shown_done_ = std::max(shown_done_, done);
  };
}

void UncertaintyProgress::finish() {
  if (bar_) bar_->finish();
}

std::string plot_colour(int k) {
  static const int kLinetypes[] = {1, 2, 3, 4, 6, 7, 8};
  return " lc " + std::to_string(kLinetypes[((k % 7) + 7) % 7]);
}

}  // namespace modaltyre::app

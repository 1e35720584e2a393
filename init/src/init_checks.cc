#include "init_checks.h"

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/input_file.h"

namespace modaltyre::init {
namespace {

/// The modal test's and the operating pressure [kPa]: the config reader's range (a tyre below
/// 10 kPa is not a modal carcass; 2000 kPa exceeds any tyre).
constexpr double kMinPressure_kPa = 10, kMaxPressure_kPa = 2000;
/// A tyre name is one line of text; a longer one is not a name.
constexpr std::size_t kMaxNameBytes = 200;
/// The ring's mass per length [kg/m] no tyre lies outside: a whole bicycle tyre is about
/// 0.2 kg/m, and the ring's mass (the one that makes its frequencies and statics agree) can be
/// several times below a tyre's weighed belt (the 205/60R15 of docs/validation.md: 0.67 against
/// 3.9 kg/m); the largest earthmover tyres (59/80R63, about 5 t on a 12.6 m circumference)
/// weigh 400 kg/m whole.
constexpr double kMinRingMass_kg_m = 0.02, kMaxRingMass_kg_m = 500;

// (Not num(): init_tyre.cc's, with ten digits, shares a unity translation unit with this file.)
std::string num6(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// A given number: finite, > 0 and at most `hi`, else an InputError at the option.
void check_given(const std::optional<double>& v, const std::string& option, const std::string& what,
                 double hi, const std::string& why_hi) {
  if (!v) return;
  if (!std::isfinite(*v) || !(*v > 0)) {
    throw InputError({option, 0, ""}, what + " must be a number > 0, got " + num6(*v) +
                                          " (leave the option out for the stated default)");
  }
  if (*v > hi) throw InputError({option, 0, ""}, what + " " + num6(*v) + " exceeds " + why_hi);
}

void check_pressure(double kPa, const std::string& option, const std::string& what) {
  if (!std::isfinite(kPa) || !(kPa > 0)) {
    throw InputError({option, 0, ""}, what + " must be > 0, got " + num6(kPa));
  }
  if (kPa < kMinPressure_kPa || kPa > kMaxPressure_kPa) {
    throw InputError({option, 0, ""}, what + " " + num6(kPa) +
                                          " kPa is outside 10-2000 kPa (below 10 kPa a tyre is "
                                          "not a modal carcass; 2000 kPa exceeds any tyre)");
  }
}

// The name goes into a comment line and a quoted YAML string: one line of UTF-8 text.
void check_name(const std::string& name) {
  for (unsigned char c : name) {
    if (c < 0x20 || c == 0x7F) {
      throw InputError({"--name", 0, ""},
                       "contains the control character " + printable(std::string(1, char(c))) +
                           " (a line break or tab would end the config's header comment): "
                           "give the name as one line of text");
    }
  }
  if (!valid_utf8(name)) {
    throw InputError({"--name", 0, ""}, "'" + printable(name) + "' has bytes that are not UTF-8");
  }
  if (name.size() > kMaxNameBytes) {
    throw InputError({"--name", 0, ""},
                     "longer than " + std::to_string(kMaxNameBytes) + " bytes; a name is one line");
  }
}

}  // namespace

void check_init_inputs(const InitInputs& in, const TyreSize& size) {
  check_name(in.name);
  check_pressure(in.test_pressure_kPa, "--test-pressure-kPa", "the modal test's pressure");
  if (in.pressure_kPa) check_pressure(*in.pressure_kPa, "--pressure-kPa", "the operating pressure");
  const bool list_given = !in.frequencies_hz.empty();
  if (list_given == !in.hammer_csv.empty()) {
    throw InputError({"--frequencies", 0, ""},
                     "give the modal data as exactly one of --frequencies F1,F2,... or --hammer "
                     "FILE");
  }
  if (!list_given && !in.orders.empty()) {
    throw InputError({"--orders", 0, ""},
                     "belongs to --frequencies: a hammer file's orders come from its shapes "
                     "(fit-modes); leave --orders out, or give the frequencies as a list");
  }
  if (!list_given && !in.damping_ratios.empty()) {
    throw InputError({"--damping", 0, ""},
                     "belongs to --frequencies: a hammer file states each mode's damping_ratio");
  }
  if (in.boundary != "free" && in.boundary != "rim-fixed")
    throw InputError({"--boundary", 0, ""}, "'" + in.boundary + "' is not free or rim-fixed");
  const std::string section = "the section width " + num6(size.section_width_mm) + " mm of " +
                              size.text + " (the belt and tread lie within the section)";
  check_given(in.belt_width_mm, "--belt-width-mm", "the belt width", size.section_width_mm,
              section);
  check_given(in.tread_width_mm, "--tread-width-mm", "the tread width", size.section_width_mm,
              section);
  check_given(in.tread_depth_mm, "--tread-depth-mm", "the tread depth",
              0.5 * size.section_height_mm(),
              "half the section height " + num6(size.section_height_mm()) + " mm of " + size.text);
  // The config reader's bounds (contact/carcass_source.cc), named here at the option.
  check_given(in.wheel_mass_kg, "--wheel-mass-kg", "the wheel's mass", 1e4,
              "10 t, more than any wheel");
  check_given(in.belt_mass_kg, "--belt-mass-kg", "the belt's mass", 1e5,
              "100 t, more than any tyre");
  // loads_N are 0.5-1.5 FNOMIN and at most 1e7 N (1000 t on one wheel).
  check_given(in.fnomin_N, "--fnomin", "the nominal load", 1e7 / 1.5,
              "what keeps 1.5 x FNOMIN within 1e7 N (1000 t on one wheel)");
}

std::string option_of_key(const std::string& key) {
  static const std::vector<std::pair<std::string, std::string>> table = {
      {"tyre.name", "--name"},
      {"tyre.inflation_pressure_kPa", "--pressure-kPa"},
      {"tyre.outer_radius_mm", "--size"},
      {"tyre.section_width_mm", "--size"},
      {"tyre.aspect_ratio", "--size"},
      {"tyre.rim_radius_mm", "--size"},
      {"contact.window_mm", "--size"},
      {"modal.frequencies_hz", "--frequencies"},
      {"modal.rotation_frequency_hz", "--frequencies"},
      {"modal.orders", "--orders"},
      {"modal.damping_ratios", "--damping"},
      {"modal.rotation_damping_ratio", "--damping"},
      {"modal.hammer_csv", "--hammer"},
      {"modal.test_pressure_kPa", "--test-pressure-kPa"},
      {"modal.boundary", "--boundary"},
      {"modal.wheel_mass_kg", "--wheel-mass-kg"},
      {"modal.belt_width_mm", "--belt-width-mm"},
      {"modal.belt_mass_kg", "--belt-mass-kg"},
      {"tread.thickness_mm", "--tread-depth-mm"},
      {"tread.contact_width_mm", "--tread-width-mm"},
      {"footprint_3d.tread_width_mm", "--tread-width-mm"},
      {"loads_N", "--fnomin"}};
  for (const auto& [k, option] : table) {
    if (k == key) return option;
  }
  return "";
}

void rethrow_at_option(const InputError& e) {
  const std::string prefix = format_location(e.where(), "");
  std::string message = e.what();
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  const std::string& key = e.where().key;
  const std::string option = option_of_key(key);
  if (!option.empty()) throw InputError({option, 0, ""}, message + " (written as " + key + ")");
  throw InputError({"init", 0, key}, message + " (in the config init would write)");
}

void check_ring_mass(double mu, double outer_radius_m, bool from_list) {
  if (mu >= kMinRingMass_kg_m && mu <= kMaxRingMass_kg_m) return;
  const double belt_kg = 2 * M_PI * outer_radius_m * mu;
  throw InputError(
      {from_list ? "--frequencies" : "--hammer", 0, ""},
      "the modes make the ring's mass per length " + num6(mu) + " kg/m (a belt of " +
          num6(belt_kg) + " kg), outside the " + num6(kMinRingMass_kg_m) + "-" +
          num6(kMaxRingMass_kg_m) +
          " kg/m of any tyre from a bicycle's to an earthmover's: are they this tyre's natural "
          "frequencies in Hz? (a passenger tyre's lie at about 80-300 Hz)");
}

}  // namespace modaltyre::init

#pragma once
// `modaltyre init`: a commented tyre config from what a researcher has — a size designation,
// the modal test's and the operating pressure, and the modal data (a frequency list with
// damping and orders if known, or a hammer CSV / `ema` output). Every value written says where
// it comes from: the input, a named relation (docs/ring_model.md), or a stated default with its
// range and source. Nothing is carried over from another tyre's calibration.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/init/tyre_size.h"
#include "modaltyre/modal/order_proposal.h"

namespace modaltyre::init {

struct InitInputs {
  std::string size;                    ///< e.g. "195/60R14" (required)
  std::string name;                    ///< tyre.name; "" = the size and pressure
  double test_pressure_kPa = 0;        ///< the modal test's pressure (required)
  std::vector<double> frequencies_hz;  ///< a frequency list, or
  std::string hammer_csv;              ///< a hammer CSV (`ema --output`); exactly one of the two
  std::vector<double> damping_ratios;  ///< per frequency; empty = the stated default
  /// Per frequency: an order >= 0, or -1 for the rigid rotation mode; empty = proposed.
  std::vector<int> orders;
  std::string boundary = "free";  ///< the modal test's: "free" or "rim-fixed"
  // Not given = the stated default; a given value must be a physical one (> 0, in range): a 0
  // or -1 is refused at its option, never read as "not given".
  std::optional<double> pressure_kPa;    ///< the operating pressure; default the test's
  std::optional<double> wheel_mass_kg;   ///< default: stated for the rim diameter
  std::optional<double> belt_mass_kg;    ///< a maker's belt mass (check and order-1 mass)
  std::optional<double> belt_width_mm;   ///< default: the tread width
  std::optional<double> tread_depth_mm;  ///< default: the stated new-tread depth
  std::optional<double> tread_width_mm;  ///< default: the stated share of the section width
  std::optional<double> fnomin_N;        ///< the loads' centre; default the passenger FNOMIN
  bool two_d = false;                    ///< a 2D patch config (no footprint_3d:)
  std::string output_path;  ///< where the config will be written (relative hammer path)
};

/// One decision `init` made, as `init --json` reports it.
struct InitDecision {
  std::string key;     ///< dotted config key
  std::string value;   ///< as written
  std::string source;  ///< "input", a relation, or a default with its range and source
};

struct InitResult {
  std::string yaml;  ///< the config text, comments included
  std::vector<InitDecision> decisions;
  std::vector<int> orders;  ///< the orders used, per frequency (-1 = rotation)
  bool orders_proposed = false;
  std::vector<modal::OrderProposal> alternatives;  ///< best first (proposed orders)
  contact::CarcassDerivation carcass;  ///< implied mass, tension, ring fit of the built model
  std::vector<std::string> warnings;
};

/// Validates the inputs (InputError naming the option), proposes orders when none are given,
/// writes the config text and builds the model once from it (so that what is written runs).
InitResult init_tyre(const InitInputs& inputs);

}  // namespace modaltyre::init

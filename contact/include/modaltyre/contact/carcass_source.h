#pragma once
// Where the carcass's modal data come from and how they are scaled (docs/ring_model.md):
// measured mass-normalised shapes (modal.hammer_csv, today's path), or frequencies and orders
// alone (modal.frequencies_hz / orders, or a hammer CSV with modal.normalisation: ring) whose
// modal masses the ring relations supply. The modal test's pressure and boundary are properties
// of the data; the operating pressure acts on the ring's pressure terms whenever it differs.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/modal/modal_basis.h"
#include "modaltyre/modal/mode_identification.h"
#include "modaltyre/modal/ring_model.h"

namespace modaltyre::contact {

struct TyreConfig;

enum class ModalNormalisation { shapes, ring };
enum class TestBoundary { rim_fixed, free };

/// The modal: keys beyond hammer_csv / compliance_scale / extension (tyre_config.h).
struct CarcassSettings {
  /// modal.frequencies_hz, orders, damping_ratios: a frequency list (empty = hammer_csv).
  std::vector<double> frequencies_hz;
  std::vector<int> orders;
  std::vector<double> damping_ratios;
  /// modal.order_alternatives / order_alternative_probabilities: other order assignments of the
  /// frequency list that fit nearly as well (init's near-ties, issue 36 item 3), each with its
  /// probability; `orders` has the rest (1 - their sum). The uncertainty propagation mixes them
  /// (docs/uncertainty.md section 2); the prediction itself uses `orders`.
  std::vector<std::vector<int>> order_alternatives;
  std::vector<double> order_alternative_probabilities;
  /// modal.rotation_frequency_hz / rotation_damping_ratio: the rigid rotation mode, 0 = none.
  double rotation_frequency_hz = 0;
  double rotation_damping_ratio = 0;
  /// modal.normalisation: the hammer shapes' own scale, or the ring's (always for a list).
  ModalNormalisation normalisation = ModalNormalisation::shapes;
  /// modal.test_pressure_kPa: the modal test's pressure [Pa]; 0 = not stated (then the data
  /// are taken at the operating pressure, with a warning).
  double test_pressure_Pa = 0;
  /// modal.boundary: the modal test's wheel (rim-fixed, or free on a soft support).
  TestBoundary boundary = TestBoundary::rim_fixed;
  double wheel_mass_kg = 0;  ///< modal.wheel_mass_kg, required for a free test
  /// modal.belt_width_mm: b of the hoop tension T = p b R [m]; 0 = not stated.
  double belt_width_m = 0;
  /// modal.net_tension_share: the belt's net hoop tension as a share of p b R, after the
  /// sidewalls' pull at the belt edges (docs/ring_model.md section 3a); 1 = the gross p b R.
  double net_tension_share = 1.0;
  bool net_tension_share_stated = false;  ///< the key was in the config
  /// modal.mass_per_length_kg_m: a stated ring mass mu (overrides the tension's); 0 = none.
  double mass_per_length_kg_m = 0;
  /// modal.belt_mass_kg: the belt's mass as a maker states it (MF-Swift BELT_MASS): a check of
  /// the tension's mass and the order-1 mass of the boundary correction; 0 = none.
  double belt_mass_kg = 0;
  /// modal.foundation_pneumatic_fraction: share of the sidewall foundation proportional to the
  /// pressure (1 = inflated membrane sidewalls).
  double foundation_pneumatic_fraction = 1.0;

  bool frequency_list() const { return !frequencies_hz.empty(); }
};

/// Reads the keys above from `modal` (InputErrors name file, line and key).
CarcassSettings read_carcass_settings(const ConfigSection& modal);

/// What the carcass was built from: the figures `footprint --json`, `init --json` and the
/// warnings report.
struct CarcassDerivation {
  bool ring = false;                ///< ring normalisation (else the shapes' own scale)
  modal::RingFit fit;               ///< at the test pressure, rim-held
  double mass_per_length_kg_m = 0;  ///< mu used (ring) or implied by the shapes (median)
  std::string mass_source;          ///< "tension", "stated", "belt_mass", "shapes"
  double tension_N = 0;             ///< T implied by mu and the fit (at the test pressure)
  double membrane_tension_N = 0;    ///< share x p b R, the net tension (0 without a belt width)
  double test_pressure_Pa = 0, operating_pressure_Pa = 0;
  std::vector<std::string> warnings;
};

/// The modes of the config: its hammer data identified, or its frequency list as modes of the
/// stated orders (kind radial; the rotation mode kind rotation).
modal::ModeIdentification config_modes(const TyreConfig& config);

/// The carcass's modal basis at the config's operating pressure, rim-held, and how it was
/// derived. `max_order` is the sums' highest order.
modal::ModalBasis carcass_basis(const TyreConfig& config, const modal::ModeIdentification& modes,
                                int max_order, CarcassDerivation& derivation);

/// Every term's frequency moved from the model's operating pressure to `pressure_Pa` by the
/// ring's pressure terms (an order's stiffness K_n(p) / K_n(p_model)); the basis unchanged when
/// the derivation has no ring fit.
modal::ModalBasis basis_at_pressure(const modal::ModalBasis& basis,
                                    const CarcassDerivation& derivation,
                                    const CarcassSettings& settings, double pressure_Pa);

}  // namespace modaltyre::contact

#include "modaltyre/modal/ring_basis.h"

#include <cmath>
#include <map>

#include "modaltyre/core/errors.h"

namespace modaltyre::modal {
namespace {
constexpr double kTwoPi = 6.28318530717958647692;

// The shape products of an order-n ring mode with inward radial amplitude^2 `a2`.
void set_ring_shape(ModalTerm& t, int n, double a2) {
  t.P_rr = a2;
  t.P_tt = a2 / (double(n) * n);
  t.P_rt = std::complex<double>(0.0, a2 / n);
}
}  // namespace

ModalBasis build_ring_basis(const std::vector<RingMode>& modes, const RingFit& fit,
                            const RingBasisOptions& o) {
  MODALTYRE_CHECK(o.mass_per_length_kg_m > 0 && o.radius_m > 0, "ring basis needs mu and R");
  const double mu = o.mass_per_length_kg_m, R = o.radius_m;
  ModalBasis basis;
  std::map<int, int> members;  // radial order -> modes of that order
  for (const RingMode& m : modes) {
    if (m.order < 0 || !(m.freq_hz > 0) || !std::isfinite(m.freq_hz)) {
      throw InputError("mode " + std::to_string(m.id) + " (order " + std::to_string(m.order) +
                       "): needs an order >= 0 and a positive frequency");
    }
    if (!m.rotation) ++members[m.order];
  }
  int max_measured = 0;
  double zeta_sum = 0;
  int zeta_n = 0;
  for (const RingMode& m : modes) {
    ModalTerm t;
    t.order = m.rotation ? 0 : m.order;
    t.rotation = m.rotation;
    t.mode_id = m.id;
    t.omega_rad_s = kTwoPi * m.freq_hz;
    t.damping_ratio = m.damping_ratio;
    if (m.rotation) {
      t.P_tt = 1.0 / (kTwoPi * R * mu);
    } else if (m.order == 0) {
      t.P_rr = 1.0 / (kTwoPi * R * mu);
      t.weight = 1.0 / members[0];
    } else {
      set_ring_shape(t, m.order, 1.0 / (M_PI * R * mu * ring_mass_factor(m.order)));
      t.weight = 1.0 / members[m.order];  // two entries of one order share the pair
      max_measured = std::max(max_measured, m.order);
      if (m.order >= 2) {
        zeta_sum += m.damping_ratio;
        ++zeta_n;
      }
    }
    basis.terms.push_back(t);
  }
  basis.measured_terms = static_cast<int>(basis.terms.size());
  basis.max_order = o.extend ? std::max(o.max_order, max_measured) : max_measured;
  for (int k : {0, 1}) {
    if (!members.count(k)) {
      basis.warnings.push_back("no order-" + std::to_string(k) +
                               " mode: " + (k == 0 ? "breathing" : "rigid translation") +
                               " compliance is missing from the kernel");
    }
  }
  if (o.extend && basis.max_order > max_measured) {
    if (!fit.valid) {
      throw InputError("cannot extend the modal basis beyond order " +
                       std::to_string(max_measured) + ": ring fit " + fit.reason);
    }
    const double zeta = zeta_n ? zeta_sum / zeta_n : 0.0;
    for (int k = 2; k <= basis.max_order; ++k) {
      if (members.count(k)) continue;
      ModalTerm t;
      t.order = k;
      t.measured = false;
      t.omega_rad_s = std::sqrt(fit.coefficients.omega_sq(k));
      t.damping_ratio = zeta;
      set_ring_shape(t, k, 1.0 / (M_PI * R * mu * ring_mass_factor(k)));
      basis.terms.push_back(t);
    }
  }
  for (auto& t : basis.terms) {
    MODALTYRE_CHECK(t.omega_rad_s > 0 && std::isfinite(t.omega_rad_s), "bad modal frequency");
    t.P_rr *= o.compliance_scale;
    t.P_tt *= o.compliance_scale;
    t.P_rt *= o.compliance_scale;
  }
  return basis;
}

}  // namespace modaltyre::modal

#include "modaltyre/modal/modal_basis.h"

#include <cmath>
#include <map>
#include <set>

#include "modaltyre/core/errors.h"

namespace modaltyre::modal {
namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

double ModalBasis::static_rr(int k) const {
  double s = 0;
  for (const auto& t : terms)
    if (t.order == k) s += t.weight * t.P_rr.real() / (t.omega_rad_s * t.omega_rad_s);
  return s;
}

ModalBasis build_modal_basis(const ModeIdentification& ident, const ModalBasisOptions& opts) {
  ModalBasis basis;
  basis.dispersion = ident.dispersion;
  std::map<int, int> count;  // order -> number of measured members used
  std::vector<const IdentifiedMode*> used;
  for (const auto& m : ident.modes) {
    if (m.kind == ModeKind::rotation || (m.kind == ModeKind::radial && !m.aliased)) {
      used.push_back(&m);
      if (m.kind == ModeKind::radial) ++count[m.apparent_order];
    }
  }
  if (used.empty())
    throw InputError("hammer data: no resolved mode to build a carcass kernel from");

  int max_measured = 0;
  double amp_sum = 0, zeta_sum = 0, coupling_sum = 0;
  int amp_n = 0;
  for (const IdentifiedMode* m : used) {
    ModalTerm t;
    t.mode_id = m->id;
    t.omega_rad_s = kTwoPi * m->freq_hz;
    t.damping_ratio = m->damping_ratio;
    if (m->kind == ModeKind::rotation) {
      t.order = 0;
      t.rotation = true;
      t.weight = 1.0;
      t.P_rr = m->radial.A[0] * m->radial.A[0];
      t.P_tt = m->tangential.A[0] * m->tangential.A[0];
      t.P_rt = 0.0;  // mirror symmetry: no static radial-tangential coupling at order 0
    } else {
      const int k = m->apparent_order;
      t.order = k;
      t.weight = (k == 0 || count[k] == 1) ? 1.0 : 0.5;
      const auto cr = m->c_radial, ct = m->c_tangential;
      t.P_rr = cr * std::conj(cr);
      t.P_tt = ct * std::conj(ct);
      // Mirror symmetry of the tyre (theta -> -theta) puts the tangential shape in quadrature
      // with the radial one: only Im(c_r conj(c_t)) is physical; the real part is measurement
      // noise and would make the static footprint lean fore or aft.
      t.P_rt = std::complex<double>(0.0, (cr * std::conj(ct)).imag());
      max_measured = std::max(max_measured, k);
      if (k >= 2) {
        amp_sum += std::norm(cr);
        zeta_sum += m->damping_ratio;
        // Im(c_r conj(c_t)) = s |c_r|^2 / k for the inextensional ring.
        coupling_sum += t.P_rt.imag() * k / std::max(std::norm(cr), 1e-300);
        ++amp_n;
      }
    }
    t.P_rr *= opts.compliance_scale;
    t.P_tt *= opts.compliance_scale;
    t.P_rt *= opts.compliance_scale;
    basis.terms.push_back(t);
  }
  basis.measured_terms = static_cast<int>(basis.terms.size());
  // Without the extension the kernel's highest order is the highest measured one.
  basis.max_order = opts.extend ? std::max(opts.max_order, max_measured) : max_measured;

  for (int k : {0, 1}) {
    if (!count.count(k)) {
      basis.warnings.push_back(
          "no resolved order-" + std::to_string(k) + " mode in the hammer data: " +
          (k == 0 ? "breathing" : "rigid translation") + " compliance is missing from the kernel");
    }
  }
  if (opts.extend && basis.max_order > max_measured) {
    if (!ident.dispersion.valid) {
      throw InputError("hammer data: cannot extend the modal basis beyond order " +
                       std::to_string(max_measured) + ": dispersion fit " +
                       ident.dispersion.reason);
    }
    if (amp_n == 0) throw InputError("hammer data: no resolved radial mode of order >= 2");
    const double amp2 = amp_sum / amp_n * opts.compliance_scale;
    const double zeta = zeta_sum / amp_n;
    const double sign = coupling_sum >= 0 ? 1.0 : -1.0;
    for (int k = 2; k <= basis.max_order; ++k) {
      if (count.count(k)) continue;
      ModalTerm t;
      t.order = k;
      t.measured = false;
      t.weight = 1.0;
      t.omega_rad_s = std::sqrt(ident.dispersion.omega_sq(k));
      t.damping_ratio = zeta;
      t.P_rr = amp2;
      t.P_tt = amp2 / (double(k) * k);
      t.P_rt = std::complex<double>(0.0, sign * amp2 / k);
      basis.terms.push_back(t);
    }
  }
  for (const auto& t : basis.terms) {
    MODALTYRE_CHECK(t.omega_rad_s > 0 && std::isfinite(t.omega_rad_s), "bad modal frequency");
  }
  return basis;
}

}  // namespace modaltyre::modal

#include "modaltyre/modal/critical_speed.h"

#include <limits>

namespace modaltyre::modal {

CriticalSpeed critical_speed(const ModalBasis& basis, double radius_m, int max_order) {
  CriticalSpeed c;
  c.speed_m_s = std::numeric_limits<double>::infinity();
  for (const ModalTerm& t : basis.terms) {
    if (t.rotation || t.order < 1 || (max_order > 0 && t.order > max_order)) continue;
    const double v = t.omega_rad_s * radius_m / t.order;
    if (v < c.speed_m_s) c.speed_m_s = v, c.order = t.order;
  }
  return c;
}

}  // namespace modaltyre::modal

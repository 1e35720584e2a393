#pragma once
// The tyre's flexing (hysteresis) resistance for `traction` (docs/soil.md section 5.4): the
// tyre's own rolling resistance on the rigid road at the same load and speed, as the transient's
// rolling scenario measures it (transient/driver.h: the mean of -F_x, the moment of the contact
// forces about the axle over its height, over the run's last 10 %). One short run per load on
// the patch the traction runs on: 2D units or 3D cells, the config's transient: settings with
// the rolling scenario's load and speed replaced.
#include <map>
#include <vector>

#include "modaltyre/contact/tyre_model.h"

namespace modaltyre::report {

/// Per load [N]: the rolling resistance [N] at `speed_m_s` (0: none, an empty map).
/// ComputationError when a run fails, naming the load and the transient's reason.
std::map<double, double> flexing_resistance_N(const contact::TyreModel& tyre,
                                              const std::vector<double>& loads_N, double speed_m_s);

}  // namespace modaltyre::report

#include "modaltyre/report/traction_flexing.h"

#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/transient/driver.h"

namespace modaltyre::report {

std::map<double, double> flexing_resistance_N(const contact::TyreModel& tyre,
                                              const std::vector<double>& loads_N,
                                              double speed_m_s) {
  std::map<double, double> out;
  if (!(speed_m_s > 0)) return out;
  transient::TransientModel model = transient::build_transient_model(tyre);
  model.tyre.config.ground = ground::GroundSettings{};  // the rigid flat road
  for (double load : loads_N) {
    if (out.count(load)) continue;
    model.settings.rolling.load_N = load;
    model.settings.rolling.speed_m_s = speed_m_s;
    const transient::TransientResult r =
        transient::run_scenario(model, transient::Scenario::rolling);
    if (!r.ok()) {
      std::ostringstream msg;
      msg << "traction: the tyre's flexing resistance at " << load << " N, " << speed_m_s * 3.6
          << " km/h (the transient's rolling scenario on the road) failed: " << r.message;
      throw ComputationError(msg.str());
    }
    out[load] = r.rolling_resistance_N;
  }
  return out;
}

}  // namespace modaltyre::report

#include "modaltyre/transient/output_grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace modaltyre::transient {
namespace {

/// Output samples of one run (memory and CSV rows), as plan_scenario() bounds a stated step.
constexpr double kMaxSamples = 1e6;

/// The first time from + k step (k a whole number) after t.
double next_on(double from, double step, double t) {
  const double k = std::floor((t - from) / step + 1e-9) + 1;
  return from + k * step;
}

}  // namespace

double OutputGrid::next_after(double t) const {
  double c;
  if (fine_step_s > 0 && t < fine_from_s) {
    c = std::min(next_on(0, step_s, t), fine_from_s);
  } else if (fine_step_s > 0 && t < fine_until_s) {
    c = std::min(next_on(fine_from_s, fine_step_s, t), fine_until_s);
  } else if (fine_step_s > 0) {
    c = next_on(fine_until_s, step_s, t);
  } else {
    c = next_on(0, step_s, t);
  }
  if (c >= end_s || end_s - c < 1e-9 * end_s) c = end_s;
  return c;
}

double OutputGrid::step_at(double t) const {
  return fine_step_s > 0 && t >= fine_from_s && t < fine_until_s ? fine_step_s : step_s;
}

std::string OutputGrid::describe() const {
  std::ostringstream o;
  o.precision(3);
  o << "output every " << step_s * 1e3 << " ms";
  if (!chosen) return o.str() + " (transient.output_step_ms)";
  o << " (chosen: ";
  if (bounce_hz > 0)
    o << kSamplesPerBounce << " samples per period of the ~" << bounce_hz << " Hz hub bounce";
  else
    o << "the " << kAutoOutputStepCap_s * 1e3 << " ms default";
  if (fine_step_s > 0)
    o << "; every " << fine_step_s * 1e3 << " ms while the cleat crosses, "
      << kSamplesPerCleatPassage << " samples per passage of its length";
  if (sample_bound) o << "; coarsened to at most " << kMaxSamples << " samples over the run";
  return o.str() + ")";
}

OutputGrid output_grid(const TransientModel& model, const ScenarioPlan& plan, double initial_load_N,
                       double initial_sinking_m) {
  OutputGrid g;
  g.end_s = plan.duration_s;
  if (model.settings.output_step_s > 0) {  // stated (bounded by plan_scenario)
    g.step_s = model.settings.output_step_s;
    return g;
  }
  g.chosen = true;
  g.step_s = kAutoOutputStepCap_s;
  if (initial_load_N > 0 && initial_sinking_m > 0) {
    const double k = 2 * initial_load_N / initial_sinking_m;
    g.bounce_hz = std::sqrt(k / model.settings.hub_mass_kg) / (2 * M_PI);
    g.step_s = std::min(g.step_s, 1 / (kSamplesPerBounce * g.bounce_hz));
  }
  if (plan.cleat && plan.speed_m_s > 0 && plan.step_limit_until_s > plan.step_limit_from_s) {
    const double fine = plan.cleat_length_m / plan.speed_m_s / kSamplesPerCleatPassage;
    if (fine < g.step_s) {
      g.fine_step_s = fine;
      g.fine_from_s = plan.step_limit_from_s;
      g.fine_until_s = std::min(plan.step_limit_until_s, plan.duration_s);
    }
  }
  // Never more samples than a stated step may give.
  const double fine_span = g.fine_step_s > 0 ? g.fine_until_s - g.fine_from_s : 0.0;
  const double samples =
      plan.duration_s / g.step_s + (g.fine_step_s > 0 ? fine_span / g.fine_step_s : 0.0);
  if (samples > kMaxSamples) {
    const double scale = samples / kMaxSamples;
    g.step_s *= scale;
    g.fine_step_s *= scale;
    g.sample_bound = true;
  }
  return g;
}

}  // namespace modaltyre::transient

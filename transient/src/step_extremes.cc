#include "step_extremes.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace modaltyre::transient::detail {
namespace {

/// Quarter points searched inside each of a kept extreme's two steps.
constexpr double kQuarters[] = {0.25, 0.5, 0.75};

/// The vertex of the parabola through (x0, y0), (x1, y1), (x2, y2) when it is a maximum strictly
/// between x0 and x2 (else NaN). Times relative to x1 for the conditioning of short steps.
double parabola_max_at(double x0, double y0, double x1, double y1, double x2, double y2) {
  const double a = x0 - x1, c = x2 - x1;
  if (!(a < 0 && c > 0)) return NAN;
  // y = y1 + p u + q u^2 through (a, y0) and (c, y2), u = x - x1.
  const double q = ((y0 - y1) / a - (y2 - y1) / c) / (a - c);
  const double p = (y0 - y1) / a - q * a;
  if (!(q < 0)) return NAN;
  const double u = -p / (2 * q);
  return u > a && u < c ? x1 + u : NAN;
}

}  // namespace

StepExtremes::StepExtremes(ForceObserver at_steps, ForceObserver anywhere, int hub_z_index)
    : at_steps_(std::move(at_steps)), observe_(std::move(anywhere)), hub_z_index_(hub_z_index) {
  trackers_[0].quantity = 0, trackers_[0].sign = 1;   // largest load
  trackers_[1].quantity = 0, trackers_[1].sign = -1;  // smallest load
  trackers_[2].quantity = 1, trackers_[2].sign = 1;   // largest longitudinal force
  trackers_[3].quantity = 1, trackers_[3].sign = -1;  // smallest longitudinal force
}

double StepExtremes::value(const Tracker& k, const TransientSample& s) {
  return k.sign * (k.quantity == 0 ? s.load_N : s.longitudinal_force_N);
}

void StepExtremes::offer(const TransientSample& s) {
  for (Tracker& k : trackers_) {
    const double v = value(k, s);
    if (v > k.best) k.best = v, k.t_best = s.t_s;
  }
}

void StepExtremes::start(double t0, const std::vector<double>& y0) {
  const TransientSample s = observe_(t0, y0.data());
  for (Tracker& k : trackers_) k.best = value(k, s), k.t_best = t0, k.kept.clear();
  t_[2] = t0, y_[2] = std::make_shared<std::vector<double>>(y0), s_[2] = s;
  ends_seen_ = 1;
  started_ = true;
  hub_.clear();
  if (hub_z_index_ >= 0) hub_.push_back({t0, y0[static_cast<std::size_t>(hub_z_index_)]});
}

void StepExtremes::on_quadratic(const Pair& p, double t, std::vector<double>& y) const {
  // Lagrange basis on the three (unequally spaced) ends.
  const double t0 = p.t[0], t1 = p.t[1], t2 = p.t[2];
  const double l0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
  const double l1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
  const double l2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
  const auto &a = *p.y[0], &b = *p.y[1], &c = *p.y[2];
  y.resize(b.size());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = l0 * a[i] + l1 * b[i] + l2 * c[i];
}

void StepExtremes::keep(Tracker& k, double v) {
  // The pair of steps around the middle end of the last three (t_[1]).
  auto& kept = k.kept;
  if (static_cast<int>(kept.size()) == kKept) {
    auto low = std::min_element(kept.begin(), kept.end(),
                                [](const Pair& a, const Pair& b) { return a.value < b.value; });
    if (!(v > low->value)) return;
    kept.erase(low);
  }
  Pair p;
  p.value = v;
  p.t = t_;
  p.s = s_;
  for (std::size_t i = 0; i < 3; ++i) p.y[i] = y_[i];
  kept.push_back(std::move(p));
}

void StepExtremes::step(double t1, const std::vector<double>& y1) {
  if (!started_) return;
  const TransientSample s1 = at_steps_(t1, y1.data());
  offer(s1);
  // Rotate the last ends (the vectors are swapped, the newest copied into the oldest's memory).
  std::swap(t_[0], t_[1]), std::swap(t_[1], t_[2]);
  std::swap(y_[0], y_[1]), std::swap(y_[1], y_[2]);
  std::swap(s_[0], s_[1]), std::swap(s_[1], s_[2]);
  t_[2] = t1, s_[2] = s1;
  // The oldest end's buffer takes the new state unless a kept pair holds it.
  if (!y_[2] || y_[2].use_count() > 1)
    y_[2] = std::make_shared<std::vector<double>>(y1);
  else
    y_[2]->assign(y1.begin(), y1.end());
  if (hub_z_index_ >= 0) hub_.push_back({t1, y1[static_cast<std::size_t>(hub_z_index_)]});
  if (++ends_seen_ < 3) return;
  // A local extreme at the middle end of the last three: keep the three ends if it is among
  // the kKept largest of its signal so far.
  for (Tracker& k : trackers_) {
    const double a = value(k, s_[0]), b = value(k, s_[1]), c = value(k, s_[2]);
    if (b > a && b >= c) keep(k, b);
  }
}

void StepExtremes::search(Tracker& k, const Pair& p) {
  ++searches_;
  std::vector<TransientSample> pts;
  for (std::size_t half = 0; half < 2; ++half) {
    const double ta = p.t[half], tb = p.t[half + 1];
    pts.push_back(p.s[half]);
    for (double f : kQuarters) {
      const double t = ta + f * (tb - ta);
      on_quadratic(p, t, work_);
      pts.push_back(observe_(t, work_.data()));
    }
  }
  pts.push_back(p.s[2]);
  for (const TransientSample& s : pts) offer(s);
  std::size_t i = 0;
  for (std::size_t j = 1; j < pts.size(); ++j)
    if (value(k, pts[j]) > value(k, pts[i])) i = j;
  if (i == 0 || i + 1 == pts.size()) return;
  const double t = parabola_max_at(pts[i - 1].t_s, value(k, pts[i - 1]), pts[i].t_s,
                                   value(k, pts[i]), pts[i + 1].t_s, value(k, pts[i + 1]));
  if (!std::isfinite(t)) return;
  on_quadratic(p, t, work_);
  offer(observe_(t, work_.data()));
}

void StepExtremes::finish(TransientResult& r) {
  if (!started_) return;
  for (Tracker& k : trackers_)
    for (const Pair& p : k.kept) search(k, p);
  auto range = [&](int hi, int lo) {
    const Tracker &a = trackers_[static_cast<std::size_t>(hi)],
                  &b = trackers_[static_cast<std::size_t>(lo)];
    return SignalRange{-b.best, a.best, b.t_best, a.t_best};
  };
  r.extremes.load_N = range(0, 1);
  r.extremes.longitudinal_force_N = range(2, 3);
  r.extremes.valid = true;
  r.extremes.searches = searches_;
  r.hub_steps = std::move(hub_);
}

}  // namespace modaltyre::transient::detail

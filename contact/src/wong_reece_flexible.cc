// Wong and Reece's normal stress on the flexible tyre: see wong_reece_flexible.h.
#include "wong_reece_flexible.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace modaltyre::contact::detail {
namespace {

// The flow compliance over the column's (deepest sinkage / peak front stress): a rear cell
// pressed the whole sinkage below its surface carries sigma_t + 1 % of the peak stress. The
// prescription's error: the 100x stiffer tyre meets the rigid wheel's Wong-Reece sinkage to
// 0.08 % at 100 and 0.7 % at 10 (docs/soil.md section 10); at 1e3 the 2D fixed point stops
// settling (the flowing cells' depth follows the tyre's shape with too little stiffness).
constexpr double kFlowScale = 100;

double angle(double x_m, double R0_m) { return std::asin(std::clamp(x_m / R0_m, -1.0, 1.0)); }

}  // namespace

double FlowStressLaw::loading_Pa(double z_m) const {
  return z_m >= zs_ ? sigma_ + (z_m - zs_) / c_ : 0.0;
}

double FlowStressLaw::loading_sinkage_m(double p_Pa) const {
  return zs_ + c_ * std::max(0.0, p_Pa - sigma_);
}

double FlowStressLaw::unloading_Pa(double z_m, double) const { return loading_Pa(z_m); }

double FlowStressLaw::unloading_sinkage_m(double p_Pa, double) const {
  return loading_sinkage_m(p_Pa);
}

double FlowStressLaw::compliance_m_per_Pa(double p_Pa, double) const {
  return p_Pa >= sigma_ ? c_ : 0.0;
}

double FlowStressLaw::virgin_sinkage_m(double p_Pa, double& dz_dp_m_per_Pa) const {
  dz_dp_m_per_Pa = compliance_m_per_Pa(p_Pa, zs_);
  return loading_sinkage_m(p_Pa);
}

double FlowStressLaw::work_J_m2(double p_Pa, double) const {
  const double flow = std::max(0.0, p_Pa - sigma_);
  return zs_ * std::max(p_Pa, 0.0) + 0.5 * c_ * flow * flow;
}

WongReeceRear::WongReeceRear(const ground::WongReeceStress& wr, double slip, double R0_m,
                             int sections, int classes, double exit_reach)
    : wr_(wr),
      slip_(slip),
      R0_(R0_m),
      exit_reach_(std::clamp(exit_reach, 0.0, 1.0)),
      sections_(sections),
      classes_(classes),
      cells_(std::size_t(sections) * classes) {
  // The rear region [theta2, theta_m) is empty for every entry angle when both ends are 0.
  on_ = wr.has_rear_region(slip);
  if (on_) wr.validate();
}

void WongReeceRear::prepare(RearState& st) const {
  if (!on_) return;
  if (st.target_N.size() != cells_) st.target_N.assign(cells_, 0.0);
  if (st.rear.size() != cells_) st.rear.assign(cells_, 0);
  if (st.behind.size() != cells_) st.behind.assign(cells_, 0);
  if (st.flow_m_per_Pa.size() != std::size_t(classes_)) st.flow_m_per_Pa.assign(classes_, 0.0);
  if (st.exit_depth_m.size() != std::size_t(classes_)) st.exit_depth_m.assign(classes_, 0.0);
  if (st.exit_last.size() != std::size_t(classes_)) st.exit_last.assign(classes_, -1);
  if (st.exit_prev.size() != std::size_t(classes_)) st.exit_prev.assign(classes_, -1);
  if (st.exit_weight.size() != std::size_t(classes_)) st.exit_weight.assign(classes_, 0.0);
}

void WongReeceRear::set_exit_depths(RearState& st, const std::vector<double>& depth_m) const {
  if (!on_) return;
  for (int k = 0; k < classes_; ++k) {
    const int last = st.exit_last[k], prev = st.exit_prev[k];
    if (last < 0 || std::size_t(last) >= depth_m.size()) {
      st.exit_depth_m[k] = 0;
      continue;
    }
    const double d_last = depth_m[last];
    const double d_prev = prev >= 0 && std::size_t(prev) < depth_m.size() ? depth_m[prev] : d_last;
    // The profile deepens towards theta2; a rear cell whose gap is open (d_prev deeper) adds 0.
    // Extrapolated no further than exit_reach_ (the caller's: the last rear cell's own segment,
    // half a unit behind it; beyond, theta2 lies in the first behind cell's segment, whose floor
    // would then follow that cell's own depth: a floor that moves with the tyre, on which its
    // contact switches step after step without end; docs/soil.md section 10).
    const double w = std::min(st.exit_weight[k], exit_reach_);
    st.exit_depth_m[k] = d_last + w * std::max(0.0, d_last - d_prev);
  }
}

std::vector<const ground::PressureSinkage*> WongReeceRear::laws(const RearState& st,
                                                                const ground::PressureSinkage& soil,
                                                                const std::vector<double>& area_m2,
                                                                std::vector<double>& z_max_m) {
  std::vector<const ground::PressureSinkage*> out;
  flow_.clear();
  if (!on_) return out;
  out.assign(cells_, nullptr);
  if (z_max_m.size() != cells_) z_max_m.assign(cells_, 0.0);
  for (int k = 0; k < classes_; ++k) {
    // Behind theta2 the soil keeps the depth the rear region left there: the continuous
    // profile's, not only its rearmost cell's, which lies up to a unit ahead of theta2 and
    // shallower (a rut one unit's slope too high that the tyre behind it presses: an O(h) share
    // of the load on the rut, docs/soil.md section 10).
    for (int i = 0; i < sections_; ++i) {
      const std::size_t a = std::size_t(i) * classes_ + k;
      if (st.behind[a] && !st.rear[a]) z_max_m[a] = std::max(z_max_m[a], st.exit_depth_m[k]);
    }
    const double c = st.flow_m_per_Pa[k];
    if (!(c > 0)) continue;
    // The flowing soil's surface: the surface the front region leaves at theta_m (the memory of
    // the foremost rear cell, the shallowest of the rear's), one level for the whole rear region.
    double surface = 1e300;
    for (int i = 0; i < sections_; ++i) {
      const std::size_t a = std::size_t(i) * classes_ + k;
      if (st.rear[a])
        surface = std::min(surface, z_max_m[a] > 0 ? soil.rebound_depth_m(z_max_m[a]) : 0.0);
    }
    for (int i = 0; i < sections_; ++i) {
      const std::size_t a = std::size_t(i) * classes_ + k;
      if (!st.rear[a]) continue;
      z_max_m[a] = surface;
      const double stress_Pa = std::max(st.target_N[a], 0.0) / area_m2[i];
      flow_.push_back(std::make_unique<FlowStressLaw>(stress_Pa, surface, c));
      out[a] = flow_.back().get();
    }
  }
  return out;
}

RearState WongReeceRear::image(const std::vector<double>& x_m, const std::vector<double>& force_N,
                               const std::vector<double>& depth_m,
                               const std::vector<double>& area_m2,
                               const std::vector<double>& front_x_m) const {
  RearState img;
  prepare(img);
  if (!on_) return img;
  img.force_N = force_N;
  const int K = classes_;
  std::vector<std::pair<double, double>> front;  // (theta, sigma), ascending in theta
  for (int k = 0; k < K; ++k) {
    if (!std::isfinite(front_x_m[k])) continue;
    const double theta1 = angle(front_x_m[k], R0_);
    const double theta_m = wr_.peak_ratio(slip_) * theta1;
    const double theta2 = -wr_.c3 * theta1;
    if (!(theta1 > 0) || !(theta_m > theta2)) continue;
    const double q = (theta1 - theta_m) / (theta_m - theta2);
    // The front's stress: the cells in [theta_m, theta1) under the soil's own law, 0 at entry.
    front.clear();
    double peak_Pa = 0, deepest_m = 0;
    for (int i = 0; i < sections_; ++i) {
      const std::size_t a = std::size_t(i) * K + k;
      deepest_m = std::max(deepest_m, depth_m[a]);
      const double th = angle(x_m[a], R0_);
      if (th < theta_m || th >= theta1) continue;
      front.emplace_back(th, force_N[a] / area_m2[i]);
      peak_Pa = std::max(peak_Pa, front.back().second);
    }
    front.emplace_back(theta1, 0.0);
    std::sort(front.begin(), front.end());
    if (!(peak_Pa > 0) || !(deepest_m > 0)) continue;
    img.flow_m_per_Pa[k] = kFlowScale * deepest_m / peak_Pa;
    // sigma_front at theta, linear between the front's cells (the rearmost's value below it).
    auto sigma_front = [&](double th) {
      const auto hi = std::upper_bound(front.begin(), front.end(), std::make_pair(th, 0.0));
      if (hi == front.begin()) return front.front().second;
      if (hi == front.end()) return front.back().second;
      const auto lo = hi - 1;
      const double t = (th - lo->first) / (hi->first - lo->first);
      return lo->second + t * (hi->second - lo->second);
    };
    // The two rearmost rear cells with a depth (theta ascending with the section index).
    double th_last = 0;
    int found = 0;
    for (int i = 0; i < sections_; ++i) {
      const std::size_t a = std::size_t(i) * K + k;
      const double th = angle(x_m[a], R0_);
      if (th >= theta_m) continue;
      img.behind[a] = 1;
      if (th < theta2) continue;
      img.rear[a] = 1;
      img.target_N[a] = sigma_front(theta1 - (th - theta2) * q) * area_m2[i];
      if (depth_m[a] > 0 && found == 1) {  // the one ahead of the rearmost: the weight
        img.exit_prev[k] = int(a);
        img.exit_weight[k] = th > th_last ? std::min(1.0, (th_last - theta2) / (th - th_last)) : 0;
        ++found;
      }
      if (depth_m[a] > 0 && found == 0) img.exit_last[k] = int(a), th_last = th, ++found;
    }
  }
  return img;
}

void WongReeceRear::fill_track(const RearState& st, const ground::PressureSinkage& soil,
                               const std::vector<double>& prior_m,
                               std::vector<double>& depth_m) const {
  if (!on_) return;
  for (int k = 0; k < classes_; ++k) {
    double ahead = prior_m.empty() ? 0.0 : prior_m[k];
    for (int i = sections_ - 1; i >= 0; --i) {
      const std::size_t a = std::size_t(i) * classes_ + k;
      const double memory =
          st.behind[a] && !st.rear[a] ? std::max(ahead, st.exit_depth_m[k]) : ahead;
      if (st.behind[a] && !(depth_m[a] > 0) && memory > 0)
        depth_m[a] = soil.rebound_depth_m(memory);
      ahead = std::max(ahead, depth_m[a]);
    }
  }
}

void WongReeceRear::pack(const RearState& st, const RearState& img, Eigen::VectorXd& state,
                         Eigen::VectorXd& image, Eigen::Index at) const {
  for (std::size_t a = 0; a < cells_ && on_; ++a) {
    state(at + Eigen::Index(a)) = st.rear[a] ? st.target_N[a] : img.force_N[a];
    image(at + Eigen::Index(a)) = img.rear[a] ? img.target_N[a] : img.force_N[a];
  }
}

void WongReeceRear::unpack(const Eigen::VectorXd& next, Eigen::Index at, RearState img,
                           RearState& st) const {
  if (!on_) return;
  st = std::move(img);
  for (std::size_t a = 0; a < cells_; ++a)
    st.target_N[a] = st.rear[a] ? std::max(next(at + Eigen::Index(a)), 0.0) : 0.0;
}

double WongReeceRear::change(const RearState& st, const RearState& img) const {
  double d = 0;
  for (std::size_t a = 0; a < cells_ && on_; ++a) {
    const double from = st.rear[a] ? st.target_N[a] : img.force_N[a];
    const double to = img.rear[a] ? img.target_N[a] : img.force_N[a];
    d = std::max(d, std::abs(to - from));
  }
  return d;
}

}  // namespace modaltyre::contact::detail

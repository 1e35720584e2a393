#pragma once
// Output samples that repeat the last computed one (internal to the transient library; used by
// the 2D and the 3D drivers).
#include <Eigen/Dense>
#include <cmath>
#include <vector>

namespace modaltyre::transient::detail {

/// Decides whether an output sample can repeat the last computed one: every state component
/// moved by less than kReuseFraction of its error weight (rtol |y| + atol) since then. The
/// samples are otherwise an O(m (nq + nr)) evaluation each, which dominated long settled holds.
class SampleReuse {
 public:
  SampleReuse(double rtol, const std::vector<double>& atol, bool allowed)
      : rtol_(rtol),
        atol_(
            Eigen::Map<const Eigen::ArrayXd>(atol.data(), static_cast<Eigen::Index>(atol.size()))),
        allowed_(allowed) {}
  void remember(const std::vector<double>& y) {
    last_ = Eigen::Map<const Eigen::ArrayXd>(y.data(), static_cast<Eigen::Index>(y.size()));
    bound_.resize(last_.size());
    known_ = 0;
  }
  bool unchanged(const std::vector<double>& y) const {
    const Eigen::Index n = last_.size();
    if (!allowed_ || n != static_cast<Eigen::Index>(y.size())) return false;
    // The bounds are computed as the check reaches them, and kept: a moving state fails at one
    // of its first components, and its bounds' pass at every computed sample (~2000 states on
    // the 3D default) was a pass over the whole state for one comparison. A settled hold
    // (a 120 s hold checks up to 60000 samples of ~800 states) passes them all once, then reads
    // them as before.
    const double *v = y.data(), *l = last_.data();
    Eigen::Index i = 0;
    for (; i < known_; ++i)
      if (!(std::abs(v[i] - l[i]) <= bound_[i])) return false;
    for (; i < n; ++i) {
      bound_[i] = bound(i);
      known_ = i + 1;
      if (!(std::abs(v[i] - l[i]) <= bound_[i])) return false;
    }
    return true;
  }
  bool allowed() const { return allowed_; }
  /// The state of the last remember() (size() entries).
  const double* last_state() const { return last_.data(); }
  /// For a state y that unchanged() accepts and rates bounded by |y'| <= rate (per component):
  /// the time over which the state stays within the bound, min (bound - |y - last|) / rate
  /// (infinite where the rate is zero).
  double slack_s(const std::vector<double>& y, const Eigen::ArrayXd& rate) const {
    // One vectorised pass without a temporary: a zero rate gives +inf (room > 0 for a state
    // that unchanged() accepts); a NaN (never expected) makes the caller check every sample.
    for (; known_ < last_.size(); ++known_) bound_[known_] = bound(known_);
    const Eigen::Map<const Eigen::ArrayXd> v(y.data(), last_.size());
    const double t = ((bound_ - (v - last_).abs()) / rate).minCoeff();
    return t > 0 ? t : 0.0;
  }

 private:
  /// Far below the integrator's own local error (1 in the same weighted norm).
  static constexpr double kReuseFraction = 1e-3;
  double rtol_;
  Eigen::ArrayXd atol_;
  bool allowed_;
  /// kReuseFraction of component i's error weight at the last computed sample.
  double bound(Eigen::Index i) const {
    return kReuseFraction * (rtol_ * std::abs(last_[i]) + atol_[i]);
  }
  Eigen::ArrayXd last_;  ///< the last computed sample's state
  /// bound(i) for i < known_ (unchanged() and slack_s() extend it).
  mutable Eigen::ArrayXd bound_;
  mutable Eigen::Index known_ = 0;
};

}  // namespace modaltyre::transient::detail

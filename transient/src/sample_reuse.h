#pragma once
// Output samples that repeat the last computed one (internal to the transient library; used by
// the 2D and the 3D drivers).
#include <Eigen/Dense>
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
    bound_ = kReuseFraction * (rtol_ * last_.abs() + atol_);
  }
  bool unchanged(const std::vector<double>& y) const {
    if (!allowed_ || last_.size() != static_cast<Eigen::Index>(y.size())) return false;
    // One vectorised pass (a 120 s hold checks up to 60000 samples of ~800 states).
    const Eigen::Map<const Eigen::ArrayXd> v(y.data(), last_.size());
    return ((v - last_).abs() <= bound_).all();
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
  Eigen::ArrayXd last_, bound_;  ///< last computed sample's state, kReuseFraction of its weights
};

}  // namespace modaltyre::transient::detail

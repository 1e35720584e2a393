#pragma once
// Anderson mixing for the steady-rolling fixed points x = G(x) (traction.cc, traction3d.cc),
// internal to the contact library: the next state is the combination of the recent images
// G(x_j) whose residuals G(x_j) - x_j cancel best (least squares over the differences of the last
// `depth` residuals). A residual that does not shrink restarts the history from the plain step.
#include <Eigen/Dense>
#include <vector>

namespace modaltyre::contact::detail {

class AndersonMixer {
 public:
  explicit AndersonMixer(int depth) : depth_(depth) {}
  /// The next state from the current state and its image.
  Eigen::VectorXd next(const Eigen::VectorXd& state, const Eigen::VectorXd& image) {
    const double residual = (image - state).norm();
    if (residual >= last_residual_) xs_.clear(), gs_.clear();
    last_residual_ = residual;
    xs_.push_back(state), gs_.push_back(image);
    if (static_cast<int>(xs_.size()) > depth_ + 1) xs_.erase(xs_.begin()), gs_.erase(gs_.begin());
    Eigen::VectorXd out = image;
    const int k = static_cast<int>(xs_.size()) - 1;
    if (k > 0) {
      const auto n = state.size();
      Eigen::MatrixXd dR(n, k), dG(n, k);
      for (int j = 0; j < k; ++j) {
        dR.col(j) = (gs_[j + 1] - xs_[j + 1]) - (gs_[j] - xs_[j]);
        dG.col(j) = gs_[j + 1] - gs_[j];
      }
      const Eigen::VectorXd gamma = dR.colPivHouseholderQr().solve(gs_[k] - xs_[k]);
      if (gamma.allFinite()) out -= dG * gamma;
    }
    return out;
  }

 private:
  int depth_;
  double last_residual_ = 1e300;
  std::vector<Eigen::VectorXd> xs_, gs_;  ///< recent states and their images, oldest first
};

}  // namespace modaltyre::contact::detail

#pragma once
// Sample statistics shared by the identification reports (rheology) and discover's regime scan.
#include <span>

namespace modaltyre::solvers {

/// Pearson correlation coefficient r = s_xy / sqrt(s_xx s_yy) of the first min(|x|, |y|)
/// pairs; 0 when fewer than two pairs or when either side has no spread.
double pearson_correlation(std::span<const double> x, std::span<const double> y);

}  // namespace modaltyre::solvers

#pragma once
// How a solve, a fit or a prediction ended: the one status vocabulary of the library's results
// (solvers' ContactSolution, RootResult and LeastSquaresResult, and the footprint, 3D patch,
// prediction, calibration and fit results built on them). A result holds a SolveStatus and a
// message of its own (the reason in words, with the figures that matter); callers test the
// result's ok(). The JSON documents keep their "converged": true / false (= ok()).
namespace modaltyre {

enum class SolveStatus {
  converged,       ///< the tolerances were met
  max_iterations,  ///< the iteration limit came first
  singular,        ///< a linear system on the way was singular
  aborted,         ///< the caller's function stopped the search
  failed,          ///< any other failure (not finite, outside the model's window, ...)
};

/// True only for SolveStatus::converged.
constexpr bool ok(SolveStatus status) { return status == SolveStatus::converged; }

/// The status in words, for messages: "converged", "iteration limit reached", ...
const char* to_string(SolveStatus status);

}  // namespace modaltyre

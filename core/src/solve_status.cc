#include "modaltyre/core/solve_status.h"

namespace modaltyre {

const char* to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::converged:
      return "converged";
    case SolveStatus::max_iterations:
      return "iteration limit reached";
    case SolveStatus::singular:
      return "singular system";
    case SolveStatus::aborted:
      return "aborted";
    case SolveStatus::failed:
      return "failed";
  }
  return "unknown";
}

}  // namespace modaltyre

#pragma once
// The 2D patch's result from a contact solution (contour, units, edges), shared by solve_patch()
// on the flat rigid road and solve_ground_patch() on another ground (ground_patch.h).
#include <span>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/solvers/unilateral_contact.h"

namespace modaltyre::contact::detail {

/// `extra_diagonal`: compliance in series with the tyre per unit (a soil's tangent) that the
/// edges' level function adds to C_ii (empty: none).
FootprintResult patch_result(const TyreModel& model, const PatchOperator& op, const LoadCase& load,
                             const solvers::ContactSolution& s,
                             std::span<const double> extra_diagonal);

}  // namespace modaltyre::contact::detail

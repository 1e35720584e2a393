#pragma once
// The .tir text of the longitudinal laws (slip_fit.h): the header's comments, the [MODEL] and
// [VERTICAL] keys they add, and their sections, in MF-Tool's order (after [CONTACT_PATCH]):
// [VERTICAL_FORCE_RANGE], [LONG_SLIP_RANGE], [SCALING_COEFFICIENTS] (every MF 6.2 factor 1),
// [LONGITUDINAL_COEFFICIENTS] (pure slip), [ROLLING_COEFFICIENTS].
#include <ostream>

#include "modaltyre/tir/slip_fit.h"

namespace modaltyre::tir {

/// Header comments: what was run, the residuals, what is left out and how to merge.
void write_slip_comments(std::ostream& s, const TirSlipFit& f);
/// [MODEL]: TYRESIDE, LONGVL, VXLOW.
void write_slip_model_keys(std::ostream& s, const TirSlipFit& f);
/// [VERTICAL]: Q_RE0, BREFF, DREFF, FREFF.
void write_slip_vertical_keys(std::ostream& s, const TirSlipFit& f);
/// The sections after [CONTACT_PATCH].
void write_slip_sections(std::ostream& s, const TirSlipFit& f);

}  // namespace modaltyre::tir

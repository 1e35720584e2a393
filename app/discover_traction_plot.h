#pragma once
// discover --plot on traction rows: measured and predicted drawbar pull / load and soil sinkage
// against slip, per load (and speed and pass), the baseline's prediction and the named
// effects'.
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/discover/discover.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::app {

/// Appends the two traction panels to `figure` (nothing when the data have no traction rows).
/// The predictions are the in-sample fits' at the measured slips: measured + residual x scale
/// (discover/traction_evidence.h), so a row draws the observables it measured.
void add_traction_panels(PlotFigure& figure, const discover::DiscoverReport& report,
                         const studies::MeasurementSet& data, double outer_radius_m);

}  // namespace modaltyre::app

#pragma once
// The 3D patch's outputs of `footprint` (contact/patch3d.h): the pressure map in CSV and the
// footprint image (the map printed like a pressure-sensitive film,
// with its contour, beside the centre-line pressure).
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"

namespace modaltyre::app {

/// load_N,x_mm,y_mm,pressure_kPa: one line per cell of each case's map, written atomically.
void write_map_csv(const std::vector<contact::Prediction>& cases, const std::string& path);

/// The footprint image of each case (map, contour) and a last panel with the centre-line
/// pressure of every case (.svg or .png).
void plot_footprint_maps(const std::vector<contact::Prediction>& cases,
                         const contact::TyreConfig& config, const std::string& path);

}  // namespace modaltyre::app

#pragma once
// The 3D patch's outputs of `footprint` (contact/patch3d.h): the pressure map in CSV and the
// footprint image (the map printed like a pressure-sensitive film,
// with its contour, beside the centre-line pressure).
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::app {

/// The 95 % band of every map cell, per case in the map's order (row by row across y, x along
/// each row): footprint --uncertainty with --map-csv (issue 35).
struct MapBands {
  std::vector<std::vector<uncertainty::Band>> cells;  ///< [case][j * nx + i]
};

/// The map cells of each nominal case as extra outputs of the footprint's propagation.
uncertainty::ExtraOutputs map_cell_outputs(const std::vector<contact::Prediction>& nominal);

/// Moves the map cells' bands out of `r` (after output_names() in each case), leaving the
/// footprint's bands.
MapBands take_map_bands(uncertainty::PropagationResult& r);

/// load_N,x_mm,y_mm,pressure_kPa: one line per cell of each case's map, written atomically;
/// with bands, two more columns pressure_p025_kPa,pressure_p975_kPa (the band as two maps).
void write_map_csv(const std::vector<contact::Prediction>& cases, const std::string& path,
                   const MapBands* bands = nullptr);

/// The footprint image of each case (map, contour) and a last panel with the centre-line
/// pressure of every case (.svg or .png).
void plot_footprint_maps(const std::vector<contact::Prediction>& cases,
                         const contact::TyreConfig& config, const std::string& path);

}  // namespace modaltyre::app

#pragma once
// Measures of a predicted footprint beyond sinking, length and width: the contact area, the
// peak and the mean contact pressure, as `footprint` prints them (2D: the units; 3D: the map).
#include "modaltyre/contact/predictor.h"

namespace modaltyre::contact {

/// Road area of the cells in contact [m^2]: sum of dx dy over the cells that carry force (the
/// `contact_area_mm2` printed per case). Not contact_area_m2 (pneumatic_share.h), which
/// interpolates each column's run edges on the level function so that the pneumatic share's
/// area is continuous in the load.
double cell_area_in_contact_m2(const Patch3dResult& r);

/// The highest pressure [Pa]: of the units on the 2D patch, of the whole map on the 3D patch.
double peak_pressure_Pa(const Prediction& p);

/// Load over the contact area [Pa]: the 3D map's cells in contact, or length x width in 2D.
double mean_pressure_Pa(const Prediction& p);

/// The same over the 3D contact area interpolated on the level function (contact_area_m2 of
/// pneumatic_share.h), continuous in the inputs where the cell count steps; 2D as above.
double smooth_mean_pressure_Pa(const Prediction& p);

}  // namespace modaltyre::contact

#pragma once
// The tread's transverse profile before loading: the drop z(y) >= 0 of the outer surface below
// the crown line at lateral position y (y = 0 on the centre plane, the profile symmetric in y),
// for the 3D contact patch (patch3d.h).
//
// Shapes:
//   flat      z = 0 (the 2D model's patch, every cell of a section at the same height)
//   circular  a crown arc of radius R1, z = R1 - sqrt(R1^2 - y^2); optionally followed, from
//             |y| = y1 on, by a tangent shoulder arc of radius R2 < R1 (tread profiles are made
//             of such arcs: flat in the centre, rounder towards the shoulder)
//   power     z = (y_r^2 / 2 R1) (|y| / y_r)^n: the parabola of radius R1 at the reference
//             half-width y_r, with the exponent n > 1 setting how the drop is shared between
//             centre and shoulder (n = 2: the circular crown's parabola, y^2 / 2 R1; n > 2 flatter
//             in the centre and steeper at the shoulder, n < 2 the reverse). The lateral edge of
//             a section pressed in by d is y_r (2 R1 d / y_r^2)^(1/n).
//   contour   a measured contour: |y| and z tabulated, linear between the points
#include <string>
#include <vector>

#include "modaltyre/core/config_tree.h"

namespace modaltyre::contact {

enum class CrownShape { flat, circular, power, contour };

struct CrownProfile {
  CrownShape shape = CrownShape::circular;
  double radius_m = 0.8;               ///< R1, crown arc radius (circular, power), > 0
  double exponent = 2;                 ///< n of the power crown, > 1
  double reference_half_width_m = 0;   ///< y_r of the power crown, > 0
  double shoulder_radius_m = 0;        ///< R2 of the shoulder arc, 0 = none, else < R1
  double shoulder_start_m = 0;         ///< y1, where the shoulder arc begins, < R1
  std::vector<double> contour_y_m;     ///< |y|, strictly increasing from 0 (contour)
  std::vector<double> contour_drop_m;  ///< z at those points, from 0, strictly increasing
  /// flat: a crown taken flat for want of a section drawing is an assumption; the bands span
  /// crowns from flat to the circular crown of this radius (uniform in the curvature,
  /// docs/uncertainty.md section 2). 0 = the flat crown is certain.
  double round_limit_radius_m = 0;

  /// z(y) [m] for any y (symmetric). Beyond the last contour point or where a shoulder arc
  /// turns vertical the drop keeps the last slope (the tread-width limit of patch3d.h cuts the
  /// cells before that matters).
  double drop_m(double y_m) const;
  /// The largest |y| with z(|y|) <= d: the lateral edge of a section pressed in by d [m].
  double half_width_m(double d_m) const;
  /// |y| where a circular profile turns vertical (crown or shoulder arc); infinity otherwise.
  double reach_m() const;
  /// Throws std::invalid_argument naming what is inconsistent.
  void validate() const;
};

/// Reads the `crown:` section: shape (flat, circular, power, contour), radius_mm,
/// shoulder_radius_mm, shoulder_start_mm, exponent, reference_half_width_mm, contour_y_mm,
/// contour_drop_mm. Errors name file, line and key.
CrownProfile read_crown_profile(const ConfigSection& section);

}  // namespace modaltyre::contact

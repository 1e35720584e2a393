#pragma once
// The test geometry a UFF file may carry beside its FRFs (issue 38): nodes (dataset 15, single
// precision, or 2411, double) and coordinate systems (dataset 2420). With it, a DOF's direction
// is read as modal software writes it - direction 1, 2, 3 of the node's displacement coordinate
// system (x, y, z of a Cartesian system; r, theta, z of a cylindrical one) - and turned into the
// tyre's radial or tangential direction at that node; the node's angle around the tyre comes from
// its position. Without geometry the reader keeps the implied convention (docs/ema.md: +-3
// radial, +-1 tangential in each point's local frame, points equally spaced in number order).
//
// Conventions (docs/ema.md, "Geometry"):
//  - Dataset 2420, records 5-7: row i holds the global components of the system's i-th axis
//    (for a cylindrical system: axis 1 the direction of theta = 0, axis 3 the cylinder's axis);
//    record 8 its origin. System 0 is the global Cartesian system. Spherical systems are refused.
//  - Node coordinates are in the node's definition system (dataset 15/2411 field 2): x, y, z, or
//    r, theta [deg], z.
//  - The tyre: the plane and circle fitted to the measured nodes (least squares); its axis is
//    oriented so that angles grow with the node numbers (Newell's normal of the polygon in number
//    order), angle 0 at the lowest-numbered node; radial outward, tangential towards growing angle.
//  - A DOF is radial (tangential) when its direction is within kMaxDirectionDeviationDeg of the
//    radial (tangential) direction at the node, with the sign of their scalar product; any other
//    DOF (axial, oblique) is refused naming the node, the direction and the angles.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre::ema {

/// A transducer or hammer aligned by hand is within a few degrees of its intended direction;
/// 10 degrees (cos = 0.985) separates that from a DOF meant along another axis.
inline constexpr double kMaxDirectionDeviationDeg = 10.0;

struct UffNode {
  long label = 0;
  long definition_cs = 0, displacement_cs = 0;
  std::array<double, 3> coordinates{};  ///< in the definition system
  int line = 0;
};

struct UffCoordinateSystem {
  long label = 0;
  int type = 0;                                 ///< 0 Cartesian, 1 cylindrical
  std::array<std::array<double, 3>, 3> axes{};  ///< axis i in global components (unit length)
  std::array<double, 3> origin{};
  int line = 0;
};

struct UffGeometry {
  std::map<long, UffNode> nodes;
  std::map<long, UffCoordinateSystem> systems;
  int first_line = 0;  ///< line of the first geometry dataset (for messages)
};

/// The lines of one dataset (between its number line and the closing "-1"), with the file line
/// of the first; `path` for messages.
struct UffDatasetLines {
  std::string path;
  int first_line = 0;
  std::vector<std::string> lines;
};

/// Dataset 15 (4I10, 1P3E13.5 per node) or 2411 (4I10 / 1P3D25.16): adds the nodes; a node
/// given twice is an InputError naming both lines.
void read_uff_nodes(const UffDatasetLines& d, bool double_precision, UffGeometry& g);

/// Dataset 2420: adds the coordinate systems.
void read_uff_coordinate_systems(const UffDatasetLines& d, UffGeometry& g);

/// A DOF as the file states it: node and signed direction 1 ... 3 (with the line and field of
/// the record that states it, for messages).
struct RawDof {
  long node = 0;
  long direction = 0;
  int line = 0;
  std::string node_field, direction_field;
};

/// What the geometry makes of the DOFs of an FRF set: each raw DOF as a tyre DOF and a sign,
/// and the angle of every measured node.
struct MappedDofs {
  std::vector<Dof> dofs;
  std::vector<int> signs;
  std::map<int, double> angle_deg;
};

/// Maps every raw DOF through the geometry (see the conventions above). InputError (naming the
/// file, the record's line and field) for a node without coordinates, an unknown or spherical
/// coordinate system, fewer than three nodes, nodes on a line, or a DOF that is neither radial
/// nor tangential.
MappedDofs map_dofs(const std::string& path, const UffGeometry& g, const std::vector<RawDof>& raw);

}  // namespace modaltyre::ema

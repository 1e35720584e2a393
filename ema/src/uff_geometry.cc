// Test geometry of a UFF file: nodes, coordinate systems, the tyre's frame (uff_geometry.h).
#include "modaltyre/ema/uff_geometry.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::ema {
namespace {

using Vec = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMaxNodes = 100000;  // a tyre test has tens of nodes; a car body thousands

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

std::optional<double> real(std::string t) {
  for (char& c : t) {
    if (c == 'D' || c == 'd') c = 'E';
  }
  return parse_finite_double(t);
}

std::optional<long> whole(const std::string& t) {
  const auto v = parse_finite_double(t);
  if (!v || *v != std::floor(*v) || std::abs(*v) > 1e9) return std::nullopt;
  return static_cast<long>(*v);
}

[[noreturn]] void fail(const UffDatasetLines& d, std::size_t i, const std::string& field,
                       const std::string& message) {
  throw InputError({d.path, d.first_line + static_cast<int>(i), field}, message);
}

// Fixed columns first (Format 4I10), then blank-separated fields.
std::array<long, 4> node_record(const UffDatasetLines& d, std::size_t i, int dataset) {
  const std::string& s = d.lines[i];
  std::array<long, 4> v{};
  auto t = words(s);
  if (t.size() < 4) {
    fail(d, i, "dataset " + std::to_string(dataset) + " record 1",
         "expected node label, definition and displacement coordinate systems and colour");
  }
  for (int k = 0; k < 4; ++k) {
    const auto x = whole(t[k]);
    if (!x) {
      fail(d, i, "dataset " + std::to_string(dataset) + " record 1 field " + std::to_string(k + 1),
           "'" + printable(t[k]) + "' is not a whole number");
    }
    v[k] = *x;
  }
  return v;
}

std::array<double, 3> reals3(const UffDatasetLines& d, std::size_t i, const std::string& field,
                             const std::vector<std::string>& t) {
  std::array<double, 3> out{};
  if (t.size() != 3) fail(d, i, field, "expected three numbers");
  for (int k = 0; k < 3; ++k) {
    const auto x = real(t[k]);
    if (!x || std::abs(*x) > 1e12) fail(d, i, field, "'" + printable(t[k]) + "' is not a number");
    out[k] = *x;
  }
  return out;
}

void add_node(const UffDatasetLines& d, std::size_t i, UffNode n, UffGeometry& g) {
  if (n.label < 1 || n.label > kMaxPointNumber) {
    fail(d, i, "node label",
         std::to_string(n.label) + " is not a node number from 1 to " +
             std::to_string(kMaxPointNumber));
  }
  if (const auto it = g.nodes.find(n.label); it != g.nodes.end()) {
    fail(d, i, "node label",
         "node " + std::to_string(n.label) + " given twice (first on line " +
             std::to_string(it->second.line) + ")");
  }
  if (g.nodes.size() >= kMaxNodes) fail(d, i, "", "more than 100000 nodes; refusing");
  if (g.first_line == 0) g.first_line = d.first_line;
  g.nodes[n.label] = n;
}

Vec vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

const UffCoordinateSystem* system_of(const UffGeometry& g, long label) {
  static const UffCoordinateSystem global{0, 0, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {}, 0};
  if (label == 0) return &global;
  const auto it = g.systems.find(label);
  return it == g.systems.end() ? nullptr : &it->second;
}

Vec axis(const UffCoordinateSystem& cs, int i) { return vec(cs.axes[i]); }

}  // namespace

void read_uff_nodes(const UffDatasetLines& d, bool double_precision, UffGeometry& g) {
  const int dataset = double_precision ? 2411 : 15;
  if (!double_precision) {
    for (std::size_t i = 0; i < d.lines.size(); ++i) {
      const auto t = words(d.lines[i]);
      if (t.empty()) continue;
      if (t.size() != 7) {
        fail(d, i, "dataset 15",
             "expected node label, definition and displacement coordinate systems, colour and "
             "three coordinates (Format 4I10,1P3E13.5)");
      }
      const auto r = node_record(d, i, dataset);
      UffNode n{r[0], r[1], r[2], {}, d.first_line + static_cast<int>(i)};
      n.coordinates = reals3(d, i, "dataset 15 fields 5-7 (coordinates)", {t[4], t[5], t[6]});
      add_node(d, i, n, g);
    }
    return;
  }
  std::size_t i = 0;
  while (i < d.lines.size()) {
    if (words(d.lines[i]).empty()) {
      ++i;
      continue;
    }
    const auto r = node_record(d, i, dataset);
    UffNode n{r[0], r[1], r[2], {}, d.first_line + static_cast<int>(i)};
    if (i + 1 >= d.lines.size()) fail(d, i, "dataset 2411 record 2", "missing coordinates");
    n.coordinates = reals3(d, i + 1, "dataset 2411 record 2 (coordinates)", words(d.lines[i + 1]));
    add_node(d, i, n, g);
    i += 2;
  }
}

void read_uff_coordinate_systems(const UffDatasetLines& d, UffGeometry& g) {
  // Records 1-2 (part UID, part name), then records 3-8 per system.
  if (d.lines.size() < 2) fail(d, 0, "dataset 2420 record 1", "missing part UID and name");
  std::size_t i = 2;
  while (i < d.lines.size()) {
    if (words(d.lines[i]).empty()) {
      ++i;
      continue;
    }
    const auto t = words(d.lines[i]);
    const auto label = t.size() >= 2 ? whole(t[0]) : std::nullopt;
    const auto type = t.size() >= 2 ? whole(t[1]) : std::nullopt;
    if (!label || !type) {
      fail(d, i, "dataset 2420 record 3", "expected coordinate system label, type and colour");
    }
    if (*type != 0 && *type != 1) {
      fail(d, i, "dataset 2420 record 3 field 2 (coordinate system type)",
           *type == 2 ? "a spherical system is not read (Cartesian 0 or cylindrical 1)"
                      : "must be 0 (Cartesian) or 1 (cylindrical)");
    }
    if (i + 5 >= d.lines.size()) fail(d, i, "dataset 2420", "records 4-8 missing");
    UffCoordinateSystem cs{*label, static_cast<int>(*type), {}, {}, d.first_line + int(i)};
    for (int r = 0; r < 3; ++r) {
      const std::size_t at = i + 2 + static_cast<std::size_t>(r);
      const auto row = reals3(d, at,
                              "dataset 2420 record " + std::to_string(5 + r) +
                                  " (transformation matrix row " + std::to_string(r + 1) + ")",
                              words(d.lines[at]));
      const double norm = vec(row).norm();
      if (!(std::abs(norm - 1) < 1e-3)) {
        fail(d, at, "dataset 2420 record " + std::to_string(5 + r),
             "axis " + std::to_string(r + 1) + " is not a unit vector (length " +
                 std::to_string(norm) + ")");
      }
      cs.axes[r] = row;
    }
    cs.origin = reals3(d, i + 5, "dataset 2420 record 8 (origin)", words(d.lines[i + 5]));
    if (cs.label <= 0) fail(d, i, "dataset 2420 record 3 field 1", "label must be positive");
    if (g.systems.count(cs.label)) {
      fail(d, i, "dataset 2420 record 3 field 1",
           "coordinate system " + std::to_string(cs.label) + " given twice");
    }
    if (g.first_line == 0) g.first_line = d.first_line;
    g.systems[cs.label] = cs;
    i += 6;
  }
}

MappedDofs map_dofs(const std::string& path, const UffGeometry& g, const std::vector<RawDof>& raw) {
  const auto refuse = [&](const RawDof& r, bool direction, const std::string& message) {
    throw InputError({path, r.line, direction ? r.direction_field : r.node_field}, message);
  };
  // Global positions of the measured nodes, in number order.
  std::map<long, Vec> position;
  std::map<long, const RawDof*> first_use;
  for (const auto& r : raw) {
    if (position.count(r.node)) continue;
    const auto it = g.nodes.find(r.node);
    if (it == g.nodes.end()) {
      refuse(r, false,
             "node " + std::to_string(r.node) +
                 " has no coordinates, but the file carries a geometry (datasets 15/2411 from "
                 "line " +
                 std::to_string(g.first_line) + "): every measured node needs them");
    }
    const UffNode& n = it->second;
    const UffCoordinateSystem* cs = system_of(g, n.definition_cs);
    if (!cs) {
      throw InputError({path, n.line, "definition coordinate system"},
                       "node " + std::to_string(n.label) + " is defined in coordinate system " +
                           std::to_string(n.definition_cs) + ", which no dataset 2420 gives");
    }
    const auto& c = n.coordinates;
    Vec local = cs->type == 1 ? Vec(c[0] * std::cos(c[1] * kPi / 180),
                                    c[0] * std::sin(c[1] * kPi / 180), c[2])
                              : vec(c);
    position[r.node] = vec(cs->origin) + local(0) * axis(*cs, 0) + local(1) * axis(*cs, 1) +
                       local(2) * axis(*cs, 2);
    first_use[r.node] = &r;
  }
  const RawDof& any = raw.front();
  if (position.size() < 3) {
    refuse(any, false,
           "the geometry gives " + std::to_string(position.size()) +
               " measured node(s); the tyre's circle needs at least three");
  }
  // The tyre's plane: Newell's normal of the polygon in node-number order (oriented so that
  // angles grow with the numbers), through the centroid.
  Vec centroid = Vec::Zero();
  for (const auto& [label, p] : position) centroid += p;
  centroid /= double(position.size());
  std::vector<Vec> p;
  for (const auto& [label, q] : position) p.push_back(q - centroid);
  Vec normal = Vec::Zero();
  double size = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    normal += p[i].cross(p[(i + 1) % p.size()]);
    size = std::max(size, p[i].norm());
  }
  if (!(normal.norm() > 1e-6 * size * size)) {
    refuse(any, false, "the measured nodes lie on a line: they are not points around a tyre");
  }
  normal.normalize();
  const Vec u = (p.front() - p.front().dot(normal) * normal).normalized();
  const Vec v = normal.cross(u);
  // Circle through the projected nodes (algebraic least squares): x^2 + y^2 + D x + E y + F = 0.
  Eigen::MatrixXd a(p.size(), 3);
  Eigen::VectorXd b(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p[i].dot(u), y = p[i].dot(v);
    a.row(static_cast<Eigen::Index>(i)) << x, y, 1;
    b(static_cast<Eigen::Index>(i)) = -(x * x + y * y);
  }
  const Eigen::Vector3d def = a.colPivHouseholderQr().solve(b);
  const Vec centre = centroid - 0.5 * def(0) * u - 0.5 * def(1) * v;

  MappedDofs out;
  std::map<long, std::pair<Vec, Vec>> frame;  // node -> (radial, tangential)
  for (const auto& [label, q] : position) {
    Vec r = q - centre;
    r -= r.dot(normal) * normal;
    if (!(r.norm() > 1e-6 * size)) {
      refuse(*first_use[label], false,
             "node " + std::to_string(label) + " is at the fitted tyre centre");
    }
    r.normalize();
    frame[label] = {r, normal.cross(r)};
  }
  const Vec r0 = frame.begin()->second.first, t0 = frame.begin()->second.second;
  for (const auto& [label, f] : frame) {
    double angle = std::atan2(f.first.dot(t0), f.first.dot(r0)) * 180 / kPi;
    if (angle < 0) angle += 360;
    if (angle >= 360) angle -= 360;
    out.angle_deg[static_cast<int>(label)] = angle;
  }
  const double cos_max = std::cos(kMaxDirectionDeviationDeg * kPi / 180);
  for (const auto& r : raw) {
    const long d = std::abs(r.direction);
    if (d < 1 || d > 3) {
      refuse(r, true,
             "direction " + std::to_string(r.direction) +
                 " is not a translation (1, 2, 3 of the node's displacement system)");
    }
    const UffNode& n = g.nodes.at(r.node);
    const UffCoordinateSystem* cs = system_of(g, n.displacement_cs);
    if (!cs) {
      throw InputError({path, n.line, "displacement coordinate system"},
                       "node " + std::to_string(n.label) + " moves in coordinate system " +
                           std::to_string(n.displacement_cs) + ", which no dataset 2420 gives");
    }
    Vec dir = axis(*cs, static_cast<int>(d) - 1);
    if (cs->type == 1 && d < 3) {  // r or theta at the node
      const Vec q = position.at(r.node) - vec(cs->origin);
      const double phi = std::atan2(q.dot(axis(*cs, 1)), q.dot(axis(*cs, 0)));
      const Vec er = std::cos(phi) * axis(*cs, 0) + std::sin(phi) * axis(*cs, 1);
      const Vec et = -std::sin(phi) * axis(*cs, 0) + std::cos(phi) * axis(*cs, 1);
      dir = d == 1 ? er : et;
    }
    if (r.direction < 0) dir = -dir;
    const auto& [radial, tangential] = frame.at(r.node);
    const double ar = dir.dot(radial), at = dir.dot(tangential);
    if (std::abs(ar) >= cos_max) {
      out.dofs.push_back({static_cast<int>(r.node), Direction::radial});
      out.signs.push_back(ar > 0 ? 1 : -1);
    } else if (std::abs(at) >= cos_max) {
      out.dofs.push_back({static_cast<int>(r.node), Direction::tangential});
      out.signs.push_back(at > 0 ? 1 : -1);
    } else {
      const auto deg = [](double c) {
        return std::to_string(
            std::lround(std::acos(std::clamp(std::abs(c), 0.0, 1.0)) * 180 / kPi));
      };
      refuse(r, true,
             "node " + std::to_string(r.node) + " direction " + std::to_string(r.direction) +
                 " is " + deg(ar) + " deg from the tyre's radial and " + deg(at) +
                 " deg from its tangential direction there (more than " +
                 std::to_string(static_cast<int>(kMaxDirectionDeviationDeg)) +
                 "): ema reads radial and tangential DOFs only");
    }
  }
  return out;
}

}  // namespace modaltyre::ema

// surfaces: generated membrane meshes. Each surface maps the unit square of parameters (s, t) onto
//   rectangle  corner + s side1 + t side2
//   cylinder   centre + (R cos theta, R sin theta, t length), theta from angles[0] to angles[1]
//   disc       centre + (s R cos theta, s R sin theta, 0), theta likewise (triangles only)
//   meridian   from + s (to - from), a meridian in the x-z plane swept about the z axis
//              (axisymmetric membrane elements; its nodes' y dofs are fixed)
// divided into divisions[0] x divisions[1] cells of Q4/Q8/Q12 quads or pairs of T3/T6/T10
// triangles. A generated node that lands on an existing node (of nodes:, lines: or an earlier
// surface, or of the same surface, as at the centre of a disc or the seam of a closed cylinder)
// becomes that node. Cables can be laid along cell boundaries (hoop rings of a tube).
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <unordered_map>

#include "apps/case/case_builder.hpp"
#include "libstruct/element/axisymmetric_membrane.hpp"
#include "libstruct/shape/quad_shape.hpp"
#include "libstruct/shape/triangle_shape.hpp"

namespace flexmoor::app {
namespace {

enum class Shape { Rectangle, Cylinder, Disc, Meridian };

// Parameter directions of each shape, for `cables: along:` and the error messages.
std::array<const char*, 2> directionNames(Shape shape) {
  switch (shape) {
    case Shape::Rectangle: return {"side1", "side2"};
    case Shape::Cylinder: return {"around", "along"};
    case Shape::Disc: return {"radial", "around"};
    case Shape::Meridian: return {"around", "around"};  // hoop cables at the meridian's nodes
  }
  return {"", ""};
}

struct ElementKind {
  bool triangle;
  int nodes;
  int order;  // nodes per cell edge - 1
};

const std::vector<std::pair<std::string, ElementKind>>& elementKinds() {
  static const std::vector<std::pair<std::string, ElementKind>> kinds = {
      {"Q4", {false, 4, 1}}, {"Q8", {false, 8, 2}},  {"Q12", {false, 12, 3}},
      {"T3", {true, 3, 1}},  {"T6", {true, 6, 2}},   {"T10", {true, 10, 3}}};
  return kinds;
}

// Natural coordinates of the nodes of an element kind.
std::vector<Eigen::Vector2d> naturalNodes(const ElementKind& k) {
  std::vector<Eigen::Vector2d> nodes;
  for (int i = 0; i < k.nodes; ++i) {
    if (k.triangle)
      nodes.push_back(k.nodes == 3   ? shape::TriangleShape<3>::node(i)
                      : k.nodes == 6 ? shape::TriangleShape<6>::node(i)
                                     : shape::TriangleShape<10>::node(i));
    else
      nodes.push_back(k.nodes == 4   ? shape::QuadShape<4>::node(i)
                      : k.nodes == 8 ? shape::QuadShape<8>::node(i)
                                     : shape::QuadShape<12>::node(i));
  }
  return nodes;
}

// The geometry of one surface: parameters (s, t) in [0, 1]^2 to a point.
struct SurfaceMap {
  Shape shape = Shape::Rectangle;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), side1 = Eigen::Vector3d::Zero(),
                  side2 = Eigen::Vector3d::Zero();
  double radius = 0.0, length = 0.0, theta0 = 0.0, theta1 = 2.0 * M_PI;

  Eigen::Vector3d operator()(double s, double t) const {
    switch (shape) {
      case Shape::Rectangle:
      case Shape::Meridian: return origin + s * side1 + t * side2;
      case Shape::Cylinder: {
        const double theta = theta0 + s * (theta1 - theta0);
        return origin + Eigen::Vector3d(radius * std::cos(theta), radius * std::sin(theta), t * length);
      }
      case Shape::Disc: {
        const double theta = theta0 + t * (theta1 - theta0);
        return origin + Eigen::Vector3d(s * radius * std::cos(theta), s * radius * std::sin(theta), 0.0);
      }
    }
    return origin;
  }
  double size() const { return std::max({side1.norm(), side2.norm(), radius, length}); }
};

// Finds the node at a position, within a tolerance, over a uniform grid of cells.
class NodeIndex {
 public:
  NodeIndex(const model::Model& m, double tolerance) : tolerance_(tolerance) {
    for (int node = 0; node < m.nodeCount(); ++node) add(m.reference().col(node), node);
  }
  int find(const Eigen::Vector3d& x) const {
    const Key k = key(x);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto cell = cells_.find(hash({k[0] + dx, k[1] + dy, k[2] + dz}));
          if (cell == cells_.end()) continue;
          for (const auto& [position, node] : cell->second)
            if ((position - x).norm() <= tolerance_) return node;
        }
    return -1;
  }
  void add(const Eigen::Vector3d& x, int node) { cells_[hash(key(x))].push_back({x, node}); }

 private:
  using Key = std::array<long long, 3>;
  Key key(const Eigen::Vector3d& x) const {
    return {std::llround(x(0) / (4 * tolerance_)), std::llround(x(1) / (4 * tolerance_)),
            std::llround(x(2) / (4 * tolerance_))};
  }
  static size_t hash(const Key& k) {
    return std::hash<long long>()(k[0]) ^ (std::hash<long long>()(k[1]) * 0x9E3779B97F4A7C15ULL) ^
           (std::hash<long long>()(k[2]) * 0xC2B2AE3D27D4EB4FULL);
  }
  double tolerance_;
  std::unordered_map<size_t, std::vector<std::pair<Eigen::Vector3d, int>>> cells_;
};

// The nodes of one surface, by lattice point: parameters in units of 1/6 of a cell, so that the
// nodes of every element order (thirds and halves of a cell edge) fall on whole numbers.
class SurfaceNodeMaker {
 public:
  static constexpr int kLattice = 6;
  SurfaceNodeMaker(CaseBuilder& b, const SurfaceMap& map, std::array<int, 2> divisions, int line)
      : b_(b), map_(map), divisions_(divisions), line_(line),
        index_(b.model, 1e-9 * std::max(map.size(), 1e-300)) {}

  // The node at lattice point (u, v), made on first use.
  int node(int u, int v) {
    const long long key = static_cast<long long>(u) * (kLattice * 100000LL + 1) + v;
    if (const auto found = lattice_.find(key); found != lattice_.end()) return found->second;
    const Eigen::Vector3d x = map_(static_cast<double>(u) / (kLattice * divisions_[0]),
                                   static_cast<double>(v) / (kLattice * divisions_[1]));
    int n = index_.find(x);
    if (n < 0) {
      n = b_.addGeneratedNode(x, line_);
      index_.add(x, n);
    }
    lattice_[key] = n;
    if (std::find(nodes_.begin(), nodes_.end(), n) == nodes_.end()) nodes_.push_back(n);
    return n;
  }
  const std::vector<int>& nodes() const { return nodes_; }

 private:
  CaseBuilder& b_;
  const SurfaceMap& map_;
  std::array<int, 2> divisions_;
  int line_;
  NodeIndex index_;
  std::unordered_map<long long, int> lattice_;
  std::vector<int> nodes_;
};

// Cell (i, j) split into two triangles: the corners of each, counter-clockwise in (s, t).
using Corners = std::array<Eigen::Vector2i, 3>;
std::array<Corners, 2> splitCell(int i, int j, bool forward) {
  const Eigen::Vector2i p00(i, j), p10(i + 1, j), p11(i + 1, j + 1), p01(i, j + 1);
  if (forward) return {Corners{p00, p10, p11}, Corners{p00, p11, p01}};
  return {Corners{p00, p10, p01}, Corners{p10, p11, p01}};
}

// Which way the diagonal of cell (i, j) runs: one way everywhere, or towards the centre of the
// surface (the symmetric "union jack" pattern of Example 7).
bool forwardDiagonal(const std::string& pattern, int i, int j, std::array<int, 2> n) {
  if (pattern == "forward") return true;
  if (pattern == "backward") return false;
  return (2 * i + 1 < n[0]) == (2 * j + 1 < n[1]);
}

struct SurfaceSpec {
  std::string name;
  SurfaceMap map;
  ElementKind kind{false, 4, 1};
  std::array<int, 2> divisions{1, 1};
  std::string diagonals = "forward";
  const SectionSpec* section = nullptr;
};

std::optional<std::array<int, 2>> readDivisions(CaseBuilder& b, const YAML::Node& n,
                                                const std::string& path) {
  if (!n.IsSequence() || n.size() != 2) {
    b.diag.error(n, path + ": expected [n1, n2], the cells along each direction (got " +
                        describeNode(n) + ")");
    return std::nullopt;
  }
  const auto n1 = b.in.integer(n[0], itemPath(path, 0), 1, 100000);
  const auto n2 = b.in.integer(n[1], itemPath(path, 1), 1, 100000);
  if (!n1 || !n2) return std::nullopt;
  return std::array<int, 2>{*n1, *n2};
}

// angles: [from, to] of a cylinder or disc (plain numbers are radians; `90 deg` works).
bool readAngles(CaseBuilder& b, Fields& f, SurfaceMap& m) {
  const YAML::Node* n = f.find("angles");
  if (!n) return true;
  if (!n->IsSequence() || n->size() != 2) {
    b.diag.error(*n, f.path("angles") + ": expected [from, to] (got " + describeNode(*n) + ")");
    return false;
  }
  const auto a0 = b.in.quantity((*n)[0], itemPath(f.path("angles"), 0), kind::kNumber);
  const auto a1 = b.in.quantity((*n)[1], itemPath(f.path("angles"), 1), kind::kNumber);
  if (!a0 || !a1) return false;
  if (!(std::abs(*a1 - *a0) > 0.0) || std::abs(*a1 - *a0) > 2.0 * M_PI + 1e-12) {
    b.diag.error(*n, f.path("angles") + ": expected two different angles at most a full turn apart");
    return false;
  }
  m.theta0 = *a0;
  m.theta1 = *a1;
  return true;
}

// The geometric keys of each shape.
const std::vector<std::string>& keysOf(Shape shape) {
  static const std::vector<std::string> common = {"name", "shape", "element", "section",
                                                  "divisions", "diagonals", "cables"};
  static const auto with = [](std::vector<std::string> more) {
    more.insert(more.begin(), common.begin(), common.end());
    return more;
  };
  static const std::vector<std::string> rectangle = with({"corner", "side1", "side2"});
  static const std::vector<std::string> cylinder = with({"centre", "radius", "length", "angles"});
  static const std::vector<std::string> disc = with({"centre", "radius", "angles"});
  static const std::vector<std::string> meridian = {"name", "shape", "section", "from", "to",
                                                    "elements", "order", "cables"};
  switch (shape) {
    case Shape::Rectangle: return rectangle;
    case Shape::Cylinder: return cylinder;
    case Shape::Disc: return disc;
    case Shape::Meridian: return meridian;
  }
  return rectangle;
}

bool readGeometry(CaseBuilder& b, Fields& f, SurfaceSpec& s) {
  Input& in = b.in;
  SurfaceMap& m = s.map;
  const auto vector = [&](const char* key, Eigen::Vector3d& out) {
    const YAML::Node* n = f.require(key);
    const auto v = n ? in.vector3(*n, f.path(key), kind::kLength) : std::nullopt;
    if (v) out = *v;
    return v.has_value();
  };
  const auto positive = [&](const char* key, double& out) {
    const YAML::Node* n = f.require(key);
    const auto v = n ? in.quantity(*n, f.path(key), kind::kLength, Limit::Positive) : std::nullopt;
    if (v) out = *v;
    return v.has_value();
  };
  switch (m.shape) {
    case Shape::Rectangle: {
      const bool ok = vector("corner", m.origin) & vector("side1", m.side1) & vector("side2", m.side2);
      if (ok && !(m.side1.cross(m.side2).norm() > 1e-12 * m.side1.norm() * m.side2.norm())) {
        b.diag.error(f.node(), f.path() + ": side1 and side2 are parallel or zero (expected two "
                                          "independent edge vectors)");
        return false;
      }
      return ok;
    }
    case Shape::Cylinder:
      return vector("centre", m.origin) & positive("radius", m.radius) &
             positive("length", m.length) & readAngles(b, f, m);
    case Shape::Disc:
      return vector("centre", m.origin) & positive("radius", m.radius) & readAngles(b, f, m);
    case Shape::Meridian: {
      Eigen::Vector3d to = Eigen::Vector3d::Zero();
      const bool ok = vector("from", m.origin) & vector("to", to);
      if (!ok) return false;
      m.side1 = to - m.origin;
      if (std::abs(m.origin(1)) > 0.0 || std::abs(to(1)) > 0.0 || m.origin(0) < 0.0 || to(0) < 0.0 ||
          !(m.side1.norm() > 0.0)) {
        b.diag.error(f.node(), f.path() + ": not a meridian (expected from and to in the x-z plane, "
                                          "y = 0, radius x >= 0, and apart)");
        return false;
      }
      return true;
    }
  }
  return false;
}

// cables: [{along: DIRECTION, at: K or [K, ...], section: S}]: cable elements on the cell
// boundaries K (0 to the number of cells across) running along DIRECTION.
struct CableRow {
  int direction;  // 0: along s, 1: along t
  int boundary;
  const SectionSpec* section;
};

std::vector<CableRow> readCableRows(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                                    const SurfaceSpec& s) {
  std::vector<CableRow> rows;
  const std::array<const char*, 2> names = directionNames(s.map.shape);
  const std::vector<YAML::Node> items = listItems(b.diag, n, path);
  for (size_t i = 0; i < items.size(); ++i) {
    Fields f(b.diag, items[i], itemPath(path, i), {"along", "at", "section"});
    const bool meridian = s.map.shape == Shape::Meridian;
    const YAML::Node* along = meridian ? f.find("along") : f.require("along");
    const YAML::Node* at = f.require("at");
    const YAML::Node* sec = f.require("section");
    const auto direction =
        along ? b.in.choice<int>(*along, f.path("along"), {{names[0], 0}, {names[1], 1}})
              : std::optional<int>(meridian ? 0 : -1);
    const SectionSpec* section = sec ? b.section(*sec, f.path("section")) : nullptr;
    if (!direction || *direction < 0 || !at) continue;
    // Boundaries across the cables' direction; a meridian's hoops sit at its element ends.
    const int across = meridian ? s.divisions[0] : s.divisions[1 - *direction];
    std::vector<YAML::Node> boundaries;
    if (at->IsSequence())
      boundaries = listItems(b.diag, *at, f.path("at"));
    else
      boundaries.push_back(*at);
    for (size_t k = 0; k < boundaries.size(); ++k) {
      const auto boundary = b.in.integer(boundaries[k], f.path("at"), 0, across);
      if (boundary && section) rows.push_back({*direction, *boundary, section});
    }
  }
  return rows;
}

// Membrane elements of every cell, then the cables of each row.
void generate(CaseBuilder& b, const SurfaceSpec& s, const std::vector<CableRow>& rows, int line) {
  const int L = SurfaceNodeMaker::kLattice;
  SurfaceNodeMaker maker(b, s.map, s.divisions, line);
  PendingSurface pending{s.name, {}};
  const std::vector<Eigen::Vector2d> natural = naturalNodes(s.kind);
  const element::MembraneSection& section = s.section->membrane;
  if (s.map.shape == Shape::Meridian) {
    for (int e = 0; e < s.divisions[0]; ++e) {
      std::vector<int> nodes;
      for (int k = 0; k <= s.kind.order; ++k) nodes.push_back(maker.node(L * e + L * k / s.kind.order, 0));
      pending.elements.emplace_back(
          "axisymmetric_membrane",
          element::makeAxisymmetricMembrane(nodes, section, s.section->quadrature));
    }
    for (int node : maker.nodes()) b.model.constrain(node, 1);  // y carries nothing
  } else {
    for (int j = 0; j < s.divisions[1]; ++j)
      for (int i = 0; i < s.divisions[0]; ++i) {
        std::vector<std::vector<int>> cells;
        if (!s.kind.triangle) {
          std::vector<int> nodes;
          for (const Eigen::Vector2d& xi : natural)
            nodes.push_back(maker.node(static_cast<int>(std::lround(L * (i + (xi(0) + 1) / 2))),
                                       static_cast<int>(std::lround(L * (j + (xi(1) + 1) / 2)))));
          cells.push_back(nodes);
        } else {
          for (const Corners& c : splitCell(i, j, forwardDiagonal(s.diagonals, i, j, s.divisions))) {
            std::vector<int> nodes;
            for (const Eigen::Vector2d& rs : natural) {
              // A triangle with two corners on one node (at the centre of a disc) has no area:
              // skip it once its corners (nodes 0-2) are known, before its edge nodes are made,
              // which no element would hold.
              if (nodes.size() == 3 &&
                  (nodes[0] == nodes[1] || nodes[1] == nodes[2] || nodes[2] == nodes[0]))
                break;
              const Eigen::Vector2d p = c[0].cast<double>() + rs(0) * (c[1] - c[0]).cast<double>() +
                                        rs(1) * (c[2] - c[0]).cast<double>();
              nodes.push_back(maker.node(static_cast<int>(std::lround(L * p(0))),
                                         static_cast<int>(std::lround(L * p(1)))));
            }
            if (nodes.size() == natural.size() && nodes[0] != nodes[1] && nodes[1] != nodes[2] &&
                nodes[2] != nodes[0])
              cells.push_back(nodes);
          }
        }
        for (std::vector<int>& nodes : cells)
          pending.elements.emplace_back(
              "membrane", element::makeMembraneElement(s.kind.triangle ? "triangle" : "quad",
                                                       std::move(nodes), section,
                                                       s.section->quadrature));
      }
  }
  for (const CableRow& row : rows) {
    if (s.map.shape == Shape::Meridian) {  // a hoop ring at the node of boundary `at`
      const int node = maker.node(L * row.boundary, 0);
      pending.elements.emplace_back("hoop_cable",
                                    std::make_unique<element::HoopCable>(node, row.section->section));
      continue;
    }
    const int cells = s.divisions[row.direction];
    for (int e = 0; e < cells; ++e) {
      std::vector<int> nodes;
      for (int k = 0; k <= s.kind.order; ++k) {
        const int along = L * e + L * k / s.kind.order, across = L * row.boundary;
        nodes.push_back(row.direction == 0 ? maker.node(along, across) : maker.node(across, along));
      }
      if (nodes.front() == nodes.back()) continue;  // a row through the centre of a disc
      pending.elements.emplace_back(
          "cable",
          element::makeCableElement(nodes, row.section->section, row.section->quadrature));
    }
  }
  b.surfaces[s.name] = maker.nodes();
  b.surface_elements.push_back(std::move(pending));
}

void readSurface(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  const std::string shape_word = peekText(item, "shape");
  const std::vector<std::pair<std::string, Shape>> shapes = {{"rectangle", Shape::Rectangle},
                                                             {"cylinder", Shape::Cylinder},
                                                             {"disc", Shape::Disc},
                                                             {"meridian", Shape::Meridian}};
  SurfaceSpec s;
  const auto known = std::find_if(shapes.begin(), shapes.end(),
                                  [&](const auto& p) { return p.first == shape_word; });
  if (known != shapes.end()) s.map.shape = known->second;
  Fields f(b.diag, item, path, keysOf(s.map.shape));
  const YAML::Node* name_node = f.require("name");
  if (name_node) s.name = b.in.text(*name_node, f.path("name")).value_or("");
  const bool named = !s.name.empty() && checkName(b, *name_node, f.path("name"), s.name);
  const YAML::Node* shape_node = f.require("shape");
  bool ok = shape_node && b.in.choice(*shape_node, f.path("shape"), shapes).has_value();
  ok = readGeometry(b, f, s) && ok;
  if (const YAML::Node* sec = f.require("section"))
    s.section = b.section(*sec, f.path("section"), SectionUse::Membrane);
  ok = ok && s.section;
  if (s.map.shape == Shape::Meridian) {
    const YAML::Node* ne = f.require("elements");
    const YAML::Node* no = f.require("order");
    const auto elements = ne ? b.in.integer(*ne, f.path("elements"), 1, 1000000) : std::nullopt;
    const auto order = no ? b.in.integer(*no, f.path("order"), 2, 4) : std::nullopt;
    ok = ok && elements && order;
    const int nodes = order.value_or(2);
    s.divisions = {elements.value_or(1), 1};
    s.kind = {false, nodes, nodes - 1};
  } else {
    const YAML::Node* element = f.require("element");
    const auto kind = element ? b.in.choice(*element, f.path("element"), elementKinds()) : std::nullopt;
    const YAML::Node* div = f.require("divisions");
    const auto divisions = div ? readDivisions(b, *div, f.path("divisions")) : std::nullopt;
    ok = ok && kind && divisions;
    if (kind) s.kind = *kind;
    if (divisions) s.divisions = *divisions;
    if (const YAML::Node* d = f.find("diagonals")) {
      const auto pattern = b.in.choice<std::string>(
          *d, f.path("diagonals"),
          {{"forward", "forward"}, {"backward", "backward"}, {"centre", "centre"}});
      if (pattern && !s.kind.triangle)
        b.diag.error(*d, f.path("diagonals") + ": only for triangles (got element " +
                             peekText(item, "element") + ", expected T3, T6 or T10)");
      ok = ok && pattern && s.kind.triangle;
      s.diagonals = pattern.value_or(s.diagonals);
    }
    if (kind && s.map.shape == Shape::Disc && !kind->triangle) {
      b.diag.error(*element, f.path("element") + ": a disc needs triangles (got " +
                                 element->Scalar() +
                                 ", expected T3, T6 or T10: quads would collapse at the centre)");
      ok = false;
    }
  }
  std::vector<CableRow> rows;
  if (const YAML::Node* c = f.find("cables")) rows = readCableRows(b, *c, f.path("cables"), s);
  if (!ok || !named) {
    if (!s.name.empty()) b.broken_node_names.insert(s.name);
    return;
  }
  generate(b, s, rows, lineOf(item));
}

}  // namespace

void readSurfaces(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "surfaces");
  for (size_t i = 0; i < items.size(); ++i) readSurface(b, items[i], itemPath("surfaces", i));
}

}  // namespace flexmoor::app

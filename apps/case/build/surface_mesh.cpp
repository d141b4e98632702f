#include "apps/case/build/surface_mesh.hpp"

#include <Eigen/Geometry>
#include <unordered_map>
#include <unordered_set>

#include "apps/case/build/node_index.hpp"
#include "libstruct/shape/quad_shape.hpp"
#include "libstruct/shape/triangle_shape.hpp"

namespace flexmoor::app {
namespace {

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

// The nodes of one surface, by lattice point: parameters in units of 1/6 of a cell, so that the
// nodes of every element order (thirds and halves of a cell edge) fall on whole numbers.
class SurfaceNodeMaker {
 public:
  static constexpr int kLattice = 6;
  SurfaceNodeMaker(const model::NodalField& reference, const SurfaceMap& map,
                   std::array<int, 2> divisions,
                   const std::function<int(const Eigen::Vector3d&)>& add_node)
      : add_node_(add_node),
        map_(map),
        divisions_(divisions),
        index_(reference, 1e-9 * std::max(map.size(), 1e-300)) {}

  // The node at lattice point (u, v), made on first use.
  int node(int u, int v) {
    const long long key = static_cast<long long>(u) * (kLattice * 100000LL + 1) + v;
    if (const auto found = lattice_.find(key); found != lattice_.end()) return found->second;
    const Eigen::Vector3d x = map_(static_cast<double>(u) / (kLattice * divisions_[0]),
                                   static_cast<double>(v) / (kLattice * divisions_[1]));
    int n = index_.find(x);
    if (n < 0) {
      n = add_node_(x);
      index_.add(x, n);
    }
    lattice_[key] = n;
    if (in_surface_.insert(n).second) nodes_.push_back(n);
    return n;
  }
  const std::vector<int>& nodes() const { return nodes_; }

 private:
  const std::function<int(const Eigen::Vector3d&)>& add_node_;
  const SurfaceMap& map_;
  std::array<int, 2> divisions_;
  NodeIndex index_;
  std::unordered_map<long long, int> lattice_;
  std::vector<int> nodes_;
  std::unordered_set<int> in_surface_;  // nodes_ as a set
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

}  // namespace

// Parameter directions of each shape, for `cables: along:` and the error messages.
std::array<const char*, 2> directionNames(SurfaceShape shape) {
  switch (shape) {
    case SurfaceShape::Rectangle:
      return {"side1", "side2"};
    case SurfaceShape::Cylinder:
      return {"around", "along"};
    case SurfaceShape::Disc:
      return {"radial", "around"};
    case SurfaceShape::Meridian:
      return {"around", "around"};  // hoop cables at the meridian's nodes
  }
  return {"", ""};
}

Eigen::Vector3d SurfaceMap::operator()(double s, double t) const {
  switch (shape) {
    case SurfaceShape::Rectangle:
    case SurfaceShape::Meridian:
      return origin + s * side1 + t * side2;
    case SurfaceShape::Cylinder: {
      const double theta = theta0 + s * (theta1 - theta0);
      Eigen::Vector3d p;  // in the cyclic frame (e1, e2, axis)
      p((axis + 1) % 3) = radius * std::cos(theta);
      p((axis + 2) % 3) = radius * std::sin(theta);
      p(axis) = t * length;
      return origin + p;
    }
    case SurfaceShape::Disc: {
      const double theta = theta0 + t * (theta1 - theta0);
      return origin +
             Eigen::Vector3d(s * radius * std::cos(theta), s * radius * std::sin(theta), 0.0);
    }
  }
  return origin;
}

SurfaceElements meshSurface(const model::NodalField& reference, const SurfaceSpec& s,
                            const std::vector<CableRow>& rows,
                            const std::function<int(const Eigen::Vector3d&)>& add_node) {
  const int L = SurfaceNodeMaker::kLattice;
  SurfaceNodeMaker maker(reference, s.map, s.divisions, add_node);
  SurfaceElements out;
  const std::vector<Eigen::Vector2d> natural = naturalNodes(s.kind);
  const element::MembraneSection& section = s.section->membrane;
  if (s.map.shape == SurfaceShape::Meridian) {
    for (int e = 0; e < s.divisions[0]; ++e) {
      std::vector<int> nodes;
      for (int k = 0; k <= s.kind.order; ++k)
        nodes.push_back(maker.node(L * e + L * k / s.kind.order, 0));
      out.elements.push_back({"axisymmetric_membrane", nullptr,
                              ElementSpec::membrane(ElementSpec::Kind::AxisymmetricMembrane, nodes,
                                                    section, s.section->quadrature)});
    }
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
          for (const Corners& c :
               splitCell(i, j, forwardDiagonal(s.diagonals, i, j, s.divisions))) {
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
          out.elements.push_back(
              {"membrane", nullptr,
               ElementSpec::membrane(s.kind.triangle ? ElementSpec::Kind::MembraneTriangle
                                                     : ElementSpec::Kind::MembraneQuad,
                                     std::move(nodes), section, s.section->quadrature)});
      }
  }
  for (const CableRow& row : rows) {
    if (s.map.shape == SurfaceShape::Meridian) {  // a hoop ring at the node of boundary `at`
      const int node = maker.node(L * row.boundary, 0);
      out.elements.push_back(
          {"hoop_cable", row.section, ElementSpec::hoopCable(node, row.section->section)});
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
      out.elements.push_back(
          {"cable", row.section,
           ElementSpec::cable(nodes, row.section->section, row.section->quadrature)});
    }
  }
  out.nodes = maker.nodes();
  return out;
}

}  // namespace flexmoor::app

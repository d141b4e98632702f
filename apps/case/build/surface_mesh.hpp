#pragma once
// The membrane meshes of surfaces (a case file's surfaces:, read_surfaces.cpp; a scenario's tube). Each surface
// maps the unit square of parameters (s, t) onto
//   rectangle  corner + s side1 + t side2
//   cylinder   centre + (R cos theta, R sin theta, t length), theta from angles[0] to angles[1],
//              in the frame (e1, e2, axis) of its axis: (x, y, z) for axis z (the default),
//              (y, z, x) for x, (z, x, y) for y (theta = 0 on top, 90 deg at +x); the normal
//              (around) x (along) points out either way
//   disc       centre + (s R cos theta, s R sin theta, 0), theta likewise (triangles only)
//   meridian   from + s (to - from), a meridian in the x-z plane swept about the z axis
//              (axisymmetric membrane elements; its nodes' y dofs are fixed)
// divided into divisions[0] x divisions[1] cells of Q4/Q8/Q12 quads or pairs of T3/T6/T10
// triangles. A generated node that lands on an existing node (of nodes:, lines: or an earlier
// surface, or of the same surface, as at the centre of a disc or the seam of a closed cylinder)
// becomes that node. Cables can be laid along cell boundaries (hoop rings of a tube).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "apps/problem/mesh_spec.hpp"
#include "apps/problem/section_spec.hpp"

namespace flexmoor::app {

enum class SurfaceShape { Rectangle, Cylinder, Disc, Meridian };

// Parameter directions of each shape, for `cables: along:` and the error messages.
std::array<const char*, 2> directionNames(SurfaceShape shape);

// An element of a surface: Q4, Q8, Q12 (quads) or T3, T6, T10 (triangles); for a meridian, its
// 2 to 4 nodes.
struct ElementKind {
  bool triangle;
  int nodes;
  int order;  // nodes per cell edge - 1
};

// The geometry of one surface: parameters (s, t) in [0, 1]^2 to a point.
struct SurfaceMap {
  SurfaceShape shape = SurfaceShape::Rectangle;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), side1 = Eigen::Vector3d::Zero(),
                  side2 = Eigen::Vector3d::Zero();
  double radius = 0.0, length = 0.0, theta0 = 0.0, theta1 = 2.0 * M_PI;
  int axis = 2;  // cylinder: 0, 1, 2 = x, y, z

  Eigen::Vector3d operator()(double s, double t) const;
  double size() const { return std::max({side1.norm(), side2.norm(), radius, length}); }
};

struct SurfaceSpec {
  std::string name;
  SurfaceMap map;
  ElementKind kind{false, 4, 1};
  std::array<int, 2> divisions{1, 1};
  std::string diagonals = "forward";
  const SectionSpec* section = nullptr;
};

// cables: [{along: DIRECTION, at: K or [K, ...], section: S}]: cable elements on the cell
// boundaries K (0 to the number of cells across) running along DIRECTION.
struct CableRow {
  int direction;  // 0: along s, 1: along t
  int boundary;
  const SectionSpec* section;
};

// A surface's mesh: its membrane elements, cell by cell, then the cables of each row, on the
// nodes `add_node` makes at points where `reference` has none (it returns the new node's
// index; the nodes made so far are merged too).
struct SurfaceElements {
  std::vector<int> nodes;  // the surface's, in the order first used
  // Each element and its element_types entry ("membrane", "axisymmetric_membrane", "cable",
  // "hoop_cable"), with the section that made it (null for the surface's own).
  struct Generated {
    const char* type;
    const SectionSpec* row_section;
    ElementSpec element;
  };
  std::vector<Generated> elements;
};
SurfaceElements meshSurface(const model::NodalField& reference, const SurfaceSpec& s,
                            const std::vector<CableRow>& rows,
                            const std::function<int(const Eigen::Vector3d&)>& add_node);

}  // namespace flexmoor::app

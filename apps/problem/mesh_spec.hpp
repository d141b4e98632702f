#pragma once
// A case's nodes and elements as specifications: what `nodes:`, `lines:`, `surfaces:`,
// `elements:` and the bodies' masses read into, what a program fills to state a mesh without a
// case file, and what buildMesh (apps/case/build/build_mesh.hpp) turns into the model's nodes and
// elements, in this order. Nodes are 0-based model nodes, elements 0-based model elements; values
// are in the case's units.
#include <Eigen/Core>
#include <algorithm>
#include <utility>
#include <vector>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/model/state.hpp"

namespace flexmoor::app {

// One element and the data its kind needs; what a kind does not use keeps its default.
struct ElementSpec {
  enum class Kind {
    Cable,                 // 2 to 4 nodes along the cable (cable_element.hpp)
    MembraneTriangle,      // 3, 6 or 10 nodes (membrane_element.hpp)
    MembraneQuad,          // 4, 8 or 12 nodes
    AxisymmetricMembrane,  // a meridian of 2 to 4 nodes in x-z (axisymmetric_membrane.hpp)
    HoopCable,             // a hoop ring at one node of an axisymmetric model
    Spring,                // two nodes (spring_element.hpp)
    PointMass,             // one node
  };
  Kind kind = Kind::Cable;
  std::vector<int> nodes;  // in the element's node order

  element::CableSection cable_section;        // Cable, HoopCable
  element::MembraneSection membrane_section;  // the membranes
  int quadrature = 0;  // Gauss points of a cable or membrane; 0 = the element's default

  double stiffness = 0.0;     // Spring: k
  double rest_length = -1.0;  // Spring: < 0 takes the reference distance of its nodes
  material::Compression compression = material::Compression::TensionOnly;  // Spring
  double damping = 0.0;  // Spring: the dashpot in parallel, force per rate of length change

  double mass = 0.0;  // PointMass

  static ElementSpec cable(std::vector<int> nodes, element::CableSection section, int quadrature) {
    ElementSpec e;
    e.kind = Kind::Cable;
    e.nodes = std::move(nodes);
    e.cable_section = std::move(section);
    e.quadrature = quadrature;
    return e;
  }
  // kind: MembraneTriangle, MembraneQuad or AxisymmetricMembrane.
  static ElementSpec membrane(Kind kind, std::vector<int> nodes, element::MembraneSection section,
                              int quadrature) {
    ElementSpec e;
    e.kind = kind;
    e.nodes = std::move(nodes);
    e.membrane_section = std::move(section);
    e.quadrature = quadrature;
    return e;
  }
  static ElementSpec hoopCable(int node, element::CableSection section) {
    ElementSpec e;
    e.kind = Kind::HoopCable;
    e.nodes = {node};
    e.cable_section = std::move(section);
    return e;
  }
  static ElementSpec spring(int node_a, int node_b, double stiffness, double rest_length,
                            material::Compression compression, double damping) {
    ElementSpec e;
    e.kind = Kind::Spring;
    e.nodes = {node_a, node_b};
    e.stiffness = stiffness;
    e.rest_length = rest_length;
    e.compression = compression;
    e.damping = damping;
    return e;
  }
  static ElementSpec pointMass(int node, double mass) {
    ElementSpec e;
    e.kind = Kind::PointMass;
    e.nodes = {node};
    e.mass = mass;
    return e;
  }
};

// Positions of these nodes closer than this (a millionth of the model's size) are one point.
inline double positionTolerance(const model::NodalField& reference) {
  if (reference.cols() == 0) return 0.0;
  const double size = (reference.rowwise().maxCoeff() - reference.rowwise().minCoeff()).norm();
  return 1e-6 * std::max(size, reference.cwiseAbs().maxCoeff());
}

struct MeshSpec {
  model::NodalField reference = model::NodalField(3, 0);  // each node's reference position
  std::vector<ElementSpec> elements;

  // Appends nodes at their reference positions; returns the first one's index.
  int addNode(const Eigen::Vector3d& position) {
    const int node = nodeCount();
    reference.conservativeResize(3, node + 1);
    reference.col(node) = position;
    return node;
  }
  int addNodes(const model::NodalField& positions) {
    const int first = nodeCount();
    reference.conservativeResize(3, first + positions.cols());
    reference.rightCols(positions.cols()) = positions;
    return first;
  }
  // Appends an element; returns its index.
  int addElement(ElementSpec element) {
    elements.push_back(std::move(element));
    return elementCount() - 1;
  }

  int nodeCount() const { return static_cast<int>(reference.cols()); }
  Eigen::Vector3d position(int node) const { return reference.col(node); }
  int elementCount() const { return static_cast<int>(elements.size()); }
  const std::vector<int>& elementNodes(int element) const { return elements[element].nodes; }
  double positionTolerance() const { return app::positionTolerance(reference); }
  // The node nearest x (-1 when there is none) and its distance from it.
  std::pair<int, double> nearestNode(const Eigen::Vector3d& x) const {
    int nearest = -1;
    double distance = 0.0;
    for (int node = 0; node < nodeCount(); ++node) {
      const double d = (position(node) - x).norm();
      if (nearest < 0 || d < distance) nearest = node, distance = d;
    }
    return {nearest, distance};
  }
};

}  // namespace flexmoor::app

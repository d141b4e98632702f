#pragma once
// Curved isoparametric membrane element, total Lagrangian, plane stress in convected coordinates
// (Eq. 2.26-2.42, 3.1-3.17, 4.28-4.41). One kernel for every shape: Shape is QuadShape<4|8|12>
// or TriangleShape<3|6|10> (values and derivatives on the reference cell).
#include <memory>

#include "libstruct/element/element.hpp"
#include "libstruct/material/membrane_material.hpp"
#include "libstruct/shape/shape_table.hpp"
#include "libstruct/shape/triangle_quadrature.hpp"

namespace flexmoor::element {

struct MembraneSection {
  double thickness = 0.0;  // h0
  double density = 0.0;    // rho0, mass per unit reference volume
  std::shared_ptr<const material::MembraneMaterial> material;
};

template <class Shape>
class MembraneElement final : public Element {
 public:
  MembraneElement(std::vector<int> nodes, MembraneSection section,
                  const shape::QuadratureRule2D& rule);

  std::string typeName() const override;
  void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                     Eigen::MatrixXd* K) const override;
  void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const override;
  void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                Eigen::VectorXd& p) const override;
  void followerPressure(const ElementContext& c, const PressureField& pressure, Eigen::VectorXd& f,
                        Eigen::MatrixXd* dfdu) const override;
  using Element::result;
  void result(const ElementContext& c, ElementResult& out) const override;
  double minRelativeJacobian(const model::NodalField& X) const override;
  Eigen::VectorXd nodalAreas(const model::NodalField& X) const override;

 private:
  static constexpr int N = Shape::Values::RowsAtCompileTime;
  using Coordinates = Eigen::Matrix<double, 3, N>;
  using AreaMatrix = Eigen::Matrix<double, N, N>;
  using NodalVector = Eigen::Matrix<double, 3 * N, 1>;  // 3 I + i: component i at node I
  using Tangent = Eigen::Matrix<double, 3 * N, 3 * N>;
  void gather(const ElementContext& c, Coordinates& X, Coordinates& Y) const;
  // int M^I M^J dA over the reference surface X (the mass matrix per unit rho h, Eq. 4.40).
  AreaMatrix areaMatrix(const Coordinates& X) const;

  MembraneSection section_;
  const shape::QuadratureRule2D& rule_;
  std::shared_ptr<const shape::ShapeTable<Shape>> shapes_;  // at rule_'s points
};

// Builds the membrane element for `shape` ("quad" or "triangle") and its node count; quadrature
// order 0 picks the default (quads: Gauss n x n with n = 2, 3, 4 for Q4, Q8, Q12; triangles:
// degree 2, 4, 6 for T3, T6, T10, exact for the mass matrix of a flat element).
std::unique_ptr<Element> makeMembraneElement(const std::string& shape, std::vector<int> nodes,
                                             MembraneSection section, int quadrature = 0);

}  // namespace flexmoor::element

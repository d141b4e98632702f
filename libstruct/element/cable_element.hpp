#pragma once
// Curved isoparametric cable element with N = 2, 3 or 4 nodes, total Lagrangian, Green strain in
// convected coordinates (Eq. 2.43-2.55, 3.19-3.29, 4.42-4.49). One kernel for every node count.
#include <memory>

#include "libstruct/element/element.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/shape/gauss_legendre.hpp"

namespace flexmoor::element {

struct CableSection {
  double area = 0.0;     // A0, reference cross-section
  double density = 0.0;  // rho0, mass per unit reference volume
  std::shared_ptr<const material::CableMaterial> material;
  // Axial Kelvin-Voigt damping (axial_damping.hpp): BA in N s, or, when damping_ratio > 0,
  // MoorDyn's negative input zeta, converted per element with its node spacing as the segment
  // length. At most one of them is non-zero.
  double axial_damping = 0.0;
  double damping_ratio = 0.0;
};

template <int N>
class CableElement final : public Element {
 public:
  // quadrature_points: Gauss-Legendre order; 0 means N (full integration of the mass matrix of a
  // straight element).
  CableElement(std::vector<int> nodes, CableSection section, int quadrature_points = 0);

  std::string typeName() const override;
  void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                     Eigen::MatrixXd* K) const override;
  void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const override;
  void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                Eigen::VectorXd& p) const override;
  bool takesLineLoads() const override { return true; }
  bool lineLoad(const ElementContext& c, const model::LineLoad& load, Eigen::VectorXd& p,
                LoadMatrices* J) const override;
  bool hasDamping() const override;
  void dampingForce(const ElementContext& c, Eigen::VectorXd& f, LoadMatrices* J) const override;
  // Axial force at the integration points, the viscous part BA d(lambda)/dt included (the end
  // tensions come from the assembler's nodal force balance: ElementResult).
  using Element::result;
  void result(const ElementContext& c, ElementResult& out) const override;
  // The axial force from the strain at natural coordinate xi (at xi = +-1 the strain-based end
  // tension, which converges more slowly than the nodal force balance).
  double axialForceAt(const ElementContext& c, double xi) const;
  // At the integration points and at the ends.
  double minRelativeJacobian(const model::NodalField& X) const override;

  const CableSection& section() const { return section_; }

 private:
  using Coordinates = Eigen::Matrix<double, 3, N>;
  void gather(const ElementContext& c, Coordinates& X, Coordinates& Y) const;
  void gatherVelocity(const ElementContext& c, Coordinates& V) const;
  // BA of the element (N s): the section's, or its damping ratio's at this element's segment.
  double axialDamping(const Coordinates& X) const;
  double axialForce(const Coordinates& X, const Coordinates& Y, const Coordinates& V, double BA,
                    double xi) const;

  CableSection section_;
  const shape::QuadratureRule1D& rule_;  // Gauss-Legendre, along the element
};

// Builds the element of the right node count (2, 3 or 4 nodes).
std::unique_ptr<Element> makeCableElement(std::vector<int> nodes, CableSection section,
                                          int quadrature_points = 0);

}  // namespace flexmoor::element

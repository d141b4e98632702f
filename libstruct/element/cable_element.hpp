#pragma once
// Curved isoparametric cable element with N = 2, 3 or 4 nodes, total Lagrangian, Green strain in
// convected coordinates (Eq. 2.43-2.55, 3.19-3.29, 4.42-4.49). One kernel for every node count.
#include <memory>

#include "libstruct/element/element.hpp"
#include "libstruct/material/cable_material.hpp"

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
  void lineLoad(const ElementContext& c, const model::LineLoad& load, Eigen::VectorXd& p,
                LoadMatrices* J) const override;
  bool hasDamping() const override;
  void dampingForce(const ElementContext& c, Eigen::VectorXd& f, LoadMatrices* J) const override;
  // Axial force at the integration points and the ends, the viscous part BA d(lambda)/dt included.
  ElementResult result(const ElementContext& c) const override;
  // At the integration points and at the ends, where the end tensions are evaluated.
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
  int quadrature_points_;
};

// Builds the element of the right node count (2, 3 or 4 nodes).
std::unique_ptr<Element> makeCableElement(std::vector<int> nodes, CableSection section,
                                          int quadrature_points = 0);

}  // namespace flexmoor::element

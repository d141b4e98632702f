#pragma once
// Axisymmetric membrane element: a meridian of N = 2, 3 or 4 nodes in the x-z plane (x is the
// radius r, z the axis) swept about the z axis. The convected metric of the shell of revolution
// is diagonal: meridian a11 = x,1 . x,1, hoop a22 = r^2 (per radian), so the membrane laws of
// Eq. 2.40-2.42 apply unchanged. Forces, masses and pressures are per radian of circumference.
// The nodes' y dofs carry nothing and must be fixed by the model.
#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"

namespace flexmoor::element {

template <int N>
class AxisymmetricMembrane final : public Element {
 public:
  AxisymmetricMembrane(std::vector<int> nodes, MembraneSection section, int quadrature_points = 0);

  std::string typeName() const override { return "axisymmetric_membrane" + std::to_string(N); }
  bool axisymmetric() const override { return true; }
  void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                     Eigen::MatrixXd* K) const override;
  void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const override;
  void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                Eigen::VectorXd& p) const override;
  // Per radian; a field is evaluated on the meridian (theta = 0, the x-z plane), which is right
  // for a field that is axisymmetric about the z axis (hydrostatic pressure).
  void followerPressure(const ElementContext& c, const PressureField& pressure, Eigen::VectorXd& f,
                        Eigen::MatrixXd* dfdu) const override;
  using Element::result;
  void result(const ElementContext& c, ElementResult& out) const override;
  // The meridian's, and the radius r / D at each integration point (the hoop metric is r^2).
  double minRelativeJacobian(const model::NodalField& X) const override;
  Eigen::VectorXd nodalAreas(const model::NodalField& X) const override;  // per radian

 private:
  using Coordinates = Eigen::Matrix<double, 3, N>;
  void gather(const ElementContext& c, Coordinates& X, Coordinates& Y) const;
  // int L^I L^J r ds over the reference meridian X (the mass matrix per unit rho h per radian,
  // Eq. 4.40).
  Eigen::Matrix<double, N, N> areaMatrix(const Coordinates& X) const;
  MembraneSection section_;
  const shape::QuadratureRule1D& rule_;  // Gauss-Legendre, along the element
};

// A circumferential cable (hoop ring) at one node of an axisymmetric model: radius r = x of the
// node, stretch rho / r with rho the current radius; radial force per radian N = S lambda A0
// (Eq. 2.53 / 2.54 with a11 = r^2, A11 = rho^2).
class HoopCable final : public Element {
 public:
  HoopCable(int node, CableSection section);

  std::string typeName() const override { return "hoop_cable"; }
  bool axisymmetric() const override { return true; }
  void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                     Eigen::MatrixXd* K) const override;
  void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const override;
  void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                Eigen::VectorXd& p) const override;
  using Element::result;
  void result(const ElementContext& c, ElementResult& out) const override;

 private:
  CableSection section_;
};

std::unique_ptr<Element> makeAxisymmetricMembrane(std::vector<int> nodes, MembraneSection section,
                                                  int quadrature_points = 0);

}  // namespace flexmoor::element

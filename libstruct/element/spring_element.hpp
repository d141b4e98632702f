#pragma once
// Two-node axial spring: N = k (l - l0) along the current chord e = (y2 - y1) / l.
// Tangent: k e e^T + (N / l)(I - e e^T). Massless. An optional dashpot in parallel adds
// c dl/dt, dl/dt = e . (y2' - y1') (axial_damping.hpp with y,1 = y2 - y1).
#include "libstruct/element/element.hpp"
#include "libstruct/material/cable_material.hpp"

namespace flexmoor::element {

class SpringElement final : public Element {
 public:
  // rest_length < 0 takes the distance of the two nodes in the reference configuration;
  // damping: the dashpot's c, force per unit rate of length change (N s/m).
  SpringElement(int node_a, int node_b, double stiffness, double rest_length,
                material::Compression compression, double damping = 0.0);

  std::string typeName() const override { return "spring"; }
  void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                     Eigen::MatrixXd* K) const override;
  void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const override;
  void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                Eigen::VectorXd& p) const override;
  bool hasDamping() const override { return damping_ > 0.0; }
  void dampingForce(const ElementContext& c, Eigen::VectorXd& f, LoadMatrices* J) const override;
  // The spring's and the dashpot's force together.
  using Element::result;
  void result(const ElementContext& c, ElementResult& out) const override;

 private:
  double restLength(const ElementContext& c) const;
  double stiffness_, rest_length_, damping_;
  material::Compression compression_;
};

// A concentrated mass at one node (a buoy, a clump weight): mass m I and weight m g. With
// `weighs` false, inertia only: a mass whose weight reaches the structure another way (a
// contained liquid's, through the gradient of its pressure on the walls).
class PointMassElement final : public Element {
 public:
  PointMassElement(int node, double mass, bool weighs = true);

  std::string typeName() const override { return "point_mass"; }
  void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                     Eigen::MatrixXd* K) const override;
  void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const override;
  void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                Eigen::VectorXd& p) const override;
  using Element::result;
  void result(const ElementContext&, ElementResult& out) const override { out.clear(); }
  // The mass whose weight it puts on its node (0 when it does not weigh).
  double weighingMass() const { return weighs_ ? mass_ : 0.0; }

 private:
  double mass_;
  bool weighs_;
};

}  // namespace flexmoor::element

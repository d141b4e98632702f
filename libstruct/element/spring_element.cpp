#include "libstruct/element/spring_element.hpp"

#include "libstruct/element/axial_damping.hpp"

namespace flexmoor::element {

using Eigen::Matrix3d;
using Eigen::Vector3d;

SpringElement::SpringElement(int node_a, int node_b, double stiffness, double rest_length,
                             material::Compression compression, double damping)
    : Element({node_a, node_b}),
      stiffness_(stiffness),
      rest_length_(rest_length),
      damping_(damping),
      compression_(compression) {}

double SpringElement::restLength(const ElementContext& c) const {
  if (rest_length_ >= 0.0) return rest_length_;
  return (c.reference.col(nodes()[1]) - c.reference.col(nodes()[0])).norm();
}

void SpringElement::internalForce(const ElementContext& c, Eigen::VectorXd& f,
                                  Eigen::MatrixXd* K) const {
  const Vector3d ya = c.reference.col(nodes()[0]) + c.state.displacement.col(nodes()[0]);
  const Vector3d yb = c.reference.col(nodes()[1]) + c.state.displacement.col(nodes()[1]);
  const Vector3d d = yb - ya;
  const double l = d.norm();
  const Vector3d e = d / l;
  double force = stiffness_ * (l - restLength(c));
  const bool slack = compression_ == material::Compression::TensionOnly && force < 0.0;
  if (slack) force = 0.0;
  f.resize(6);
  f.head<3>() = -force * e;
  f.tail<3>() = force * e;
  if (!K) return;
  const Matrix3d ee = e * e.transpose();
  const Matrix3d k = (slack ? 0.0 : stiffness_) * ee + (force / l) * (Matrix3d::Identity() - ee);
  K->resize(6, 6);
  K->topLeftCorner<3, 3>() = k;
  K->bottomRightCorner<3, 3>() = k;
  K->topRightCorner<3, 3>() = -k;
  K->bottomLeftCorner<3, 3>() = -k;
}

// f_b = -f_a = c e e^T (y2' - y1'): axial_damping.hpp's p with y,1 = y2 - y1, v,1 = y2' - y1'.
void SpringElement::dampingForce(const ElementContext& c, Eigen::VectorXd& f,
                                 LoadMatrices* J) const {
  f.setZero(6);
  if (J) J->setZero(6);
  if (!hasDamping()) return;
  const int a = nodes()[0], b = nodes()[1];
  const Vector3d chord = c.reference.col(b) + c.state.displacement.col(b) - c.reference.col(a) -
                         c.state.displacement.col(a);
  const AxialRate p = axialRate(chord, c.state.velocity.col(b) - c.state.velocity.col(a));
  f.head<3>() = -damping_ * p.value;
  f.tail<3>() = damping_ * p.value;
  if (!J) return;
  const Matrix3d sum =
      J->summed ? Matrix3d(J->summed->stiffness * p.d_position + J->summed->damping * p.d_velocity)
                : Matrix3d::Zero();
  for (int I = 0; I < 2; ++I)
    for (int K = 0; K < 2; ++K) {
      const double sign = I == K ? damping_ : -damping_;
      if (J->summed) {
        J->stiffness.block<3, 3>(3 * I, 3 * K) = sign * sum;
        continue;
      }
      J->stiffness.block<3, 3>(3 * I, 3 * K) = sign * p.d_position;
      J->damping.block<3, 3>(3 * I, 3 * K) = sign * p.d_velocity;
    }
}

void SpringElement::mass(const ElementContext&, MassKind, Eigen::MatrixXd& M) const {
  M.setZero(6, 6);
}

void SpringElement::bodyLoad(const ElementContext&, const Vector3d&, Eigen::VectorXd& p) const {
  p.setZero(6);
}

void SpringElement::result(const ElementContext& c, ElementResult& out) const {
  Eigen::VectorXd f, viscous;
  internalForce(c, f, nullptr);
  dampingForce(c, viscous, nullptr);
  f += viscous;
  const Vector3d chord = c.reference.col(nodes()[1]) + c.state.displacement.col(nodes()[1]) -
                         c.reference.col(nodes()[0]) - c.state.displacement.col(nodes()[0]);
  out.clear();
  out.point_tension.push_back(f.tail<3>().dot(chord.normalized()));
}

PointMassElement::PointMassElement(int node, double mass, bool weighs)
    : Element({node}), mass_(mass), weighs_(weighs) {}

void PointMassElement::internalForce(const ElementContext&, Eigen::VectorXd& f,
                                     Eigen::MatrixXd* K) const {
  f.setZero(3);
  if (K) K->setZero(3, 3);
}

void PointMassElement::mass(const ElementContext&, MassKind, Eigen::MatrixXd& M) const {
  M = mass_ * Eigen::MatrixXd::Identity(3, 3);
}

void PointMassElement::bodyLoad(const ElementContext&, const Vector3d& g,
                                Eigen::VectorXd& p) const {
  p = weighs_ ? Eigen::VectorXd(mass_ * g) : Eigen::VectorXd::Zero(3);
}

}  // namespace flexmoor::element

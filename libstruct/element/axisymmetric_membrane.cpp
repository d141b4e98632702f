#include "libstruct/element/axisymmetric_membrane.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

#include "libstruct/element/interpolated_point.hpp"
#include "libstruct/element/nodal_mass.hpp"
#include "libstruct/element/reference_jacobian.hpp"
#include "libstruct/shape/gauss_legendre.hpp"
#include "libstruct/shape/lagrange_1d.hpp"

namespace flexmoor::element {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

const Vector3d kRadial = Vector3d::UnitX();

// Metric of the shell of revolution at a point: meridian a11 and hoop r^2 (Eq. 2.26 with the
// convected coordinates xi along the meridian and theta around the axis).
Matrix2d metric(const Vector3d& tangent, double radius) {
  return Eigen::Vector2d(tangent.squaredNorm(), radius * radius).asDiagonal();
}

}  // namespace

template <int N>
AxisymmetricMembrane<N>::AxisymmetricMembrane(std::vector<int> nodes, MembraneSection section,
                                              int quadrature_points)
    : Element(std::move(nodes)),
      section_(std::move(section)),
      rule_(shape::gaussLegendre(quadrature_points > 0 ? quadrature_points : N + 1)) {
  if (static_cast<int>(this->nodes().size()) != N)
    throw std::invalid_argument("axisymmetric membrane node count does not match its order");
}

template <int N>
void AxisymmetricMembrane<N>::gather(const ElementContext& c, Coordinates& X,
                                     Coordinates& Y) const {
  for (int I = 0; I < N; ++I) {
    X.col(I) = c.reference.col(nodes()[I]);
    Y.col(I) = X.col(I) + c.state.displacement.col(nodes()[I]);
  }
}

template <int N>
void AxisymmetricMembrane<N>::internalForce(const ElementContext& c, Eigen::VectorXd& f,
                                            Eigen::MatrixXd* K) const {
  using L = shape::Lagrange1D<N>;
  Coordinates X, Y;
  gather(c, X, Y);
  f.setZero(3 * N);
  if (K) K->setZero(3 * N, 3 * N);
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector Lv = L::values(rule_.points[q]);
    const typename L::Vector dL = L::derivatives(rule_.points[q]);
    const Vector3d x1 = X * dL, y1 = Y * dL;
    const double r = X.row(0).dot(Lv), rho = Y.row(0).dot(Lv);
    const Matrix2d a = metric(x1, r), A = metric(y1, rho);
    const material::MembraneStress s = section_.material->stress(a, A);
    const double dV = section_.thickness * std::sqrt(a.determinant()) * rule_.weights[q];
    // Eq. 3.17 on the shell of revolution: T^11 L^I,1 y,1 + T^22 rho L^I e_r
    Eigen::Matrix<double, 2, 3 * N> B = Eigen::Matrix<double, 2, 3 * N>::Zero();
    for (int I = 0; I < N; ++I) {
      f.template segment<3>(3 * I) +=
          dV * (s.T(0, 0) * dL(I) * y1 + s.T(1, 1) * rho * Lv(I) * kRadial);
      B.template block<1, 3>(0, 3 * I) = dL(I) * y1.transpose();             // d gamma_11
      B.template block<1, 3>(1, 3 * I) = rho * Lv(I) * kRadial.transpose();  // d gamma_22
    }
    if (!K) continue;
    // Eq. 4.39: material B^T C B (no shear in axisymmetry) + geometric part
    K->noalias() += dV * (B.transpose() * s.C.template topLeftCorner<2, 2>() * B);
    for (int I = 0; I < N; ++I)
      for (int J = 0; J < N; ++J) {
        auto block = K->template block<3, 3>(3 * I, 3 * J);
        block.diagonal().array() += dV * s.T(0, 0) * dL(I) * dL(J);
        block(0, 0) += dV * s.T(1, 1) * Lv(I) * Lv(J);
      }
  }
}

template <int N>
Eigen::Matrix<double, N, N> AxisymmetricMembrane<N>::areaMatrix(const Coordinates& X) const {
  using L = shape::Lagrange1D<N>;
  Eigen::Matrix<double, N, N> m = Eigen::Matrix<double, N, N>::Zero();
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector Lv = L::values(rule_.points[q]);
    const double dA =
        (X * L::derivatives(rule_.points[q])).norm() * X.row(0).dot(Lv) * rule_.weights[q];
    m += dA * (Lv * Lv.transpose());
  }
  return m;
}

template <int N>
void AxisymmetricMembrane<N>::mass(const ElementContext& c, MassKind kind,
                                   Eigen::MatrixXd& M) const {
  Coordinates X, Y;
  gather(c, X, Y);
  nodalMass<N>((section_.density * section_.thickness) * areaMatrix(X), kind, M);  // Eq. 4.40
}

template <int N>
Eigen::VectorXd AxisymmetricMembrane<N>::nodalAreas(const model::NodalField& X) const {
  Coordinates Xe;
  for (int I = 0; I < N; ++I) Xe.col(I) = X.col(nodes()[I]);
  return lumpedDiagonal<N>(areaMatrix(Xe));
}

template <int N>
void AxisymmetricMembrane<N>::bodyLoad(const ElementContext& c, const Vector3d& g,
                                       Eigen::VectorXd& p) const {
  Eigen::MatrixXd M;
  mass(c, MassKind::Consistent, M);
  Eigen::VectorXd gravity(3 * N);
  for (int I = 0; I < N; ++I) gravity.segment<3>(3 * I) = Vector3d(0.0, 0.0, g.z());
  p = M * gravity;  // only the axial component of gravity is axisymmetric
}

template <int N>
void AxisymmetricMembrane<N>::followerPressure(const ElementContext& c,
                                               const PressureField& pressure, Eigen::VectorXd& f,
                                               Eigen::MatrixXd* dfdu) const {
  using L = shape::Lagrange1D<N>;
  Coordinates X, Y, V, A;
  gather(c, X, Y);
  for (int I = 0; I < N; ++I) {
    V.col(I) = c.state.velocity.col(nodes()[I]);
    A.col(I) = c.state.acceleration.col(nodes()[I]);
  }
  f.setZero(3 * N);
  if (dfdu) dfdu->setZero(3 * N, 3 * N);
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector Lv = L::values(rule_.points[q]);
    const typename L::Vector dL = L::derivatives(rule_.points[q]);
    const Vector3d t = Y * dL;
    const double rho = Y.row(0).dot(Lv);
    model::LoadPoint point = interpolatedPoint(c, Y, V, A, Lv);
    const model::PointPressure p = pressure(point, dfdu != nullptr);
    const double w = p.pressure * rule_.weights[q];
    // Eq. 3.37 per radian: n = y,theta x y,xi = rho (t_z, 0, -t_r): the pressure pushes to the
    // right of the meridian (outwards for a meridian that runs up the axis)
    const Vector3d n(rho * t.z(), 0.0, -rho * t.x());
    for (int I = 0; I < N; ++I) f.template segment<3>(3 * I) += (w * Lv(I)) * n;
    if (!dfdu) continue;
    // dn/du^J, and the gradient part dp/du^J = L^J (dp/dy)^T
    const Matrix3d n_grad = rule_.weights[q] * (n * p.d_position.transpose());
    for (int J = 0; J < N; ++J) {
      Matrix3d dn = Matrix3d::Zero();
      dn(0, 0) = Lv(J) * t.z();
      dn(0, 2) = rho * dL(J);
      dn(2, 0) = -Lv(J) * t.x() - rho * dL(J);
      dn = w * dn + Lv(J) * n_grad;
      for (int I = 0; I < N; ++I) dfdu->template block<3, 3>(3 * I, 3 * J) += Lv(I) * dn;
    }
  }
}

template <int N>
void AxisymmetricMembrane<N>::result(const ElementContext& c, ElementResult& out) const {
  using L = shape::Lagrange1D<N>;
  Coordinates X, Y;
  gather(c, X, Y);
  out.clear();
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector Lv = L::values(rule_.points[q]);
    const typename L::Vector dL = L::derivatives(rule_.points[q]);
    const Vector3d x1 = X * dL, y1 = Y * dL;
    const double r0 = X.row(0).dot(Lv), rho = Y.row(0).dot(Lv);
    const Matrix2d a = metric(x1, r0), A = metric(y1, rho);
    const material::MembraneStress s = section_.material->stress(a, A);
    // stress resultants per current length: meridian along y,1, hoop along e_theta (= y here)
    const double scale = section_.thickness * std::sqrt(a.determinant() / A.determinant());
    Matrix3d n = scale * s.T(0, 0) * (y1 * y1.transpose());
    n(1, 1) = scale * s.T(1, 1) * rho * rho;
    out.point_resultant.push_back(n);
  }
}

template <int N>
double AxisymmetricMembrane<N>::minRelativeJacobian(const model::NodalField& X) const {
  Coordinates Xe;
  for (int I = 0; I < N; ++I) Xe.col(I) = X.col(nodes()[I]);
  const std::vector<double>& xi = rule_.points;
  double smallest = lineRelativeJacobian<N>(Xe, xi);
  const double size = boundingDiagonal<N>(Xe);
  for (double p : xi)
    smallest = std::min(smallest, Xe.row(0).dot(shape::Lagrange1D<N>::values(p)) / size);
  return smallest;
}

template class AxisymmetricMembrane<2>;
template class AxisymmetricMembrane<3>;
template class AxisymmetricMembrane<4>;

std::unique_ptr<Element> makeAxisymmetricMembrane(std::vector<int> nodes, MembraneSection section,
                                                  int quadrature_points) {
  switch (nodes.size()) {
    case 2:
      return std::make_unique<AxisymmetricMembrane<2>>(std::move(nodes), std::move(section),
                                                       quadrature_points);
    case 3:
      return std::make_unique<AxisymmetricMembrane<3>>(std::move(nodes), std::move(section),
                                                       quadrature_points);
    case 4:
      return std::make_unique<AxisymmetricMembrane<4>>(std::move(nodes), std::move(section),
                                                       quadrature_points);
  }
  throw std::invalid_argument("an axisymmetric membrane element has 2, 3 or 4 nodes (got " +
                              std::to_string(nodes.size()) + ")");
}

HoopCable::HoopCable(int node, CableSection section)
    : Element({node}), section_(std::move(section)) {}

void HoopCable::internalForce(const ElementContext& c, Eigen::VectorXd& f,
                              Eigen::MatrixXd* K) const {
  const double r = c.reference(0, nodes()[0]);
  const double rho = r + c.state.displacement(0, nodes()[0]);
  const material::CableStress s = section_.material->stress(r * r, rho * rho);
  f.setZero(3);
  f(0) = s.T11 * rho * section_.area * r;  // per radian: T^11 rho A0 sqrt(a11)
  if (!K) return;
  K->setZero(3, 3);
  (*K)(0, 0) = section_.area * r * (s.T11 + s.C1111 * rho * rho);
}

void HoopCable::mass(const ElementContext& c, MassKind, Eigen::MatrixXd& M) const {
  M = section_.density * section_.area * c.reference(0, nodes()[0]) *
      Eigen::MatrixXd::Identity(3, 3);
}

void HoopCable::bodyLoad(const ElementContext& c, const Vector3d& g, Eigen::VectorXd& p) const {
  p = section_.density * section_.area * c.reference(0, nodes()[0]) * Vector3d(0.0, 0.0, g.z());
}

void HoopCable::result(const ElementContext& c, ElementResult& out) const {
  const double r = c.reference(0, nodes()[0]);
  const double rho = r + c.state.displacement(0, nodes()[0]);
  out.clear();
  const double tension = section_.material->tension(r * r, rho * rho, section_.area);
  out.point_tension.push_back(tension);
  out.end_tension[0] = out.end_tension[1] = tension;
}

}  // namespace flexmoor::element

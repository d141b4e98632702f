#include "libstruct/element/membrane_element.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

#include "libstruct/element/interpolated_point.hpp"
#include "libstruct/element/nodal_mass.hpp"
#include "libstruct/element/reference_jacobian.hpp"
#include "libstruct/shape/quad_shape.hpp"
#include "libstruct/shape/triangle_shape.hpp"

namespace flexmoor::element {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// Rows d(gamma_11, gamma_22, 2 gamma_12)/du^I of node I (Eq. 4.39): M^I,1 y,1; M^I,2 y,2;
// M^I,1 y,2 + M^I,2 y,1.
Matrix3d strainRows(const Eigen::Vector2d& dM, const Eigen::Matrix<double, 3, 2>& y) {
  Matrix3d B;
  B.row(0) = dM(0) * y.col(0).transpose();
  B.row(1) = dM(1) * y.col(1).transpose();
  B.row(2) = dM(0) * y.col(1).transpose() + dM(1) * y.col(0).transpose();
  return B;
}

Matrix3d skew(const Vector3d& v) {
  Matrix3d S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

}  // namespace

template <class Shape>
MembraneElement<Shape>::MembraneElement(std::vector<int> nodes, MembraneSection section,
                                        const shape::QuadratureRule2D& rule)
    : Element(std::move(nodes)),
      section_(std::move(section)),
      rule_(rule),
      shapes_(shape::ShapeTable<Shape>::of(rule)) {
  if (static_cast<int>(this->nodes().size()) != N)
    throw std::invalid_argument("membrane element node count does not match its shape");
}

template <class Shape>
std::string MembraneElement<Shape>::typeName() const {
  return "membrane" + std::to_string(N);
}

template <class Shape>
void MembraneElement<Shape>::gather(const ElementContext& c, Coordinates& X, Coordinates& Y) const {
  for (int I = 0; I < N; ++I) {
    const int n = nodes()[I];
    X.col(I) = c.reference.col(n);
    Y.col(I) = X.col(I) + c.state.displacement.col(n);
  }
}

template <class Shape>
void MembraneElement<Shape>::internalForce(const ElementContext& c, Eigen::VectorXd& f,
                                           Eigen::MatrixXd* K) const {
  Coordinates X, Y;
  gather(c, X, Y);
  NodalVector force = NodalVector::Zero();
  Tangent tangent;  // fixed size: the products below are unrolled, not general GEMM calls
  if (K) tangent.setZero();
  for (int q = 0; q < rule_.size(); ++q) {
    const typename Shape::Derivatives& dM = shapes_->derivatives[q];
    const Eigen::Matrix<double, 3, 2> x = X * dM, y = Y * dM;  // x,a and y,a
    const Matrix2d a = x.transpose() * x, A = y.transpose() * y;
    const material::MembraneStress s = section_.material->stress(a, A);
    const double dV = section_.thickness * std::sqrt(a.determinant()) * rule_.weights[q];
    // Eq. 3.17 / 4.29: F^I = int T^ab M^I,a y,b h0 sqrt(a)
    const Eigen::Matrix<double, 3, N> yTdM = dV * (y * (s.T * dM.transpose()));
    force += Eigen::Map<const NodalVector>(yTdM.data());
    if (!K) continue;
    // Eq. 4.39: geometric T^ab M^I,a M^J,b delta_ij + material B_I^T C B_J
    Eigen::Matrix<double, 3, 3 * N> B;
    for (int I = 0; I < N; ++I) B.template middleCols<3>(3 * I) = strainRows(dM.row(I), y);
    const Eigen::Matrix<double, 3, 3 * N> CB = dV * (s.C * B);
    // The upper triangle of B^T (C B), a column at a time (depth 3, no GEMM call); the tangent
    // is symmetric, its lower triangle is copied once at the end.
    const Eigen::Matrix<double, 3 * N, 3> Bt = B.transpose();
    for (int j = 0; j < 3 * N; ++j)
      tangent.col(j).head(j + 1).noalias() += Bt.topRows(j + 1) * CB.col(j);
    const Eigen::Matrix<double, N, N> G = dV * (dM * s.T * dM.transpose());
    for (int J = 0; J < N; ++J)
      for (int I = 0; I <= J; ++I)
        tangent.template block<3, 3>(3 * I, 3 * J).diagonal().array() += G(I, J);
  }
  f = force;
  if (!K) return;
  tangent.template triangularView<Eigen::StrictlyLower>() = tangent.transpose();
  *K = tangent;
}

template <class Shape>
typename MembraneElement<Shape>::AreaMatrix MembraneElement<Shape>::areaMatrix(
    const Coordinates& X) const {
  Eigen::Matrix<double, N, N> m = Eigen::Matrix<double, N, N>::Zero();
  for (int q = 0; q < rule_.size(); ++q) {
    const typename Shape::Values& Mv = shapes_->values[q];
    const Eigen::Matrix<double, 3, 2> x = X * shapes_->derivatives[q];
    const double dA = std::sqrt((x.transpose() * x).determinant()) * rule_.weights[q];
    m += dA * (Mv * Mv.transpose());
  }
  return m;
}

template <class Shape>
void MembraneElement<Shape>::mass(const ElementContext& c, MassKind kind,
                                  Eigen::MatrixXd& M) const {
  Coordinates X, Y;
  gather(c, X, Y);
  nodalMass<N>((section_.density * section_.thickness) * areaMatrix(X), kind, M);  // Eq. 4.40
}

template <class Shape>
Eigen::VectorXd MembraneElement<Shape>::nodalAreas(const model::NodalField& X) const {
  Coordinates Xe;
  for (int I = 0; I < N; ++I) Xe.col(I) = X.col(nodes()[I]);
  return lumpedDiagonal<N>(areaMatrix(Xe));
}

template <class Shape>
void MembraneElement<Shape>::bodyLoad(const ElementContext& c, const Vector3d& g,
                                      Eigen::VectorXd& p) const {
  Coordinates X, Y;
  gather(c, X, Y);
  p.setZero(3 * N);
  for (int q = 0; q < rule_.size(); ++q) {
    const typename Shape::Values& Mv = shapes_->values[q];
    const Eigen::Matrix<double, 3, 2> x = X * shapes_->derivatives[q];
    const double dA = std::sqrt((x.transpose() * x).determinant()) * rule_.weights[q];
    for (int I = 0; I < N; ++I)
      p.template segment<3>(3 * I) += (section_.density * section_.thickness * Mv(I) * dA) * g;
  }
}

template <class Shape>
void MembraneElement<Shape>::followerPressure(const ElementContext& c,
                                              const PressureField& pressure, Eigen::VectorXd& f,
                                              Eigen::MatrixXd* dfdu) const {
  Coordinates X, Y, V, A;
  gather(c, X, Y);
  for (int I = 0; I < N; ++I) {
    V.col(I) = c.state.velocity.col(nodes()[I]);
    A.col(I) = c.state.acceleration.col(nodes()[I]);
  }
  Coordinates load = Coordinates::Zero();  // column I: P^I
  // Row-major: the rows of node I are one contiguous block, updated by one axpy a point.
  Eigen::Matrix<double, 3 * N, 3 * N, Eigen::RowMajor> tangent;
  if (dfdu) tangent.setZero();
  for (int q = 0; q < rule_.size(); ++q) {
    const typename Shape::Values& Mv = shapes_->values[q];
    const typename Shape::Derivatives& dM = shapes_->derivatives[q];
    const Eigen::Matrix<double, 3, 2> y = Y * dM;
    model::LoadPoint point = interpolatedPoint(c, Y, V, A, Mv);
    const model::PointPressure p = pressure(point, dfdu != nullptr);
    const double w = p.pressure * rule_.weights[q];
    // Eq. 3.37: P^I = int p M^I (y,1 x y,2) dxi1 dxi2 (the cross product carries the area)
    const Vector3d n = y.col(0).cross(y.col(1));
    load.noalias() += (w * n) * Mv.transpose();
    if (!dfdu) continue;
    // d(y,1 x y,2)/du^J = M^J,1 (-[y,2]x) + M^J,2 [y,1]x, i.e. dn = dy,1 x y,2 + y,1 x dy,2;
    // the gradient part: dp/du^J = M^J (dp/dy)^T. Block (I, J) of dP/du is M^I dn_J.
    const Matrix3d S1 = skew(y.col(0)), S2 = skew(y.col(1));
    const Matrix3d n_grad = rule_.weights[q] * (n * p.d_position.transpose());
    Eigen::Matrix<double, 3, 3 * N, Eigen::RowMajor> dn;
    for (int J = 0; J < N; ++J)
      dn.template middleCols<3>(3 * J) = w * (-dM(J, 0) * S2 + dM(J, 1) * S1) + Mv(J) * n_grad;
    for (int I = 0; I < N; ++I) tangent.template middleRows<3>(3 * I) += Mv(I) * dn;
  }
  f = Eigen::Map<const NodalVector>(load.data());
  if (dfdu) *dfdu = tangent;
}

template <class Shape>
void MembraneElement<Shape>::result(const ElementContext& c, ElementResult& out) const {
  Coordinates X, Y;
  gather(c, X, Y);
  out.clear();
  for (int q = 0; q < rule_.size(); ++q) {
    const typename Shape::Derivatives& dM = shapes_->derivatives[q];
    const Eigen::Matrix<double, 3, 2> x = X * dM, y = Y * dM;
    const Matrix2d a = x.transpose() * x, A = y.transpose() * y;
    const material::MembraneStress s = section_.material->stress(a, A);
    // n = h sigma = h0 sqrt(a / A) T^ab y,a (x) y,b: force per unit current length
    out.point_resultant.push_back(section_.thickness *
                                  std::sqrt(a.determinant() / A.determinant()) *
                                  (y * s.T * y.transpose()));
  }
}

template <class Shape>
double MembraneElement<Shape>::minRelativeJacobian(const model::NodalField& X) const {
  Coordinates Xe;
  for (int I = 0; I < N; ++I) Xe.col(I) = X.col(nodes()[I]);
  return surfaceRelativeJacobian<Shape, N>(Xe, rule_.points);
}

template class MembraneElement<shape::QuadShape<4>>;
template class MembraneElement<shape::QuadShape<8>>;
template class MembraneElement<shape::QuadShape<12>>;
template class MembraneElement<shape::TriangleShape<3>>;
template class MembraneElement<shape::TriangleShape<6>>;
template class MembraneElement<shape::TriangleShape<10>>;

std::unique_ptr<Element> makeMembraneElement(const std::string& shape, std::vector<int> nodes,
                                             MembraneSection section, int quadrature) {
  const int n = static_cast<int>(nodes.size());
  if (shape == "quad") {
    const int order = quadrature > 0 ? quadrature : (n == 4 ? 2 : n == 8 ? 3 : 4);
    const auto& rule = shape::gaussLegendreQuad(order);
    switch (n) {
      case 4:
        return std::make_unique<MembraneElement<shape::QuadShape<4>>>(std::move(nodes),
                                                                      std::move(section), rule);
      case 8:
        return std::make_unique<MembraneElement<shape::QuadShape<8>>>(std::move(nodes),
                                                                      std::move(section), rule);
      case 12:
        return std::make_unique<MembraneElement<shape::QuadShape<12>>>(std::move(nodes),
                                                                       std::move(section), rule);
    }
  } else if (shape == "triangle") {
    const int degree = quadrature > 0 ? quadrature : (n == 3 ? 2 : n == 6 ? 4 : 6);
    const auto& rule = shape::triangleRule(degree);
    switch (n) {
      case 3:
        return std::make_unique<MembraneElement<shape::TriangleShape<3>>>(std::move(nodes),
                                                                          std::move(section), rule);
      case 6:
        return std::make_unique<MembraneElement<shape::TriangleShape<6>>>(std::move(nodes),
                                                                          std::move(section), rule);
      case 10:
        return std::make_unique<MembraneElement<shape::TriangleShape<10>>>(
            std::move(nodes), std::move(section), rule);
    }
  }
  throw std::invalid_argument(
      "membrane elements are quads of 4, 8, 12 nodes or triangles of 3, 6, "
      "10 nodes (got " +
      shape + " with " + std::to_string(n) + ")");
}

}  // namespace flexmoor::element

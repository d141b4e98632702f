#include "libstruct/element/cable_element.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "libstruct/element/axial_damping.hpp"
#include "libstruct/element/interpolated_point.hpp"
#include "libstruct/element/nodal_mass.hpp"
#include "libstruct/element/reference_jacobian.hpp"
#include "libstruct/shape/gauss_legendre.hpp"
#include "libstruct/shape/lagrange_1d.hpp"

namespace flexmoor::element {

using Eigen::Matrix3d;
using Eigen::Vector3d;

template <int N>
CableElement<N>::CableElement(std::vector<int> nodes, CableSection section, int quadrature_points)
    : Element(std::move(nodes)),
      section_(std::move(section)),
      rule_(shape::gaussLegendre(quadrature_points > 0 ? quadrature_points : N)) {
  if (static_cast<int>(this->nodes().size()) != N)
    throw std::invalid_argument("cable element node count does not match its order");
}

template <int N>
std::string CableElement<N>::typeName() const {
  return "cable" + std::to_string(N);
}

template <int N>
void CableElement<N>::gather(const ElementContext& c, Coordinates& X, Coordinates& Y) const {
  for (int I = 0; I < N; ++I) {
    const int n = nodes()[I];
    X.col(I) = c.reference.col(n);
    Y.col(I) = X.col(I) + c.state.displacement.col(n);
  }
}

template <int N>
void CableElement<N>::gatherVelocity(const ElementContext& c, Coordinates& V) const {
  for (int I = 0; I < N; ++I) V.col(I) = c.state.velocity.col(nodes()[I]);
}

template <int N>
double CableElement<N>::axialDamping(const Coordinates& X) const {
  if (section_.damping_ratio <= 0.0) return section_.axial_damping;
  double length = 0.0;  // unstretched, int |x,1| dxi
  for (int q = 0; q < rule_.size(); ++q)
    length += (X * shape::Lagrange1D<N>::derivatives(rule_.points[q])).norm() * rule_.weights[q];
  const double EA = section_.material->initialModulus() * section_.area;
  return dampingCoefficientOfRatio(section_.damping_ratio, length / (N - 1), EA,
                                   section_.density * section_.area);
}

template <int N>
bool CableElement<N>::hasDamping() const {
  return section_.axial_damping > 0.0 || section_.damping_ratio > 0.0;
}

// axial_damping.hpp: f_I = int BA d(lambda)/dt L^I,1 t dxi = int (BA / |x,1|) L^I,1 p dxi.
template <int N>
void CableElement<N>::dampingForce(const ElementContext& c, Eigen::VectorXd& f,
                                   LoadMatrices* J) const {
  using L = shape::Lagrange1D<N>;
  f.setZero(3 * N);
  if (J) J->setZero(3 * N);
  if (!hasDamping()) return;
  Coordinates X, Y, V;
  gather(c, X, Y);
  gatherVelocity(c, V);
  const double BA = axialDamping(X);
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector dL = L::derivatives(rule_.points[q]);
    const double weight = BA * rule_.weights[q] / (X * dL).norm();
    const AxialRate p = axialRate(Y * dL, V * dL);
    for (int I = 0; I < N; ++I) f.template segment<3>(3 * I) += (weight * dL(I)) * p.value;
    if (!J) continue;
    if (J->summed) {
      const Matrix3d sum = J->summed->stiffness * p.d_position + J->summed->damping * p.d_velocity;
      for (int I = 0; I < N; ++I)
        for (int K = 0; K < N; ++K)
          J->stiffness.template block<3, 3>(3 * I, 3 * K) += (weight * dL(I) * dL(K)) * sum;
      continue;
    }
    for (int I = 0; I < N; ++I)
      for (int K = 0; K < N; ++K) {
        const double w = weight * dL(I) * dL(K);
        J->stiffness.template block<3, 3>(3 * I, 3 * K) += w * p.d_position;
        J->damping.template block<3, 3>(3 * I, 3 * K) += w * p.d_velocity;
      }
  }
}

template <int N>
void CableElement<N>::internalForce(const ElementContext& c, Eigen::VectorXd& f,
                                    Eigen::MatrixXd* K) const {
  using L = shape::Lagrange1D<N>;
  Coordinates X, Y;
  gather(c, X, Y);
  f.setZero(3 * N);
  if (K) K->setZero(3 * N, 3 * N);
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector dL = L::derivatives(rule_.points[q]);
    const Vector3d x1 = X * dL;  // x,1
    const Vector3d y1 = Y * dL;  // y,1
    const double a11 = x1.squaredNorm();
    const double A11 = y1.squaredNorm();
    const material::CableStress s = section_.material->stress(a11, A11);
    const double dV = section_.area * std::sqrt(a11) * rule_.weights[q];
    // Eq. 3.29 / 4.42: F^I_i = int T^11 L^I,1 y_i,1 A0 sqrt(a11) dxi
    for (int I = 0; I < N; ++I) f.template segment<3>(3 * I) += (s.T11 * dL(I) * dV) * y1;
    if (!K) continue;
    // Eq. 4.48: geometric part T^11 L^I,1 L^J,1 delta_ij, material part C^1111 (L^I,1 y,1)(L^J,1 y,1)
    const Matrix3d material_part = s.C1111 * dV * (y1 * y1.transpose());
    for (int I = 0; I < N; ++I)
      for (int J = 0; J < N; ++J) {
        auto block = K->template block<3, 3>(3 * I, 3 * J);
        block += dL(I) * dL(J) * material_part;
        block.diagonal().array() += s.T11 * dL(I) * dL(J) * dV;
      }
  }
}

template <int N>
void CableElement<N>::mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const {
  using L = shape::Lagrange1D<N>;
  Coordinates X, Y;
  gather(c, X, Y);
  Eigen::Matrix<double, N, N> m = Eigen::Matrix<double, N, N>::Zero();
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector Lv = L::values(rule_.points[q]);
    const double ds0 = (X * L::derivatives(rule_.points[q])).norm() * rule_.weights[q];
    m += (section_.density * section_.area * ds0) * (Lv * Lv.transpose());  // Eq. 4.49
  }
  nodalMass<N>(m, kind, M);
}

template <int N>
void CableElement<N>::bodyLoad(const ElementContext& c, const Vector3d& g,
                               Eigen::VectorXd& p) const {
  using L = shape::Lagrange1D<N>;
  Coordinates X, Y;
  gather(c, X, Y);
  p.setZero(3 * N);
  for (int q = 0; q < rule_.size(); ++q) {
    const typename L::Vector Lv = L::values(rule_.points[q]);
    const double ds0 = (X * L::derivatives(rule_.points[q])).norm() * rule_.weights[q];
    for (int I = 0; I < N; ++I)
      p.template segment<3>(3 * I) += (section_.density * section_.area * Lv(I) * ds0) * g;
  }
}

template <int N>
bool CableElement<N>::lineLoad(const ElementContext& c, const model::LineLoad& load,
                               Eigen::VectorXd& p, LoadMatrices* J) const {
  using L = shape::Lagrange1D<N>;
  Coordinates X, Y;
  gather(c, X, Y);
  Eigen::Matrix<double, 3, N> V, A;
  for (int I = 0; I < N; ++I) {
    V.col(I) = c.state.velocity.col(nodes()[I]);
    A.col(I) = c.state.acceleration.col(nodes()[I]);
  }
  p.setZero(3 * N);
  if (J) J->setZero(3 * N);
  const bool per_current_length = load.measure() == model::LengthMeasure::Current;
  bool acts = false;  // a point with a force or a derivative
  for (int q = 0; q < rule_.size(); ++q) {
    const double xi = rule_.points[q];
    const typename L::Vector Lv = L::values(xi);
    const typename L::Vector dL = L::derivatives(xi);
    const Vector3d y1 = Y * dL;
    const double y1_norm = y1.norm();
    const double x1_norm = (X * dL).norm();
    model::LoadPoint point = interpolatedPoint(c, Y, V, A, Lv);
    point.tangent = y1 / y1_norm;
    point.stretch = y1_norm / x1_norm;
    const model::PointForce f = load.evaluate(point, J != nullptr);
    if (f.force.isZero(0.0) && (!J || (f.d_position.isZero(0.0) && f.d_tangent.isZero(0.0) &&
                                       f.d_velocity.isZero(0.0) && f.d_acceleration.isZero(0.0))))
      continue;  // nothing at this point
    acts = true;
    // Eq. E.1, E.12: the load per length times the length element, |y,1| dxi on the deformed
    // line (the dissertation) or |x,1| dxi on the unstretched one (MoorDyn).
    const double ds = (per_current_length ? y1_norm : x1_norm) * rule_.weights[q];
    for (int I = 0; I < N; ++I) p.template segment<3>(3 * I) += (Lv(I) * ds) * f.force;
    if (!J) continue;
    // d(ds f)/dy,1 = ds df/dt dt/dy,1 + f d(ds)/dy,1, with dt/dy,1 = (I - t t^T) / |y,1| and
    // d(ds)/dy,1 = t^T dxi on the deformed line (zero on the unstretched one).
    Matrix3d d_axis =
        (ds / y1_norm) * (f.d_tangent - (f.d_tangent * point.tangent) * point.tangent.transpose());
    if (per_current_length) d_axis += (rule_.weights[q] * f.force) * point.tangent.transpose();
    const Matrix3d d_position = ds * f.d_position;
    // The force at the point depends on node K through y = sum L_K y_K and y,1 = sum L_K' y_K.
    std::array<Matrix3d, N> by_node;
    for (int K = 0; K < N; ++K) by_node[K] = Lv(K) * d_position + dL(K) * d_axis;
    if (J->summed) {
      // k (-dp/du) + c (-dp/du') + m (-dp/du''): node K's share L_I (k by_node[K] + L_K ds
      // (c df/du' + m df/du'')).
      const LoadMatrices::Weights& w = *J->summed;
      const Matrix3d rates = ds * (w.damping * f.d_velocity + w.mass * f.d_acceleration);
      for (int K = 0; K < N; ++K) by_node[K] = w.stiffness * by_node[K] + Lv(K) * rates;
      for (int I = 0; I < N; ++I)
        for (int K = 0; K < N; ++K)
          J->stiffness.template block<3, 3>(3 * I, 3 * K) -= Lv(I) * by_node[K];
      continue;
    }
    for (int I = 0; I < N; ++I)
      for (int K = 0; K < N; ++K)
        J->stiffness.template block<3, 3>(3 * I, 3 * K) -= Lv(I) * by_node[K];
    // Damping and added mass: N_I N_K ds times df/du' and df/du'' (skipped when zero, a seabed's
    // added mass).
    for (auto [d, out] :
         {std::pair{&f.d_velocity, &J->damping}, std::pair{&f.d_acceleration, &J->mass}}) {
      if (d->isZero(0.0)) continue;
      const Matrix3d weighted = ds * *d;
      for (int I = 0; I < N; ++I)
        for (int K = 0; K < N; ++K)
          out->template block<3, 3>(3 * I, 3 * K) -= (Lv(I) * Lv(K)) * weighted;
    }
  }
  return acts;
}

template <int N>
double CableElement<N>::axialForce(const Coordinates& X, const Coordinates& Y, const Coordinates& V,
                                   double BA, double xi) const {
  const typename shape::Lagrange1D<N>::Vector dL = shape::Lagrange1D<N>::derivatives(xi);
  const Vector3d x1 = X * dL, y1 = Y * dL;
  const double elastic =
      section_.material->tension(x1.squaredNorm(), y1.squaredNorm(), section_.area);
  if (BA == 0.0) return elastic;
  return elastic + BA * y1.dot(V * dL) / (x1.norm() * y1.norm());  // axial_damping.hpp
}

template <int N>
void CableElement<N>::result(const ElementContext& c, ElementResult& out) const {
  Coordinates X, Y, V = Coordinates::Zero();
  gather(c, X, Y);
  const double BA = hasDamping() ? axialDamping(X) : 0.0;
  if (BA != 0.0) gatherVelocity(c, V);
  out.clear();
  for (int q = 0; q < rule_.size(); ++q)
    out.point_tension.push_back(axialForce(X, Y, V, BA, rule_.points[q]));
}

template <int N>
double CableElement<N>::axialForceAt(const ElementContext& c, double xi) const {
  Coordinates X, Y, V = Coordinates::Zero();
  gather(c, X, Y);
  const double BA = hasDamping() ? axialDamping(X) : 0.0;
  if (BA != 0.0) gatherVelocity(c, V);
  return axialForce(X, Y, V, BA, xi);
}

template <int N>
double CableElement<N>::minRelativeJacobian(const model::NodalField& X) const {
  Coordinates Xe;
  for (int I = 0; I < N; ++I) Xe.col(I) = X.col(nodes()[I]);
  std::vector<double> xi = rule_.points;
  xi.push_back(-1.0);
  xi.push_back(1.0);
  return lineRelativeJacobian<N>(Xe, xi);
}

template class CableElement<2>;
template class CableElement<3>;
template class CableElement<4>;

std::unique_ptr<Element> makeCableElement(std::vector<int> nodes, CableSection section,
                                          int quadrature_points) {
  switch (nodes.size()) {
    case 2:
      return std::make_unique<CableElement<2>>(std::move(nodes), std::move(section),
                                               quadrature_points);
    case 3:
      return std::make_unique<CableElement<3>>(std::move(nodes), std::move(section),
                                               quadrature_points);
    case 4:
      return std::make_unique<CableElement<4>>(std::move(nodes), std::move(section),
                                               quadrature_points);
    default:
      throw std::invalid_argument("a cable element has 2, 3 or 4 nodes (got " +
                                  std::to_string(nodes.size()) + ")");
  }
}

}  // namespace flexmoor::element

#include "tests/support/dynamic_models.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"
#include "libstruct/element/spring_element.hpp"
#include "libstruct/material/membrane_material.hpp"
#include "libstruct/shape/quad_shape.hpp"
#include "libstruct/shape/triangle_shape.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"
#include "tests/support/cable_models.hpp"
#include "tests/support/scalar_root.hpp"

namespace flexmoor::test {

namespace {

const double kPi = std::acos(-1.0);

// Newton to a tight equilibrium at load factor 1 (residual only: the displacement norm of Eq. 5.1
// is meaningless for dofs that do not move).
solve::StaticOptions tightStatics() {
  solve::StaticOptions o;
  o.load_factor = 1.0;
  o.increments = 1;
  o.flavour = solve::NewtonFlavour::Full;
  o.convergence.use_displacement = false;
  o.convergence.residual_tolerance = 1e-10;
  return o;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Linear oscillators

SpringChain makeSpringChain(const std::vector<double>& masses,
                            const std::vector<double>& stiffnesses) {
  const int n = static_cast<int>(masses.size());
  const int springs = static_cast<int>(stiffnesses.size());
  if (n < 1 || (springs != n && springs != n + 1))
    throw std::invalid_argument("makeSpringChain: one spring per mass, or one more");
  SpringChain chain;
  chain.model = std::make_unique<model::Model>();
  model::Model& m = *chain.model;
  std::vector<int> line{m.addNode(Eigen::Vector3d::Zero())};
  pin(m, line.front());
  for (int i = 0; i < n; ++i) {
    const int node = m.addNode(Eigen::Vector3d(i + 1.0, 0.0, 0.0));
    m.addElement(std::make_unique<element::PointMassElement>(node, masses[i]));
    m.constrain(node, 1);
    m.constrain(node, 2);
    chain.masses.push_back(node);
    line.push_back(node);
  }
  if (springs == n + 1) {
    line.push_back(m.addNode(Eigen::Vector3d(n + 1.0, 0.0, 0.0)));
    pin(m, line.back());
  }
  for (int s = 0; s < springs; ++s)
    m.addElement(std::make_unique<element::SpringElement>(line[s], line[s + 1], stiffnesses[s],
                                                          -1.0, material::Compression::Carry));
  m.numberEquations();
  return chain;
}

SchemeConstants schemeConstants(const solve::DynamicOptions& o) {
  if (o.hht_alpha == 0.0) return {o.gamma, o.beta, 0.0};
  const double a = o.hht_alpha;
  return {0.5 - a, 0.25 * (1.0 - a) * (1.0 - a), a};
}

Eigen::Matrix3d amplificationMatrix(const SchemeConstants& p, double omega_dt, double damping_dt) {
  // Scaled state s = (x, dt v, dt^2 a): the step is independent of dt once W = omega dt and
  // c = 2 zeta omega dt are fixed. Solve the equation of motion at n + 1 for a_{n+1}, then update.
  const double W2 = omega_dt * omega_dt, c = damping_dt, g = p.gamma, b = p.beta, al = p.alpha;
  const double D = 1.0 + (1.0 + al) * (g * c + b * W2);
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    s(j) = 1.0;
    const double x = s(0), v = s(1), a = s(2);
    const double a1 = (-(1.0 + al) * (W2 * (x + v + (0.5 - b) * a) + c * (v + (1.0 - g) * a)) +
                       al * (W2 * x + c * v)) /
                      D;
    A.col(j) << x + v + (0.5 - b) * a + b * a1, v + (1.0 - g) * a + g * a1, a1;
  }
  return A;
}

double spectralRadius(const Eigen::Matrix3d& A) { return A.eigenvalues().cwiseAbs().maxCoeff(); }

double trapezoidalPeriodRatio(double omega_dt) {
  return 0.5 * omega_dt / std::atan(0.5 * omega_dt);
}

std::vector<double> zeroCrossings(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> crossings;
  for (size_t k = 0; k + 1 < x.size(); ++k)
    if ((x[k] >= 0.0) != (x[k + 1] >= 0.0))
      crossings.push_back(t[k] + (t[k + 1] - t[k]) * x[k] / (x[k] - x[k + 1]));
  return crossings;
}

double periodFromCrossings(const std::vector<double>& crossings) {
  const int n = static_cast<int>(crossings.size());
  if (n < 2) throw std::invalid_argument("periodFromCrossings: need two crossings");
  const double i_mean = 0.5 * (n - 1);
  double t_mean = 0.0;
  for (double c : crossings) t_mean += c / n;
  double sxy = 0.0, sxx = 0.0;
  for (int i = 0; i < n; ++i) {
    sxy += (i - i_mean) * (crossings[i] - t_mean);
    sxx += (i - i_mean) * (i - i_mean);
  }
  return 2.0 * sxy / sxx;
}

// ---------------------------------------------------------------------------------------------
// Taut cable

TautCable makeTautCable(const TautCableInputs& in) {
  TautCable cable;
  cable.inputs = in;
  cable.model = std::make_unique<model::Model>();
  model::Model& m = *cable.model;
  const int left = m.addNode(Eigen::Vector3d::Zero());
  const int right = m.addNode(Eigen::Vector3d(in.length, 0.0, 0.0));
  cable.nodes = addStraightCable(
      m, left, right, in.elements, in.nodes_per_element,
      linearElasticSection(in.youngs_modulus, in.area, in.density, material::Compression::Carry));
  pin(m, left);
  m.constrain(right, 1);
  m.constrain(right, 2);
  if (in.right_end == TautCableInputs::RightEnd::PrescribedStretch)
    m.constrain(right, 0, (in.stretch - 1.0) * in.length);
  else
    m.addNodalLoad(right, Eigen::Vector3d(in.tension(), 0.0, 0.0));
  if (in.planar)
    for (int n : cable.nodes) m.constrain(n, 1);
  m.numberEquations();
  return cable;
}

model::State pretension(const TautCable& cable, const model::Assembler& assembler) {
  model::State state = cable.model->initialState();
  solve::solveStatic(assembler, state, tightStatics());
  return state;
}

double linearStringFrequency(int elements, int k, double tension, double mass_per_length,
                             double length) {
  const double h = length / elements;
  const double c = std::cos(k * kPi / elements);
  return std::sqrt(6.0 * tension / (mass_per_length * h * h) * (1.0 - c) / (2.0 + c));
}

// ---------------------------------------------------------------------------------------------
// Mode selection

double componentFraction(const model::NodalField& shape, int component) {
  const double total = shape.squaredNorm();
  return total > 0.0 ? shape.row(component).squaredNorm() / total : 0.0;
}

std::vector<int> modesAlong(const solve::ModalResult& modes, const std::vector<int>& components) {
  std::vector<int> selected;
  for (int k = 0; k < static_cast<int>(modes.shapes.size()); ++k) {
    double fraction = 0.0;
    for (int c : components) fraction += componentFraction(modes.shapes[k], c);
    if (fraction > 0.999) selected.push_back(k);
  }
  return selected;
}

// ---------------------------------------------------------------------------------------------
// Sagging cable

SaggingCable makeSaggingCable(const SaggingCableInputs& in) {
  if (in.span >= in.length) throw std::invalid_argument("a sagging cable needs span < length");
  SaggingCable cable;
  cable.inputs = in;
  cable.model = std::make_unique<model::Model>();
  model::Model& m = *cable.model;
  // Circular arc of half-angle phi: chord 2 R sin(phi) = span, length 2 R phi = L0.
  const double ratio = in.span / in.length;
  const double phi = findRoot([&](double p) { return std::sin(p) / p - ratio; }, 1e-6, kPi);
  const double R = 0.5 * in.length / phi;
  const int intervals = in.elements * (in.nodes_per_element - 1);
  for (int k = 0; k <= intervals; ++k) {
    const double theta = -phi + 2.0 * phi * k / intervals;
    cable.nodes.push_back(m.addNode(Eigen::Vector3d(0.5 * in.span + R * std::sin(theta), 0.0,
                                                    R * (std::cos(phi) - std::cos(theta)))));
  }
  // The end nodes sit exactly on the supports.
  const element::CableSection section =
      linearElasticSection(in.youngs_modulus, in.area, in.density, material::Compression::Carry);
  for (int e = 0; e < in.elements; ++e) {
    const auto begin = cable.nodes.begin() + e * (in.nodes_per_element - 1);
    m.addElement(
        element::makeCableElement(std::vector<int>(begin, begin + in.nodes_per_element), section));
  }
  pin(m, cable.nodes.front());
  pin(m, cable.nodes.back());
  m.setGravity(Eigen::Vector3d(0.0, 0.0, -in.gravity));
  m.numberEquations();
  return cable;
}

model::State hangSaggingCable(const SaggingCable& cable, const model::Assembler& assembler) {
  model::State state = cable.model->initialState();
  solve::RelaxationOptions relax;
  relax.damping = cable.inputs.youngs_modulus * cable.inputs.area / cable.inputs.length;
  relax.tolerance = 1e-6;
  solve::relax(assembler, state, relax);
  solve::solveStatic(assembler, state, tightStatics());
  return state;
}

namespace {

// This file's own Gauss-Legendre rules (n = 2, 3, 4 points) and equally spaced Lagrange
// polynomials on [-1, 1], independent of libstruct/shape.
struct Rule {
  std::vector<double> x, w;
};

Rule gaussRule(int n) {
  switch (n) {
    case 2:
      return {{-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}, {1.0, 1.0}};
    case 3:
      return {{-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
    case 4: {
      const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
      const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
      const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
      return {{-b, -a, a, b}, {wb, wa, wa, wb}};
    }
  }
  throw std::invalid_argument("gaussRule: 2, 3 or 4 points");
}

// Values and derivatives of the n Lagrange polynomials through -1 + 2 i / (n - 1).
void lagrange(int n, double xi, std::vector<double>& L, std::vector<double>& dL) {
  std::vector<double> node(n);
  for (int i = 0; i < n; ++i) node[i] = -1.0 + 2.0 * i / (n - 1);
  L.assign(n, 1.0);
  dL.assign(n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      // product rule: d/dxi of prod_j (xi - x_j) / (x_i - x_j)
      dL[i] = dL[i] * (xi - node[j]) / (node[i] - node[j]) + L[i] / (node[i] - node[j]);
      L[i] *= (xi - node[j]) / (node[i] - node[j]);
    }
}

}  // namespace

CablePotential cablePotential(const SaggingCable& cable, const model::State& state) {
  const SaggingCableInputs& in = cable.inputs;
  const int p = in.nodes_per_element;
  const Rule rule = gaussRule(p);
  const model::NodalField& X = cable.model->reference();
  CablePotential energy;
  std::vector<double> L, dL;
  for (int e = 0; e < in.elements; ++e)
    for (size_t q = 0; q < rule.x.size(); ++q) {
      lagrange(p, rule.x[q], L, dL);
      Eigen::Vector3d x1 = Eigen::Vector3d::Zero(), y1 = Eigen::Vector3d::Zero(),
                      y = Eigen::Vector3d::Zero();
      for (int I = 0; I < p; ++I) {
        const int n = cable.nodes[e * (p - 1) + I];
        const Eigen::Vector3d yI = X.col(n) + state.displacement.col(n);
        x1 += dL[I] * X.col(n);
        y1 += dL[I] * yI;
        y += L[I] * yI;
      }
      const double a11 = x1.squaredNorm();
      const double green = 0.5 * (y1.squaredNorm() / a11 - 1.0);  // (lambda^2 - 1) / 2
      const double dV = in.area * std::sqrt(a11) * rule.w[q];
      energy.strain += 0.5 * in.youngs_modulus * green * green * dV;
      energy.gravity += in.density * in.gravity * y.z() * dV;
    }
  return energy;
}

// ---------------------------------------------------------------------------------------------
// Free-floating truss

std::unique_ptr<model::Model> makeFreeTruss(int nx, int ny, int nz) {
  auto m = std::make_unique<model::Model>();
  const auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) m->addNode(Eigen::Vector3d(i, j, k));
  const element::CableSection bar =
      linearElasticSection(1.0e3, 1.0, 1.0, material::Compression::Carry);
  const auto add = [&](int a, int b) { m->addElement(element::makeCableElement({a, b}, bar)); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const bool xi = i + 1 < nx, yj = j + 1 < ny, zk = k + 1 < nz;
        if (xi) add(id(i, j, k), id(i + 1, j, k));  // edges
        if (yj) add(id(i, j, k), id(i, j + 1, k));
        if (zk) add(id(i, j, k), id(i, j, k + 1));
        if (xi && yj) add(id(i, j, k), id(i + 1, j + 1, k));  // face diagonals
        if (yj && zk) add(id(i, j, k), id(i, j + 1, k + 1));
        if (xi && zk) add(id(i, j, k), id(i + 1, j, k + 1));
        if (xi && yj && zk) add(id(i, j, k), id(i + 1, j + 1, k + 1));  // body diagonal
      }
  m->numberEquations();
  return m;
}

// ---------------------------------------------------------------------------------------------
// Square membrane

double SquareMembraneInputs::exactFrequency(int m, int n) const {
  return kPi * std::sqrt(secondPiola() / density) * std::sqrt(double(m * m + n * n)) / side;
}

namespace {

using Element = SquareMembraneInputs::Element;

int nodeIntervals(Element e) {  // node intervals per cell edge
  switch (e) {
    case Element::Quad4:
      return 1;
    case Element::Quad8:
      return 2;
    case Element::Quad12:
      return 3;
    case Element::Triangle6:
      return 2;
  }
  return 1;
}

// Grid offsets of a quad's nodes in the library's node order (QuadShape<N>::node), on a cell of
// p node intervals per edge.
template <int N>
std::vector<std::pair<int, int>> quadOffsets(int p) {
  std::vector<std::pair<int, int>> offsets;
  for (int k = 0; k < N; ++k) {
    const Eigen::Vector2d xi = shape::QuadShape<N>::node(k);
    offsets.emplace_back(static_cast<int>(std::lround(0.5 * (xi.x() + 1.0) * p)),
                         static_cast<int>(std::lround(0.5 * (xi.y() + 1.0) * p)));
  }
  return offsets;
}

}  // namespace

SquareMembrane makeSquareMembrane(const SquareMembraneInputs& in) {
  SquareMembrane membrane;
  membrane.inputs = in;
  membrane.model = std::make_unique<model::Model>();
  model::Model& m = *membrane.model;
  const int p = nodeIntervals(in.element);
  const int G = in.divisions * p;  // node intervals along a side
  const bool serendipity = in.element == Element::Quad8 || in.element == Element::Quad12;
  std::map<std::pair<int, int>, int> id;
  for (int j = 0; j <= G; ++j)
    for (int i = 0; i <= G; ++i) {
      if (serendipity && i % p != 0 && j % p != 0) continue;  // no nodes inside a cell
      const double x = in.side * i / G, y = in.side * j / G;
      const int n = m.addNode(Eigen::Vector3d(x, y, 0.0));
      id[{i, j}] = n;
      if (i == 0 || j == 0 || i == G || j == G) {
        m.constrain(n, 0, in.strain * x);
        m.constrain(n, 1, in.strain * y);
        m.constrain(n, 2);
      }
    }
  const element::MembraneSection section{
      in.thickness, in.density,
      std::make_shared<material::LinearElasticPlaneStress>(in.youngs_modulus, in.poisson)};
  const auto node = [&](int i, int j) { return id.at({i, j}); };
  for (int cj = 0; cj < in.divisions; ++cj)
    for (int ci = 0; ci < in.divisions; ++ci) {
      const int i0 = ci * p, j0 = cj * p;
      if (in.element != Element::Triangle6) {
        const std::vector<std::pair<int, int>> offsets =
            in.element == Element::Quad4   ? quadOffsets<4>(p)
            : in.element == Element::Quad8 ? quadOffsets<8>(p)
                                           : quadOffsets<12>(p);
        std::vector<int> nodes;
        for (const auto& [di, dj] : offsets) nodes.push_back(node(i0 + di, j0 + dj));
        m.addElement(element::makeMembraneElement("quad", nodes, section));
        continue;
      }
      // Two T6 per cell; the diagonal runs through the cell corner nearest the square's centre.
      const std::pair<int, int> bl{i0, j0}, br{i0 + 2, j0}, tr{i0 + 2, j0 + 2}, tl{i0, j0 + 2};
      const bool rising = (2 * (i0 + 1) - G) * (2 * (j0 + 1) - G) > 0;  // "/" diagonal
      const std::vector<std::array<std::pair<int, int>, 3>> triangles =
          rising ? std::vector<std::array<std::pair<int, int>, 3>>{{bl, br, tr}, {bl, tr, tl}}
                 : std::vector<std::array<std::pair<int, int>, 3>>{{bl, br, tl}, {br, tr, tl}};
      for (const auto& t : triangles) {
        std::vector<int> nodes;
        for (int k = 0; k < 6; ++k) {
          const Eigen::Vector2d rs = shape::TriangleShape<6>::node(k);  // in {0, 1/2, 1}
          const int i =
              t[0].first + static_cast<int>(std::lround(rs.x() * (t[1].first - t[0].first) +
                                                        rs.y() * (t[2].first - t[0].first)));
          const int j =
              t[0].second + static_cast<int>(std::lround(rs.x() * (t[1].second - t[0].second) +
                                                         rs.y() * (t[2].second - t[0].second)));
          nodes.push_back(node(i, j));
        }
        m.addElement(element::makeMembraneElement("triangle", nodes, section));
      }
    }
  m.numberEquations();
  return membrane;
}

model::State prestress(const SquareMembrane& membrane, const model::Assembler& assembler) {
  model::State state = membrane.model->initialState();
  solve::solveStatic(assembler, state, tightStatics());
  return state;
}

}  // namespace flexmoor::test

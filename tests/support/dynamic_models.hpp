#pragma once
// Models and closed forms for the dynamics and frequency tests, built in code:
//  - linear oscillators (point masses on axial springs) and the exact recurrence of the
//    Newmark / HHT-alpha scheme applied to one mode;
//  - a taut straight cable (uniform pretension), with the closed-form frequencies of a string of
//    consistent-mass linear elements;
//  - a sagging cable pinned at both ends, with its energy evaluated independently of libstruct;
//  - a free-floating truss (rigid-body modes);
//  - a flat square membrane under uniform isotropic prestress, meshed with Q4, Q8, Q12 or T6.
// Everything a test compares against is computed here from its own formula, never from the
// library's output.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "libstruct/model/assembler.hpp"
#include "libstruct/model/model.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::test {

// ---------------------------------------------------------------------------------------------
// Linear oscillators.

// Point masses masses[i] on the x axis at x = i + 1, joined by axial springs (SpringElement,
// Compression::Carry, rest length = reference spacing, so unstressed at rest): spring 0 from a
// fixed node at x = 0 to mass 0, spring i from mass i - 1 to mass i, and, when there is one more
// stiffness than masses, a last spring from the last mass to a fixed node. Every y and z dof is
// fixed, so each mass moves along x only, where a spring's force k (l - l0) is exactly linear in
// the displacements (as long as no spring is crushed to zero length).
struct SpringChain {
  std::unique_ptr<model::Model> model;  // equations numbered
  std::vector<int> masses;              // node of each mass, left to right
};

SpringChain makeSpringChain(const std::vector<double>& masses,
                            const std::vector<double>& stiffnesses);

// The scheme's constants as the integrator uses them: gamma, beta of Newmark and alpha of HHT
// (alpha = 0: plain Newmark). For alpha != 0, gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4.
struct SchemeConstants {
  double gamma = 0.5;
  double beta = 0.25;
  double alpha = 0.0;
};
SchemeConstants schemeConstants(const solve::DynamicOptions& options);

// One step of the scheme applied to x'' + 2 zeta omega x' + omega^2 x = 0 (Hilber, Hughes &
// Taylor 1977), as a linear map of the scaled state (x, dt x', dt^2 x''):
//   x''_{n+1} + (1 + alpha)(2 zeta omega x'_{n+1} + omega^2 x_{n+1})
//                                           - alpha (2 zeta omega x'_n + omega^2 x_n) = 0,
//   x_{n+1} = x_n + dt x'_n + dt^2 [(1/2 - beta) x''_n + beta x''_{n+1}],
//   x'_{n+1} = x'_n + dt [(1 - gamma) x''_n + gamma x''_{n+1}].
// omega_dt = omega dt; damping_dt = 2 zeta omega dt.
Eigen::Matrix3d amplificationMatrix(const SchemeConstants& scheme, double omega_dt,
                                    double damping_dt = 0.0);

// Spectral radius of the amplification matrix.
double spectralRadius(const Eigen::Matrix3d& A);

// The period elongation of the trapezoidal rule (gamma = 1/2, beta = 1/4) on an undamped
// oscillator: its numerical frequency satisfies tan(omega_h dt / 2) = omega dt / 2, so
// T_num / T = (omega dt / 2) / atan(omega dt / 2).
double trapezoidalPeriodRatio(double omega_dt);

// Zero crossings of a sampled signal (t_k, x_k), each by linear interpolation between the two
// samples of opposite sign around it.
std::vector<double> zeroCrossings(const std::vector<double>& t, const std::vector<double>& x);

// The period from a run of consecutive zero crossings: twice the least-squares slope of crossing
// time against crossing index (a fit, so the interpolation error of single crossings, which
// changes sign with the sampling phase, averages out).
double periodFromCrossings(const std::vector<double>& crossings);

// ---------------------------------------------------------------------------------------------
// Taut cable: a straight cable along +x from the origin, unstretched length L0, linear-elastic
// (S = E (lambda^2 - 1) / 2, Eq. 2.53, Compression::Carry), pretensioned to a uniform stretch
// lambda. The left end is pinned; the right end has y and z fixed and either a prescribed x
// displacement (lambda - 1) L0 (applied at load factor 1) or a horizontal roller pulled by the
// force T = S lambda A0 in +x.
struct TautCableInputs {
  enum class RightEnd { PrescribedStretch, Roller };
  int elements = 12;
  int nodes_per_element = 2;
  double length = 1.0;  // L0
  double youngs_modulus = 1.0e4;
  double area = 1.0;
  double density = 1.0;
  double stretch = 1.001;  // lambda
  bool planar = false;     // every y dof fixed
  RightEnd right_end = RightEnd::PrescribedStretch;

  double secondPiola() const { return 0.5 * youngs_modulus * (stretch * stretch - 1.0); }
  double tension() const { return secondPiola() * stretch * area; }  // N = S lambda A0
  double stretchedLength() const { return stretch * length; }        // L
  double massPerLength() const { return density * area / stretch; }  // m, per current length
  // Incremental axial stiffness per unit reference volume, d(N / A0) / d lambda = E lambda^2 + S.
  double axialModulus() const { return youngs_modulus * stretch * stretch + secondPiola(); }
};

struct TautCable {
  std::unique_ptr<model::Model> model;  // equations numbered
  std::vector<int> nodes;               // along the cable, left to right
  TautCableInputs inputs;
};

TautCable makeTautCable(const TautCableInputs& inputs);

// The pretensioned state: a static Newton solve to load factor 1, converged to a residual of
// 1e-10. The exact solution is the uniform stretch u = (lambda - 1) x along the cable.
model::State pretension(const TautCable& cable, const model::Assembler& assembler);

// Frequency of mode k of a taut string of n consistent-mass linear elements, fixed ends
// (tension T, mass per length m, element length h = L / n):
//   omega_k^2 = (6 T / (m h^2)) (1 - cos(k pi / n)) / (2 + cos(k pi / n)).
// The same formula with T replaced by the incremental axial stiffness gives the axial modes.
double linearStringFrequency(int elements, int k, double tension, double mass_per_length,
                             double length);

// ---------------------------------------------------------------------------------------------
// Mode selection. The fraction of a mode shape's squared amplitude carried by component
// `component` (0, 1, 2 = x, y, z) over all nodes.
double componentFraction(const model::NodalField& shape, int component);

// Indices of the modes of `modes` whose shape lies in the components listed (fraction > 0.999).
std::vector<int> modesAlong(const solve::ModalResult& modes, const std::vector<int>& components);

// ---------------------------------------------------------------------------------------------
// Sagging cable: `elements` cable elements of `nodes_per_element` nodes, linear-elastic
// (Compression::Carry), pinned at both ends at (0, 0, 0) and (span, 0, 0), gravity g in -z. The
// reference (unstressed) geometry is a circular arc of length L0 through both supports, sagging
// in -z, with the nodes equally spaced along it.
struct SaggingCableInputs {
  int elements = 8;
  int nodes_per_element = 3;
  double length = 10.0;  // L0
  double span = 8.0;
  double youngs_modulus = 2.0e4;
  double area = 1.0;
  double density = 1.0;
  double gravity = 10.0;
};

struct SaggingCable {
  std::unique_ptr<model::Model> model;  // equations numbered
  std::vector<int> nodes;               // along the cable
  SaggingCableInputs inputs;
};

SaggingCable makeSaggingCable(const SaggingCableInputs& inputs);

// Static equilibrium under gravity (load factor 1): viscous relaxation from the unstressed arc,
// then Newton to a residual of 1e-10.
model::State hangSaggingCable(const SaggingCable& cable, const model::Assembler& assembler);

// Potential energy of the cable at a state, evaluated here with this file's own Lagrange shape
// functions and Gauss-Legendre rule (the same number of points as the element, so the potential
// is the one whose gradient the discrete internal force is):
//   strain energy  sum over Gauss points of E gamma^2 / 2 A0 sqrt(a11) w, with the Green strain
//                  gamma = (lambda^2 - 1) / 2, lambda^2 = A11 / a11 (the energy of
//                  S = E (lambda^2 - 1) / 2, Eq. 2.53);
//   gravity        sum over Gauss points of rho0 A0 g z sqrt(a11) w, z the current height.
struct CablePotential {
  double strain = 0.0;
  double gravity = 0.0;
  double total() const { return strain + gravity; }
};
CablePotential cablePotential(const SaggingCable& cable, const model::State& state);

// ---------------------------------------------------------------------------------------------
// Free-floating truss: an nx x ny x nz grid of nodes (spacing 1), unstressed linear-elastic
// two-node cable elements (Compression::Carry, so bars) on every grid edge, one diagonal of every
// face of every cell and one body diagonal of every cell. Every cell is a convex polyhedron with
// triangulated faces, so rigid (Cauchy-Dehn), and the cells share faces: the whole truss is
// rigid, with exactly six rigid-body modes. No support.
std::unique_ptr<model::Model> makeFreeTruss(int nx, int ny, int nz);

// ---------------------------------------------------------------------------------------------
// Square membrane: a flat square [0, a] x [0, a] in the x-y plane, divisions x divisions square
// cells, LinearElasticPlaneStress (E, nu), thickness h0, density rho0. Edge nodes: z fixed and
// x, y prescribed to the uniform biaxial stretch u = eps x, v = eps y (load factor 1); interior
// nodes free. Meshes:
//   Quad4, Quad8, Quad12: one quadrilateral per cell, the serendipity nodes of Q8 / Q12 at the
//                         mid-sides / third points of the cell edges;
//   Triangle6:            each cell halved by the diagonal through its corner nearest the centre
//                         of the square (for 2 x 2 cells all diagonals meet at the centre: the
//                         symmetric pattern of Example 7), six-node triangles.
struct SquareMembraneInputs {
  enum class Element { Quad4, Quad8, Quad12, Triangle6 };
  Element element = Element::Quad4;
  int divisions = 2;
  double side = 1.0;       // a0
  double thickness = 1.0;  // h0
  double density = 1.0;    // rho0
  double poisson = 0.3;
  double strain = 1.0e-3;  // eps
  double youngs_modulus = 1.0e5;

  // The uniform prestress: Green strain gamma = ((1 + eps)^2 - 1) / 2 in both directions, second
  // Piola S = E gamma / (1 - nu) (isotropic plane stress).
  double secondPiola() const {
    const double gamma = 0.5 * ((1.0 + strain) * (1.0 + strain) - 1.0);
    return youngs_modulus * gamma / (1.0 - poisson);
  }
  // Out-of-plane modes of the square under isotropic tension, in reference quantities (the
  // membrane equation S h0 lap0 w = rho0 h0 w''):
  //   omega_mn = pi sqrt(S / rho0) sqrt(m^2 + n^2) / a0.
  double exactFrequency(int m, int n) const;
};

struct SquareMembrane {
  std::unique_ptr<model::Model> model;  // equations numbered
  SquareMembraneInputs inputs;
};

SquareMembrane makeSquareMembrane(const SquareMembraneInputs& inputs);

// The prestressed state: a static Newton solve to load factor 1, converged to 1e-10. The exact
// solution is u = eps x, v = eps y, w = 0 at every node.
model::State prestress(const SquareMembrane& membrane, const model::Assembler& assembler);

}  // namespace flexmoor::test

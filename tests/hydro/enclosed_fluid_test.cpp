// The enclosed fluid (libhydro/loads/enclosed_fluid.hpp; the dissertation's Example 9 model of
// the liquid in a tube: a static pressure on the wall plus the liquid's mass lumped at the wall's
// nodes). Checks: the lumped total against rho_f V of a closed box (exact) and of a circular tube
// (its discretisation error stated); the mass matrix's rigid-translation mass; the pressure's
// resultant against p times the projected area and, with its gradient, against the liquid's
// weight; the load stiffness against central differences; the sway frequency of a tube on
// springs against sqrt(k_total / (membrane + liquid mass)).
#include "libhydro/loads/enclosed_fluid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "libstruct/element/axisymmetric_membrane.hpp"
#include "libstruct/element/membrane_element.hpp"
#include "libstruct/element/spring_element.hpp"
#include "libstruct/material/membrane_material.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/fluid_tube.hpp"
#include "tests/support/surface_load_check.hpp"

namespace flexmoor::test {
namespace {

using Eigen::Vector3d;
using Eigen::VectorXd;

const double kPi = std::acos(-1.0);

// The sum over the elements of a surface load's nodal forces: its resultant.
Vector3d resultant(const model::Model& m, const std::vector<int>& elements,
                   const model::SurfaceLoad& load) {
  const model::State s = m.initialState();
  Vector3d total = Vector3d::Zero();
  VectorXd f;
  for (int e : elements) {
    m.element(e).surfaceLoad({m.reference(), s, e}, load, f, nullptr);
    for (int I = 0; I < f.size() / 3; ++I) total += f.segment<3>(3 * I);
  }
  return total;
}

double massSum(const std::vector<std::pair<int, double>>& masses) {
  double sum = 0.0;
  for (const auto& [node, m] : masses) sum += m;
  return sum;
}

// A box a x b x c of six Q4 faces, corner at `origin`; normals out (or in when `inward`).
struct Box {
  model::Model model;
  std::vector<int> faces;
};

void makeBox(Box& box, const Vector3d& size, const Vector3d& origin, bool inward) {
  for (int k = 0; k < 8; ++k)
    box.model.addNode(origin + Vector3d((k & 1) * size.x(), ((k >> 1) & 1) * size.y(),
                                        ((k >> 2) & 1) * size.z()));
  // Corner k at (k & 1, k >> 1 & 1, k >> 2 & 1); each face counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const element::MembraneSection section{
      0.01, 1.0, std::make_shared<material::LinearElasticPlaneStress>(1.0e6, 0.3)};
  for (const auto& face : faces) {
    std::vector<int> nodes(face, face + 4);
    if (inward) std::swap(nodes[1], nodes[3]);
    box.faces.push_back(box.model.addElement(element::makeMembraneElement("quad", nodes, section)));
  }
}

// Reference: the box's volume a b c and area 2 (ab + bc + ca), exact for flat faces; tolerance
// 1e-13 relative (round-off; measured below 3e-16). The total lumped mass is rho_f V whichever
// way the normals point, and the pressure pushes every face outwards: the +x face carries
// p b c along +x (same tolerance).
TEST(EnclosedFluid, LumpedMassOfAClosedBoxIsDensityTimesVolume) {
  const Vector3d size(2.0, 1.5, 0.8), origin(3.0, -1.0, -7.0);
  const double rho = 900.0, p = 2.0e4, volume = size.prod();
  for (bool inward : {false, true}) {
    Box box;
    makeBox(box, size, origin, inward);
    const hydro::Enclosure e =
        hydro::measureEnclosure(box.model, box.faces, box.model.initialState());
    EXPECT_NEAR(e.volume, inward ? -volume : volume, 1e-13 * volume);
    EXPECT_NEAR(e.area, 2.0 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x()),
                1e-13 * e.area);
    EXPECT_NEAR(e.vertical_area, 0.0, 1e-13 * e.area);
    const auto masses = hydro::lumpedFluidMasses(box.model, box.faces, e, rho);
    EXPECT_EQ(masses.size(), 8u);
    EXPECT_NEAR(massSum(masses), rho * volume, 1e-13 * rho * volume);

    hydro::addEnclosedFluid(box.model, box.faces, {rho, p, 0.0, 0.0});
    const model::SurfaceLoad& load = *box.model.surfaceLoads().back().load;
    const Vector3d on_plus_x = resultant(box.model, {box.faces[5]}, load);
    EXPECT_NEAR(on_plus_x.x(), p * size.y() * size.z(), 1e-13 * p * size.y() * size.z());
    EXPECT_NEAR(resultant(box.model, box.faces, load).norm(), 0.0, 1e-13 * p * e.area);
  }
}

// Reference: pi R^2 L for the volume of a circular tube of 6 and of 24 Q8 elements around (nodes
// on the circle, parabolic edges between them). Discretisation error measured -2.42e-3 (6
// elements, the parabola through three points 30 degrees apart cuts inside the arc) and -9.77e-6
// (24): tolerances 3e-3 and 1.2e-5. The lumped total equals rho_f V of the discrete tube to 1e-13
// (round-off, measured below 1e-15), and each node carries rho_f V / A per unit of its area, with
// V / A within the same error of R / 2.
TEST(EnclosedFluid, LumpedMassOfATubeIsDensityTimesItsVolume) {
  const double rho = 900.0;
  for (const auto& [n, tolerance] : {std::pair{6, 3e-3}, std::pair{24, 1.2e-5}}) {
    FluidTubeInputs in;
    in.elements = n;
    in.radius = 5.0;
    in.length = 2.0;
    in.centre_z = -20.0;
    const FluidTube t = makeFluidTube(in);
    const hydro::Enclosure e =
        hydro::measureEnclosure(*t.model, t.membranes, t.model->initialState());
    const double exact = kPi * in.radius * in.radius * in.length;
    std::cout << n << " Q8: V / (pi R^2 L) - 1 = " << e.volume / exact - 1.0
              << ", (V / A) / (R / 2) - 1 = " << (e.volume / e.area) / (in.radius / 2.0) - 1.0
              << ", int n_z dA / A = " << e.vertical_area / e.area << "\n";
    EXPECT_NEAR(e.volume / exact, 1.0, tolerance) << n;
    EXPECT_NEAR((e.volume / e.area) / (in.radius / 2.0), 1.0, tolerance) << n;
    EXPECT_NEAR(e.vertical_area, 0.0, 1e-13 * e.area);
    const auto masses = hydro::lumpedFluidMasses(*t.model, t.membranes, e, rho);
    EXPECT_EQ(masses.size(), static_cast<size_t>(5 * n));
    EXPECT_NEAR(massSum(masses), rho * e.volume, 1e-13 * rho * e.volume) << n;
  }
}

// Reference: a rigid translation of the wall, u = e_x at every free dof, has kinetic mass
// u^T M u = membrane mass rho_m h A + liquid mass rho_f V, consistent or lumped, with y fixed
// (the symmetry); tolerance 1e-13 relative (round-off, measured below 1e-15). The liquid's
// masses carry no weight: gravity loads the membrane only (the liquid's weight is in the
// pressure's gradient).
TEST(EnclosedFluid, MassMatrixCarriesMembraneAndLiquid) {
  FluidTubeInputs in;
  in.radius = 5.0;
  in.length = 2.0;
  in.thickness = 0.02;
  in.density = 1500.0;
  FluidTube t = makeFluidTube(in);
  model::Model& m = *t.model;
  const hydro::Enclosure e = hydro::measureEnclosure(m, t.membranes, m.initialState());
  const double rho = 900.0, g = 9.80665;
  hydro::addEnclosedFluid(m, t.membranes, {rho, 1.0e4, in.centre_z, g});
  for (int node = 0; node < m.nodeCount(); ++node) m.constrain(node, 1);
  m.setGravity(Vector3d(0.0, 0.0, -g));
  m.numberEquations();
  const model::Assembler assembler(m);
  const double expected = in.density * in.thickness * e.area + rho * e.volume;
  for (element::MassKind kind : {element::MassKind::Consistent, element::MassKind::Lumped}) {
    model::SparseMatrix M;
    assembler.mass(m.initialState(), kind, M);
    VectorXd u = VectorXd::Zero(assembler.equationCount());
    for (int node = 0; node < m.nodeCount(); ++node) u(m.equation(node, 0)) = 1.0;
    EXPECT_NEAR(u.dot(M * u), expected, 1e-13 * expected);
  }
  // Gravity and the pressure at load factor 1: the total vertical load is the membrane's weight
  // plus the liquid's (-rho_f g V from the gradient over the closed wall).
  model::State s = m.initialState();
  s.load_factor = 1.0;
  VectorXd P;
  assembler.externalLoad(s, P);
  double vertical = 0.0;
  for (int node = 0; node < m.nodeCount(); ++node) vertical += P(3 * node + 2);
  EXPECT_NEAR(vertical, -g * expected, 1e-12 * g * expected);
}

// Reference: on the right half of a tube (the 3 of 6 Q8 elements with x >= 0) a pressure field
// p_ref + rho_f g (z_ref - z) has the horizontal resultant (p_ref + rho_f g (z_ref - z_c)) 2 R L,
// p at the centre times the projected area (exact: the half is symmetric about z_c and its ends
// lie on the axis's vertical plane); on the whole tube, the vertical resultant -rho_f g V, the
// liquid's weight (exact for the discrete V), and no horizontal one. Tolerance 1e-12 relative
// (round-off; measured below 4e-15).
TEST(EnclosedFluid, PressureResultantIsPressureTimesProjectedArea) {
  FluidTubeInputs in;
  in.radius = 5.0;
  in.length = 2.0;
  in.centre_z = -20.0;
  const FluidTube t = makeFluidTube(in);
  const double rho = 900.0, g = 9.80665, p_ref = 3.0e4, z_ref = -16.0;
  const hydro::EnclosedFluidPressure load({rho, p_ref, z_ref, g}, 1.0);
  const double p_centre = p_ref + rho * g * (z_ref - in.centre_z);
  const Vector3d half = resultant(*t.model, {t.membranes[0], t.membranes[1], t.membranes[2]}, load);
  const double projected = 2.0 * in.radius * in.length;
  EXPECT_NEAR(half.x(), p_centre * projected, 1e-12 * p_centre * projected);
  const Vector3d whole = resultant(*t.model, t.membranes, load);
  const double volume =
      hydro::measureEnclosure(*t.model, t.membranes, t.model->initialState()).volume;
  EXPECT_NEAR(whole.z(), -rho * g * volume, 1e-12 * rho * g * volume);
  EXPECT_NEAR(whole.x(), 0.0, 1e-12 * p_centre * projected);
}

// Reference: central differences (step 1e-6) of the nodal forces of a curved Q8 of the tube,
// randomly displaced; tolerance 1e-8 relative to the largest entry (measured 1.6e-9).
TEST(EnclosedFluid, LoadStiffnessMatchesFiniteDifference) {
  FluidTubeInputs in;
  in.radius = 5.0;
  in.length = 2.0;
  in.centre_z = -20.0;
  const FluidTube t = makeFluidTube(in);
  const hydro::EnclosedFluidPressure load({900.0, 3.0e4, -16.0, 9.80665}, -1.0);
  const element::Element& e = t.model->element(t.membranes[1]);
  // Element 0 of the check's context: a model of that element's nodes alone.
  model::NodalField X(3, 8);
  std::vector<int> local(8);
  for (int I = 0; I < 8; ++I) {
    X.col(I) = t.model->reference().col(e.nodes()[I]);
    local[I] = I;
  }
  const auto single = element::makeMembraneElement(
      "quad", local, {0.01, 1.0, std::make_shared<material::LinearElasticPlaneStress>(1e6, 0.3)});
  model::State s(8);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> noise(-0.3, 0.3);
  for (int I = 0; I < 8; ++I) s.displacement.col(I) << noise(rng), noise(rng), noise(rng);
  const double error = surfaceStiffnessError(*single, X, s, load);
  std::cout << "enclosed-fluid load stiffness error: " << error << "\n";
  EXPECT_LT(error, 1e-8);
}

// Reference: a rigid tube on four springs of stiffness k in x (at its top and bottom nodes, both
// rings) and four in z (at its sides) sways and heaves at omega^2 = 4 k / (membrane + liquid
// mass), the mass of the discrete wall and volume (rho_m h A + rho_f V). The tube is pressurised
// (1 MPa, stiff against ovalling) and the springs are long (100 m), so its deformation and the
// springs' pretension shift omega a little (measured -2.2e-5 and -1.2e-5); tolerance 5e-5
// relative. Without the liquid's mass the frequency would be 6.8 times higher.
TEST(EnclosedFluid, SwayAndHeaveOfATubeOnSpringsFeelTheLiquidMass) {
  FluidTubeInputs in;
  in.radius = 1.0;
  in.length = 0.5;
  in.thickness = 0.01;
  in.density = 1000.0;
  in.youngs_modulus = 1.0e10;
  FluidTube t = makeFluidTube(in);
  model::Model& m = *t.model;
  const double rho = 900.0, k = 1.0e3, arm = 100.0;
  const hydro::Enclosure e = hydro::measureEnclosure(m, t.membranes, m.initialState());
  hydro::addEnclosedFluid(m, t.membranes, {rho, 1.0e6, 0.0, 0.0});
  for (int node = 0; node < m.nodeCount(); ++node) m.constrain(node, 1);
  const int n = in.elements;
  const auto spring = [&](int node, const Vector3d& direction) {
    const int ground = m.addNode(m.reference().col(node) + arm * direction);
    for (int c = 0; c < 3; ++c) m.constrain(ground, c);
    m.addElement(std::make_unique<element::SpringElement>(node, ground, k, -1.0,
                                                          material::Compression::Carry));
  };
  for (const std::vector<int>* ring : {&t.ring0, &t.ring1}) {
    spring((*ring)[0], Vector3d::UnitX());
    spring((*ring)[n], Vector3d::UnitX());
    spring((*ring)[n / 2], Vector3d::UnitZ());
    spring((*ring)[3 * n / 2], Vector3d::UnitZ());
  }
  m.numberEquations();
  const model::Assembler assembler(m);
  model::State s = m.initialState();
  solve::StaticOptions statics;
  statics.pressure_load_stiffness = true;
  solve::solveStatic(assembler, s, statics);
  solve::ModalOptions modal;
  modal.modes = 2;
  const solve::ModalResult modes = solve::naturalModes(assembler, s, modal);
  const double mass = in.density * in.thickness * e.area + rho * e.volume;
  const double omega = std::sqrt(4.0 * k / mass);
  for (int i = 0; i < 2; ++i) {
    std::cout << "mode " << i + 1
              << ": omega / sqrt(4 k / M) - 1 = " << modes.omega[i] / omega - 1.0 << "\n";
    EXPECT_NEAR(modes.omega[i] / omega, 1.0, 5e-5) << i;
  }
}

// Reference: a sphere of radius R as an axisymmetric meridian of 8 L3 elements from pole to pole
// (per radian: V / 2 pi = 2 R^3 / 3, area / 2 pi = 2 R^2); the total lumped mass per radian is
// rho_f V / 2 pi of the discrete meridian to 1e-13, and V within its discretisation error of the
// sphere's (measured -7.4e-5; tolerance 1e-4); int n_z dA over the closed meridian vanishes
// (1e-13 of the area).
TEST(EnclosedFluid, AxisymmetricSphereHoldsItsVolumePerRadian) {
  const double R = 2.0, rho = 900.0;
  const int elements = 8, n = 2 * elements + 1;
  model::Model m;
  for (int i = 0; i < n; ++i) {
    const double phi = kPi * i / (n - 1);  // from the bottom pole
    m.addNode(Vector3d(R * std::sin(phi), 0.0, -R * std::cos(phi)));
  }
  const element::MembraneSection section{
      0.01, 1.0, std::make_shared<material::LinearElasticPlaneStress>(1.0e6, 0.3)};
  std::vector<int> meridian;
  for (int e = 0; e < elements; ++e)
    meridian.push_back(
        m.addElement(element::makeAxisymmetricMembrane({2 * e, 2 * e + 1, 2 * e + 2}, section)));
  const hydro::Enclosure e = hydro::measureEnclosure(m, meridian, m.initialState());
  ASSERT_TRUE(e.axisymmetric);
  const double per_radian = 2.0 * R * R * R / 3.0;
  std::cout << "axisymmetric sphere, 8 L3: V / (2 R^3 / 3) - 1 = "
            << std::abs(e.volume) / per_radian - 1.0 << "\n";
  EXPECT_NEAR(std::abs(e.volume) / per_radian, 1.0, 1e-4);
  EXPECT_NEAR(e.vertical_area, 0.0, 1e-13 * e.area);
  const auto masses = hydro::lumpedFluidMasses(m, meridian, e, rho);
  EXPECT_NEAR(massSum(masses), rho * std::abs(e.volume), 1e-13 * rho * std::abs(e.volume));
}

}  // namespace
}  // namespace flexmoor::test

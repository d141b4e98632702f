// The assembler's load matrices of a cable in the sea (Morison line load and seabed contact on
// 2-, 3- and 4-node elements, per deformed and per unstretched length) against central
// differences of its external load: stiffness = -dP/du, damping = -dP/du', mass = -dP/du'' on
// the free dofs. This checks the element's integration of N^T f and N^T J N (the tangent's and
// the length element's derivatives included) with the adapters' Jacobians.
//
// The line runs along a sloped bed at 20 m depth, from 2 cm inside it to 3 cm above it, in an
// Airy wave and a uniform current (ocean_models.hpp's wave), displaced, moving and accelerating
// by arbitrary smooth fields, its top end pinned. Reference: central differences, steps 1e-5 m,
// 1e-6 m/s, 1e-6 m/s^2. Metric: max |J - J_fd| / max |J_fd| per matrix. Tolerance 1e-7
// (measured 2.8e-8, the same with displacement steps from 1e-4 to 1e-6 m).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>

#include "tests/support/cable_models.hpp"
#include "tests/support/ocean_models.hpp"

namespace flexmoor::test {
namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

constexpr double kDepth = 20.0;  // k h = 1.7 for the 8 s wave: its flow reaches the bed

OceanLine lineThroughTheSea(int nodes_per_element, model::LengthMeasure measure) {
  const hydro::Bathymetry bed = hydro::Bathymetry::plane(-kDepth, 0.04, -0.03);
  OceanLineInputs in;
  in.start = Vector3d(0.0, 0.0, bed.height(0.0, 0.0) - 0.02);
  in.end = Vector3d(25.0, 6.0, bed.height(25.0, 6.0) + 0.03);
  in.elements = 2;
  in.nodes_per_element = nodes_per_element;
  in.morison.diameter = 0.1;
  in.morison.cn = 1.2;
  in.morison.ct = 0.02;
  in.morison.ca = 1.0;
  in.morison.ca_axial = 0.4;
  in.measure = measure;
  // A uniform current: the power law's shear is singular at the bed the line lies on.
  const auto sea = waveAndCurrentSea(kDepth);
  sea->setCurrent(hydro::CurrentProfile::uniform(0.8, 1.745));
  in.sea = sea;
  in.bed = bed;
  in.bed_properties.friction = 0.6;
  in.bed_properties.slip_speed = 0.05;
  OceanLine line = makeOceanLine(in);
  pin(*line.model, line.nodes.back());
  line.model->numberEquations();
  return line;
}

// Smooth arbitrary fields over the nodes (no two nodes alike), so no load point sits at a kink.
model::State movingState(const model::Model& m) {
  model::State s = m.initialState();
  for (int n = 0; n < m.nodeCount(); ++n) {
    const double x = m.reference()(0, n) / 25.0;
    s.displacement.col(n) = 0.05 * Vector3d(std::sin(3.0 * x), std::cos(2.0 * x), 0.2 * x * x);
    s.velocity.col(n) = Vector3d(0.4 - 0.3 * x, 0.25 * std::cos(4.0 * x), -0.1 + 0.5 * x);
    s.acceleration.col(n) = Vector3d(0.2 * std::sin(5.0 * x), -0.3 + x, 0.15);
  }
  s.time = 1.7;
  s.load_factor = 1.0;
  return s;
}

// -dP/d(field) on the free dofs by central differences.
MatrixXd differencedLoadMatrix(const model::Assembler& assembler, model::State s,
                               model::NodalField model::State::*field, double h) {
  const model::Model& m = assembler.model();
  MatrixXd J(m.equationCount(), m.equationCount());
  VectorXd plus, minus;
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k) {
      const int eq = m.equation(n, k);
      if (eq < 0) continue;
      double& value = (s.*field)(k, n);
      const double v0 = value;
      value = v0 + h;
      assembler.externalLoad(s, plus);
      value = v0 - h;
      assembler.externalLoad(s, minus);
      value = v0;
      J.col(eq) = -assembler.restrictToFree(plus - minus) / (2.0 * h);
    }
  return J;
}

double matrixError(const model::SparseMatrix& analytic, const MatrixXd& fd) {
  return (MatrixXd(analytic) - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
}

TEST(CableLoadMatrices, MatchCentralDifferencesOfTheExternalLoad) {
  double worst = 0.0;
  for (const auto measure : {model::LengthMeasure::Current, model::LengthMeasure::Reference})
    for (int p = 2; p <= 4; ++p) {
      const OceanLine line = lineThroughTheSea(p, measure);
      const model::Assembler assembler(*line.model);
      const model::State s = movingState(*line.model);
      model::LoadMatrices J;
      assembler.loadMatrices(s, J);
      const double errors[] = {
          matrixError(J.stiffness,
                      differencedLoadMatrix(assembler, s, &model::State::displacement, 1e-5)),
          matrixError(J.damping,
                      differencedLoadMatrix(assembler, s, &model::State::velocity, 1e-6)),
          matrixError(J.mass,
                      differencedLoadMatrix(assembler, s, &model::State::acceleration, 1e-6))};
      const char* names[] = {"stiffness", "damping", "mass"};
      for (int i = 0; i < 3; ++i) {
        EXPECT_LT(errors[i], 1e-7)
            << names[i] << ", " << p << "-node elements, "
            << (measure == model::LengthMeasure::Current ? "per deformed" : "per unstretched")
            << " length";
        worst = std::max(worst, errors[i]);
      }
    }
  std::cout << "load matrices against central differences: worst relative error " << worst << '\n';
}

// The line starts inside the bed: some of its load points are in contact, so the seabed's
// matrices are part of what was checked above.
TEST(CableLoadMatrices, TheCheckedLineTouchesTheBed) {
  const OceanLine line = lineThroughTheSea(3, model::LengthMeasure::Current);
  const model::Assembler assembler(*line.model);
  model::State s = movingState(*line.model);
  const Vector3d with_bed = totalExternalLoad(assembler, s);
  s.displacement.col(line.nodes.front()).z() += 0.5;  // lifted off the bed
  s.displacement.col(line.nodes[1]).z() += 0.5;
  EXPECT_GT((with_bed - totalExternalLoad(assembler, s)).norm(), 100.0);
}

}  // namespace
}  // namespace flexmoor::test

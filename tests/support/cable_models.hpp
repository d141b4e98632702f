#pragma once
// Small cable models built in code for the verification and validation tests: a straight-cable
// generator (N elements of p nodes between two nodes), and the suspended cable of the
// dissertation's Example 1 with its viscous-relaxation solve.
#include <memory>
#include <vector>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/model/model.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"
#include "tests/support/elastic_catenary.hpp"

namespace flexmoor::test {

// A cable section of a linear-elastic material (Eq. 2.53).
element::CableSection linearElasticSection(double E, double area, double density,
                                           material::Compression compression);

// Adds `elements` cable elements of `nodes_per_element` (2, 3 or 4) nodes each on the straight
// chord between the existing nodes `first` and `last`, with the new nodes equally spaced, and
// returns every node along the cable in order, both ends included (elements * (p - 1) + 1 nodes).
std::vector<int> addStraightCable(model::Model& model, int first, int last, int elements,
                                  int nodes_per_element, const element::CableSection& section,
                                  int quadrature_points = 0);

// Fixes all three dofs of a node (prescribed value 0).
void pin(model::Model& model, int node);

// ---------------------------------------------------------------------------------------------
// Example 1 (docs/theory.md#example-1): a straight, horizontal, unstressed cable along +x from the
// origin; all y dofs fixed; the left end pinned in x and z; the right end fixed in z (a roller)
// and pulled by a horizontal force H in +x; self weight in -z. Units: ft, slug, s, lbf.
struct SuspendedCableInputs {
  double unstretched_length = 200.0;  // L0, ft (reconstruction)
  double youngs_modulus = 1.0e6;      // E, psf
  double area = 0.1;                  // A, ft^2
  double density = 0.031056;          // rho, slug/ft^3
  double gravity = 32.2;              // g, ft/s^2
  double horizontal_force = 5.8;      // H, lbf (reconstruction)

  // The same cable for the analytic elastic catenary: w = rho A g, EA = E A.
  CatenaryInputs catenary() const {
    return {unstretched_length, density * area * gravity, youngs_modulus * area, horizontal_force};
  }
};

struct SuspendedCable {
  std::unique_ptr<model::Model> model;  // equations numbered; held by pointer so that an
                                        // Assembler's reference to it stays valid
  std::vector<int> nodes;               // along the cable, left to right

  int leftNode() const { return nodes.front(); }
  int rightNode() const { return nodes.back(); }
  // The node at mid-length; the mesh must have an odd node count.
  int centreNode() const;
};

SuspendedCable makeSuspendedCable(const SuspendedCableInputs& inputs, int elements,
                                  int nodes_per_element, material::Compression compression,
                                  int quadrature_points = 0);

// Example 1's relaxation parameters: tolerance 0.001, damping constant C = 10,000, initial
// damping factor 0.01, decrement coefficient 1.00.
solve::RelaxationOptions exampleOneRelaxation();

struct SagAndMovement {
  double centre_sag = 0.0;           // -z displacement of the centre node
  double support_movement = 0.0;     // -x displacement of the roller end
  double least_point_tension = 0.0;  // the smallest axial force at any Gauss point
  solve::RelaxationReport report;
};

// Relaxes the cable from its straight start to the hanging equilibrium.
SagAndMovement relaxSuspendedCable(
    const SuspendedCable& cable, const solve::RelaxationOptions& options = exampleOneRelaxation());

}  // namespace flexmoor::test

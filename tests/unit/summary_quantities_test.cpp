// evaluateSummary: each declared quantity read from the frame that closes its step.
#include "apps/output/summary_quantities.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "libstruct/element/spring_element.hpp"

namespace flexmoor::app {
namespace {

// Two nodes (0,0,0) and (10,0,0) joined by a spring; node 0 displaced and node 1 supported.
struct Fixture {
  Case c;
  model::State state{2};
  ResultFrame frame;

  Fixture() {
    c.model = std::make_unique<model::Model>();
    model::Model& model = *c.model;
    model.addNode(Eigen::Vector3d(0.0, 0.0, 0.0));
    model.addNode(Eigen::Vector3d(10.0, 0.0, 0.0));
    model.addElement(
        std::make_unique<element::SpringElement>(0, 1, 100.0, -1.0, material::Compression::Carry));
    state.displacement.col(1) = Eigen::Vector3d(-0.5, 0.0, -2.0);
    frame.state = &state;
    frame.reactions = model::NodalField::Zero(3, 2);
    frame.reactions.col(1) = Eigen::Vector3d(3.0, 0.0, 4.0);
    frame.elements.resize(1);
    frame.elements[0].point_tension = {7.0, 9.0};
    frame.elements[0].end_tension[0] = 6.0;
    frame.elements[0].end_tension[1] = 8.0;
  }

  double evaluate(SummarySpec::Quantity q, int node = 1, int component = 2, double scale = 1.0) {
    SummarySpec spec;
    spec.name = "q";
    spec.quantity = q;
    spec.node = node;
    spec.component = component;
    spec.element = 0;
    spec.end = 1;
    spec.scale = scale;
    return evaluateSummary(spec, c, frame);
  }
};

using Q = SummarySpec::Quantity;

TEST(SummaryQuantity, DisplacementIsTheNodalComponentTimesScale) {
  Fixture f;
  EXPECT_EQ(f.evaluate(Q::Displacement), -2.0);
  EXPECT_EQ(f.evaluate(Q::Displacement, 1, 2, -1.0), 2.0);  // a sag reported positive
}

TEST(SummaryQuantity, PositionIsReferencePlusDisplacement) {
  Fixture f;
  EXPECT_EQ(f.evaluate(Q::Position, 1, 0), 9.5);
}

TEST(SummaryQuantity, ReactionComponentAndMagnitude) {
  Fixture f;
  EXPECT_EQ(f.evaluate(Q::Reaction, 1, 0), 3.0);
  EXPECT_EQ(f.evaluate(Q::ReactionMagnitude), 5.0);
}

TEST(SummaryQuantity, EndTensionOfTheNamedEnd) {
  Fixture f;
  EXPECT_EQ(f.evaluate(Q::EndTension), 8.0);
}

// The largest end tension; the integration points' (strain-based) tensions do not count.
TEST(SummaryQuantity, MaxTensionIsTheLargestEndTension) {
  Fixture f;
  EXPECT_EQ(f.evaluate(Q::MaxTension), 8.0);
  f.frame.elements[0].end_tension[0] = 11.0;
  EXPECT_EQ(f.evaluate(Q::MaxTension), 11.0);
}

TEST(SummaryQuantity, NodeOutsideTheModelIsRefused) {
  Fixture f;
  EXPECT_THROW(f.evaluate(Q::Displacement, 2), std::out_of_range);
  EXPECT_THROW(f.evaluate(Q::Position, 0, 3), std::out_of_range);
}

}  // namespace
}  // namespace flexmoor::app

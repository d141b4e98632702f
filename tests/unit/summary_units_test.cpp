// The units summary.json gives its quantities: a support reaction of an axisymmetric model is per
// radian of circumference (its meridian's forces are, Eq. 3.37 per radian), any other in the
// case's force unit.
#include <gtest/gtest.h>

#include <string>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

// A meridian of one quadratic axisymmetric element (of Example 3's tube), or the same nodes joined
// by a cable, with a reaction, a reaction magnitude and a displacement in the summary.
std::string tube(const std::string& element_type) {
  const std::string section = element_type == "cable" ? "rope" : "skin";
  return std::string(R"(units: US
materials:
  rubber: {type: mooney_rivlin, C1: 2300 psf, C2: 280 psf}
sections:
  skin: {material: rubber, thickness: 0.01 ft}
  rope: {material: rubber, area: 0.01 ft^2}
nodes:
  1: [10 ft, 0, 0]
  2: [10 ft, 0, 15 ft]
  3: [10 ft, 0, 30 ft]
elements:
  - {type: )") +
         element_type + ", nodes: [1, 2, 3], section: " + section + R"(}
supports:
  - {nodes: [1, 2, 3], fix: [z]}
  - {nodes: [1, 3], fix: [x, y]}
steps:
  - static: {}
summary:
  axial: {quantity: reaction_z, node: 1}
  support: {quantity: reaction_magnitude, node: 3}
  radial: {quantity: displacement_x, node: 2}
)";
}

std::string unitOf(const Case& c, const std::string& name) {
  for (const SummarySpec& s : c.summary)
    if (s.name == name) return s.unit;
  return "(not declared)";
}

TEST(SummaryUnits, AxisymmetricReactionsArePerRadian) {
  const Case c =
      readCase(test::writeCase("axisymmetric-reactions.yaml", tube("axisymmetric_membrane")));
  EXPECT_EQ(unitOf(c, "axial"), "lbf/rad");
  EXPECT_EQ(unitOf(c, "support"), "lbf/rad");
  EXPECT_EQ(unitOf(c, "radial"), "ft");
}

TEST(SummaryUnits, ReactionsOfOtherModelsAreForces) {
  const Case c = readCase(test::writeCase("cable-reactions.yaml", tube("cable")));
  EXPECT_EQ(unitOf(c, "axial"), "lbf");
  EXPECT_EQ(unitOf(c, "support"), "lbf");
}

}  // namespace
}  // namespace flexmoor::app

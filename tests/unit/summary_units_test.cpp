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

// `unit:` reports a quantity in a unit of its dimension: the value's scale is the case unit's
// size in it (12 in to the ft and 12 in/s to the ft/s, times a scale: given; 1 lbf =
// 4.4482216152605 N by definition), to round-off (1e-15 relative), and the unit is named as
// given; without it, the case's unit and scale 1.
TEST(SummaryUnits, AUnitOfTheQuantitysDimensionScalesTheValue) {
  const Case c = readCase(test::writeCase("report-units.yaml", tube("cable") + R"(
  radial_in: {quantity: displacement_x, node: 2, unit: in}
  speed_in: {quantity: speed, node: 2, unit: in/s, scale: 2}
  axial_kn: {quantity: reaction_z, node: 1, unit: kN}
)"));
  const auto spec = [&](const std::string& name) -> const SummarySpec& {
    for (const SummarySpec& s : c.summary)
      if (s.name == name) return s;
    throw std::runtime_error("no " + name);
  };
  EXPECT_EQ(spec("radial_in").unit, "in");
  EXPECT_NEAR(spec("radial_in").scale, 12.0, 12.0 * 1e-15);
  EXPECT_EQ(spec("speed_in").unit, "in/s");
  EXPECT_NEAR(spec("speed_in").scale, 24.0, 24.0 * 1e-15);
  EXPECT_EQ(spec("axial_kn").unit, "kN");
  EXPECT_NEAR(spec("axial_kn").scale, 4.4482216152605e-3, 4.4482216152605e-3 * 1e-15);
  EXPECT_EQ(spec("radial").unit, "ft");
  EXPECT_EQ(spec("radial").scale, 1.0);
}

}  // namespace
}  // namespace flexmoor::app

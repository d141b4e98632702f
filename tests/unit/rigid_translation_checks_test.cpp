// What `check` takes as holding a group of joined nodes against a rigid translation
// (apps/case/check/rigid_translations.hpp): supports, and vertically the seabed under a group that
// sinks onto it or the surface over one that floats up to it; never the loads horizontally. A
// direction nothing holds is an error at the line that defines the group in a relax, static or
// modes step, and a warning when only dynamic steps see it (inertia resists it there).
#include <gtest/gtest.h>

#include <string>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

using test::anyContains;
using test::joined;
using test::problems;
using test::writeCase;

// A chain in 100 m of water (lines 1-9), its section with hydro: (it touches the bed).
const std::string kChain = R"(units: SI
water: {density: 1025 kg/m^3, depth: 100 m}
materials:
  steel: {type: linear_elastic, E: 5.0e10 Pa}
sections:
  chain: {material: steel, area: 0.0076849 m^2, density: 10111.6 kg/m^3,
          hydro: {diameter: 0.09 m, Cn: 1.6, Ca: 1.0}}
loads:
  gravity: [0, 0, -9.80665]
)";

// A chain lying on the bed held in x and y at one end: the bed carries its weight, so z is
// held; without seabed: it would sink without end.
TEST(RigidTranslationChecks, TheSeabedHoldsASinkingLineVerticallyOnly) {
  const std::string line = R"(lines:
  - {name: laid, from: [0, 0, -100 m], to: [100 m, 0, -100 m], elements: 5, order: 2,
     section: chain}
supports:
  - {node: laid.start, fix: [x, y]}
steps:
  - static: {}
)";
  EXPECT_TRUE(problems(writeCase("on-bed.yaml", kChain + "seabed: {}\n" + line)).empty());
  const std::string file = writeCase("no-bed.yaml", kChain + line);
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, file + ":11: line 'laid' (6 nodes) is free to move in z as a "
                                           "rigid body"))
      << joined(messages);
}

// On the bed but held by nothing horizontally: x and y are named, and what holds z.
TEST(RigidTranslationChecks, ALineOnTheBedWithoutAnchorIsFreeHorizontally) {
  const std::string file = writeCase("adrift.yaml", kChain + R"(seabed: {}
lines:
  - {name: adrift, from: [0, 0, -100 m], to: [100 m, 0, -100 m], elements: 5, order: 2,
     section: chain}
steps:
  - static: {}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, file + ":12: line 'adrift' (6 nodes) is free to move in x, y "
                                           "as a rigid body"))
      << joined(messages);
  EXPECT_TRUE(anyContains(messages, "its z held by the seabed its weight in water rests it on"))
      << joined(messages);
}

// A surface buoy (a sphere, net buoyant with its pendant) held in x and y at the pendant's foot:
// its buoyancy falls as it rises through the surface, so z is held; not so a buoy that sinks
// (there is no seabed here).
TEST(RigidTranslationChecks, TheSurfaceHoldsAFloatingSphereVertically) {
  const auto buoyCase = [](const std::string& body) {
    return kChain + R"(lines:
  - {name: pendant, from: [0, 0, -20 m], to: [0, 0, -1 m], elements: 2, order: 2, section: chain}
supports:
  - {node: pendant.start, fix: [x, y]}
bodies:
  - {node: pendant.end, )" +
           body + R"(}
steps:
  - static: {}
)";
  };
  EXPECT_TRUE(problems(writeCase("sphere.yaml", buoyCase("type: sphere, diameter: 2 m, Cd: 0.5, "
                                                         "mass: 500 kg")))
                  .empty());
  const std::string heavy =
      writeCase("heavy.yaml", buoyCase("type: sphere, diameter: 2 m, Cd: 0.5, mass: 10000 kg"));
  EXPECT_TRUE(anyContains(problems(heavy), "is free to move in z as a rigid body"))
      << joined(problems(heavy));
}

// Released from its support in a dynamic step, a line falls: no error, a warning naming it.
TEST(RigidTranslationChecks, AGroupFreeInDynamicStepsOnlyIsAWarning) {
  const std::string file = writeCase("falling.yaml", kChain + R"(lines:
  - {name: dropped, from: [0, 0, -10 m], to: [10 m, 0, -10 m], elements: 2, order: 2,
     section: chain}
supports:
  - {node: dropped.start, fix: [x, y, z]}
steps:
  - static: {name: hanging}
  - dynamic: {name: fall, dt: 0.01 s, steps: 10,
              release: [{node: dropped.start, dofs: [x, y, z]}]}
)");
  const Case c = readCase(file);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings.front().find("line 'dropped' (3 nodes) is free to move in x, y, z as a "
                                    "rigid body in the dynamic steps"),
            std::string::npos)
      << c.warnings.front();
}

}  // namespace
}  // namespace flexmoor::app

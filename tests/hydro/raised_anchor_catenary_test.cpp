// A line from a raised anchor (libhydro/mooring/raised_anchor_catenary.hpp): laid on the bed
// between the parts hanging from the anchor and the fairlead, against the test-side solve
// (tests/support/laid_between_hanging_parts: the touchdown catenary of each part, the same H in
// both); hanging clear of the bed when it is taut or too short to reach it, as the suspended
// equations say; refused when slack; never below the bed.
#include <gtest/gtest.h>

#include <cmath>

#include "libhydro/mooring/catenary_line.hpp"
#include "tests/support/catenary_line_cases.hpp"
#include "tests/support/laid_between_hanging_parts.hpp"

namespace flexmoor::hydro {
namespace {

// OC3-Hywind's chain (w = 698.09 N/m, EA = 384.243e6 N) from an anchor 10 m above a 100 m deep
// bed to a fairlead 20 m below the surface, 400 m away: the anchor part hangs about 12 m to the
// bed, the fairlead part about 85 m.
CatenaryLineInputs raised(double length) {
  CatenaryLineInputs in;
  in.horizontal_span = 400.0;
  in.vertical_span = 70.0;
  in.anchor_height = 10.0;
  in.unstretched_length = length;
  in.weight = 698.09;
  in.axial_stiffness = 384.243e6;
  return in;
}

test::LaidBetweenSolution reference(const CatenaryLineInputs& in) {
  test::LaidBetweenInputs r;
  r.horizontal_span = in.horizontal_span;
  r.anchor_height = in.anchor_height;
  r.fairlead_height = in.anchor_height + in.vertical_span;
  r.unstretched_length = in.unstretched_length;
  r.submerged_weight = in.weight;
  r.axial_stiffness = in.axial_stiffness;
  return test::solveLaidBetween(r);
}

// The profile from the anchor (0, 0) to the fairlead (x_F, z_F), with the anchor's and the
// fairlead's tensions at its ends, |d(x, z)/ds| = 1 + T / EA along it (central differences, step
// h = 1e-3 m: within 3e-9, the positions' round-off of a few 1e-12 m over 2 h, and the chord's
// truncation kappa^2 h^2 / 6, the curvature kappa at most w / H, at a touchdown; counted twice), and never below the bed at -h_A (1e-9 of L: the solve's
// round-off).
void expectProfileOnOrAboveTheBed(const CatenaryLine& line) {
  const CatenaryLineInputs& in = line.inputs;
  const double L = line.length();
  const CatenaryPoint start = line.at(0.0), end = line.at(L);
  EXPECT_NEAR(start.x, 0.0, 1e-12 * L);
  EXPECT_NEAR(start.z, 0.0, 1e-12 * L);
  EXPECT_NEAR(end.x, in.horizontal_span, 1e-9 * L);
  EXPECT_NEAR(end.z, in.vertical_span, 1e-9 * L);
  EXPECT_NEAR(start.tension / line.anchorTension(), 1.0, 1e-12);
  EXPECT_NEAR(end.tension / line.fairleadTension(), 1.0, 1e-12);
  double lowest = 0.0;
  const double kappa = in.weight / line.horizontal, truncation = kappa * kappa * 1e-6 / 3.0;
  for (int k = 1; k < 400; ++k) {
    const double s = L * k / 400.0, h = 1e-3;
    const CatenaryPoint a = line.at(s - h), b = line.at(s + h), p = line.at(s);
    lowest = std::min(lowest, p.z);
    EXPECT_NEAR(std::hypot(b.x - a.x, b.z - a.z) / (2.0 * h), 1.0 + p.tension / in.axial_stiffness,
                3e-9 + truncation)
        << "s = " << s;
  }
  EXPECT_GE(lowest, -in.anchor_height - 1e-9 * L);
}

// Laid between its parts: H, the fairlead tension and the parts' lengths as the test-side solve
// has them, to 1e-12 (both solve to round-off; measured 2.4e-14 at most), the laid part on the bed
// (z = -h_A) in tension H, the anchor pulled down by the weight of its part (V_A = -w s_A).
TEST(RaisedAnchorCatenary, LaidBetweenItsHangingPartsMatchesTheTestSideSolve) {
  for (double length : {420.0, 450.0, 480.0}) {
    const CatenaryLineInputs in = raised(length);
    const CatenaryLine line = solveCatenary(in);
    const test::LaidBetweenSolution ref = reference(in);
    EXPECT_NEAR(line.horizontal / ref.horizontal_force, 1.0, 1e-12) << length;
    EXPECT_NEAR(line.fairleadTension() / ref.fairleadTension(), 1.0, 1e-12) << length;
    EXPECT_NEAR(line.anchorTension() / ref.anchorTension(), 1.0, 1e-12) << length;
    EXPECT_NEAR(line.laid_from, ref.anchor_part, 1e-12 * length) << length;
    EXPECT_NEAR(line.laid_length, ref.laid_length, 1e-12 * length) << length;
    EXPECT_NEAR(line.anchor_vertical, -in.weight * ref.anchor_part, 1e-12 * in.weight * length);
    EXPECT_EQ(line.anchor_horizontal, line.horizontal);
    const CatenaryPoint mid = line.at(line.laid_from + 0.5 * line.laid_length);
    EXPECT_NEAR(mid.z, -in.anchor_height, 1e-9 * length);
    EXPECT_EQ(mid.tension, line.horizontal);
    expectProfileOnOrAboveTheBed(line);
  }
}

// Taut (the suspended catenary's lowest point above the bed) or too short to reach the bed even
// hanging straight down: the suspended equations, exactly as without a bed.
TEST(RaisedAnchorCatenary, TautOrShortLineHangsClearOfTheBed) {
  CatenaryLineInputs in = raised(410.0);
  const CatenaryLine line = solveCatenary(in);
  EXPECT_EQ(line.laid_length, 0.0);
  EXPECT_EQ(line.laid_from, 0.0);
  in.seabed = false;
  const CatenaryLine free = solveCatenary(in);
  EXPECT_NEAR(line.horizontal / free.horizontal, 1.0, 1e-12);
  EXPECT_NEAR(line.vertical / free.vertical, 1.0, 1e-12);
  expectProfileOnOrAboveTheBed(line);
  // Mid-water: both ends 60 m above the bed, a 100 m line over a 60 m span.
  in = raised(100.0);
  in.horizontal_span = 60.0;
  in.vertical_span = 20.0;
  in.anchor_height = 60.0;
  const CatenaryLine high = solveCatenary(in);
  EXPECT_EQ(high.laid_length, 0.0);
  expectProfileOnOrAboveTheBed(high);
}

// Longer than its span and both parts hanging straight down: slack on the bed, refused.
TEST(RaisedAnchorCatenary, SlackLineIsRefused) {
  test::expectCatenaryError(raised(500.0), "slack on the seabed between the parts hanging");
  CatenaryLineInputs in = raised(450.0);
  in.anchor_height = -1.0;
  test::expectCatenaryError(in, "anchor is below the seabed");
  in = raised(450.0);
  in.vertical_span = -11.0;
  test::expectCatenaryError(in, "fairlead is below the seabed");
}

// The same line as two equal segments joined without a point force solves alike (the pieces'
// walk over segments); a clump weight on the laid part changes nothing (the bed carries it); one
// on a hanging part shortens that part and keeps the profile consistent.
TEST(RaisedAnchorCatenary, SegmentsAndClumpWeights) {
  const CatenaryLineInputs one = raised(450.0);
  const CatenaryLine single = solveCatenary(one);
  CatenaryLineInputs two = one;
  two.segments = {{200.0, one.weight, one.axial_stiffness},
                  {250.0, one.weight, one.axial_stiffness}};
  two.connection_forces = {0.0};
  const CatenaryLine split = solveCatenary(two);
  EXPECT_NEAR(split.horizontal / single.horizontal, 1.0, 1e-12);
  EXPECT_NEAR(split.fairleadTension() / single.fairleadTension(), 1.0, 1e-12);
  two.connection_forces = {-20e3};  // 200 m from the anchor: on the laid part
  const CatenaryLine clump = solveCatenary(two);
  EXPECT_NEAR(clump.horizontal / single.horizontal, 1.0, 1e-12);
  expectProfileOnOrAboveTheBed(clump);
  two.segments = {{5.0, one.weight, one.axial_stiffness}, {445.0, one.weight, one.axial_stiffness}};
  const CatenaryLine low = solveCatenary(two);  // 5 m from the anchor: on its hanging part
  EXPECT_LT(low.laid_from, single.laid_from);
  expectProfileOnOrAboveTheBed(low);
  two.connection_forces = {20e3};  // a buoy there would lift the part below its touchdown
  test::expectCatenaryError(two, "lifts a part hanging down to the bed");
}

// Every raised line of a grid (anchor 1 to 50 m up, spans 100 to 900 m, lengths from taut to
// nearly slack) starts: its ends where they belong and no point below the bed.
TEST(RaisedAnchorCatenary, SolvesEveryLineOfAGrid) {
  for (double height : {1.0, 10.0, 50.0})
    for (double x : {100.0, 400.0, 900.0})
      for (double z : {0.0, 40.0, 200.0})
        for (double ratio : {0.99, 1.02, 1.1, 1.3}) {
          CatenaryLineInputs in = raised(1.0);
          in.anchor_height = height;
          in.horizontal_span = x;
          in.vertical_span = z;
          in.unstretched_length = ratio * std::hypot(x, z);
          // Slack when even both ends hanging straight down leave more than the span laid.
          if (in.unstretched_length - height - (height + z) >= x) {
            EXPECT_THROW(solveCatenary(in), CatenaryError);
            continue;
          }
          if (in.unstretched_length - height - (height + z) >= x - 1.0) continue;  // stretch
          const CatenaryLine line = solveCatenary(in);
          SCOPED_TRACE(testing::Message() << height << " " << x << " " << z << " " << ratio);
          expectProfileOnOrAboveTheBed(line);
        }
}

}  // namespace
}  // namespace flexmoor::hydro

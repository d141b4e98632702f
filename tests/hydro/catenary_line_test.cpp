// The product's elastic catenary with seabed contact (libhydro/mooring/catenary_line) against the
// independent test-side solver (tests/support/mooring_catenary: the same published equations,
// its own Newton with a finite-difference Jacobian), MAP++'s published OC3-Hywind line, the
// closed forms of the friction and fully laid cases, and its input errors.
#include "libhydro/mooring/catenary_line.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/support/catenary_line_cases.hpp"
#include "tests/support/mooring_catenary.hpp"

namespace flexmoor::hydro {
namespace {

// OC3-Hywind's line (tests/support/catenary_line_cases.hpp).
CatenaryLineInputs oc3() { return test::oc3CatenaryInputs(); }

test::MooringLineSolution reference(const CatenaryLineInputs& in) {
  test::MooringLineInputs r;
  r.horizontal_span = in.horizontal_span;
  r.vertical_span = in.vertical_span;
  r.unstretched_length = in.unstretched_length;
  r.submerged_weight = in.weight;
  r.axial_stiffness = in.axial_stiffness;
  return test::solveMooringLine(r);
}

// Both solvers converge to 1e-12 of the spans; the forces then agree to about 1e-10 (measured
// 8e-12 or less): 1e-9 relative with the margin.
void expectMatchesReference(const CatenaryLineInputs& in) {
  const CatenaryLine line = solveCatenary(in);
  const test::MooringLineSolution ref = reference(in);
  EXPECT_NEAR(line.horizontal / ref.horizontal_force, 1.0, 1e-9);
  EXPECT_NEAR(line.vertical / ref.fairlead_vertical, 1.0, 1e-9);
  EXPECT_NEAR(line.laid_length, ref.seabed_length, 1e-9 * in.unstretched_length);
}

// The profile ends at the fairlead with the fairlead tension and starts at the anchor with the
// anchor's; along it |d(x, z)/ds| = 1 + T / EA (Irvine's law), checked by central differences
// (step 1e-3 m: truncation below 1e-9).
void expectProfileConsistent(const CatenaryLine& line) {
  const CatenaryLineInputs& in = line.inputs;
  const double L = in.unstretched_length;
  const CatenaryPoint end = line.at(L), start = line.at(0.0);
  EXPECT_NEAR(end.x, in.horizontal_span, 1e-9 * L);
  EXPECT_NEAR(end.z, in.vertical_span, 1e-9 * L);
  EXPECT_NEAR(end.tension / line.fairleadTension(), 1.0, 1e-12);
  EXPECT_NEAR(start.x, 0.0, 1e-12 * L);
  EXPECT_NEAR(start.z, 0.0, 1e-12 * L);
  EXPECT_NEAR(start.tension, line.anchorTension(), 1e-9 * line.fairleadTension());
  for (double f : {0.05, 0.3, 0.55, 0.8, 0.97}) {
    const double s = f * L, h = 1e-3;
    const CatenaryPoint a = line.at(s - h), b = line.at(s + h), p = line.at(s);
    const double stretch = std::hypot(b.x - a.x, b.z - a.z) / (2.0 * h);
    EXPECT_NEAR(stretch, 1.0 + p.tension / in.axial_stiffness, 1e-9) << "s = " << s;
  }
}

// MAP++ (OpenFAST regression summary, docs/theory.md): H 736,939.3 N, V 535,728.0 N, 134.785 m
// on the seabed, anchor H 736,845.2 N (MAP++ with its tiny default friction; ours is
// frictionless, so the anchor carries H itself: 1.3e-4 off). Forces to 1e-5 (the published
// figures' 7 digits and MAP++'s tolerance), the laid length to 1e-4.
TEST(CatenaryLine, Oc3MatchesMapPlusPlus) {
  const CatenaryLine line = solveCatenary(oc3());
  EXPECT_NEAR(line.horizontal / 736939.3, 1.0, 1e-5);
  EXPECT_NEAR(line.vertical / 535728.0, 1.0, 1e-5);
  EXPECT_NEAR(line.fairleadTension() / 911089.5, 1.0, 1e-5);
  EXPECT_NEAR(line.laid_length / 134.785, 1.0, 1e-4);
  EXPECT_NEAR(line.anchor_horizontal / 736845.2, 1.0, 2e-4);
  EXPECT_EQ(line.anchor_vertical, 0.0);
  EXPECT_LE(line.iterations, 8);  // "a few": measured 4
  expectProfileConsistent(line);
}

TEST(CatenaryLine, SlackLineMatchesTheTestSideSolver) {
  CatenaryLineInputs in = oc3();
  expectMatchesReference(in);
  in.unstretched_length = 1050.0;  // far more on the bed
  expectMatchesReference(in);
  expectProfileConsistent(solveCatenary(in));
}

// Fully suspended: a line nearly as short as its chord (838.2 m) and one 1% too short for it.
TEST(CatenaryLine, TautLineMatchesTheTestSideSolver) {
  CatenaryLineInputs in = oc3();
  in.horizontal_span = 800.0;
  for (double L : {845.0, 830.0}) {
    in.unstretched_length = L;
    expectMatchesReference(in);
    const CatenaryLine line = solveCatenary(in);
    EXPECT_EQ(line.laid_length, 0.0);
    EXPECT_GT(line.anchor_vertical, 0.0);  // the anchor is pulled up
    expectProfileConsistent(line);
  }
}

// A fairlead on the bed beyond the unstretched length: V = 0, H = EA (x / L - 1) without
// friction; with friction mu the tension falls by mu w per length from the fairlead, and where it
// reaches zero before the anchor, x - L = H^2 / (2 EA mu w). Closed forms to round-off (1e-12).
TEST(CatenaryLine, FullyLaidLineMatchesItsClosedForm) {
  CatenaryLineInputs in = oc3();
  in.vertical_span = 0.0;
  in.horizontal_span = 1.0005 * in.unstretched_length;
  CatenaryLine line = solveCatenary(in);
  const double ea = in.axial_stiffness, stretch = in.horizontal_span - in.unstretched_length;
  EXPECT_NEAR(line.horizontal / (ea * stretch / in.unstretched_length), 1.0, 1e-12);
  EXPECT_EQ(line.vertical, 0.0);
  EXPECT_EQ(line.laid_length, in.unstretched_length);
  expectProfileConsistent(line);
  in.friction = 1.0;
  line = solveCatenary(in);
  EXPECT_NEAR(line.horizontal / std::sqrt(2.0 * ea * in.weight * stretch), 1.0, 1e-12);
  EXPECT_LT(line.horizontal, in.weight * in.unstretched_length);  // the branch it checks
  EXPECT_EQ(line.anchor_horizontal, 0.0);
  expectProfileConsistent(line);
}

// Friction on the laid part (the C_B term of Jonkman's seabed equation): the anchor feels H - C_B w L_B (or 0),
// the laid part stretches by int T / EA (closed form below), and the suspended rest is the
// frictionless line from the touchdown point, which the test-side solver finds on its own. Both
// branches: the whole laid part in tension (C_B = 1), and its tension reaching zero (C_B = 8 on a
// slack line). Forces to 1e-9 as above.
TEST(CatenaryLine, FrictionMatchesItsClosedForm) {
  for (const auto& [friction, length] : {std::pair{1.0, 902.2}, std::pair{8.0, 1050.0}}) {
    CatenaryLineInputs in = oc3();
    in.friction = friction;
    in.unstretched_length = length;
    const CatenaryLine line = solveCatenary(in);
    const double H = line.horizontal, cw = friction * in.weight, LB = line.laid_length;
    const double zero_at = LB - H / cw;  // where the tension on the bed reaches zero
    const double laid_stretch = zero_at > 0.0 ? H * H / (2.0 * in.axial_stiffness * cw)
                                              : (H * LB - 0.5 * cw * LB * LB) / in.axial_stiffness;
    EXPECT_EQ(zero_at > 0.0, friction > 1.0) << "the branch this case is meant to check";
    EXPECT_NEAR(line.anchor_horizontal, std::max(H - cw * LB, 0.0), 1e-9 * H);
    CatenaryLineInputs rest = in;
    rest.friction = 0.0;
    rest.unstretched_length = length - LB;
    rest.horizontal_span = in.horizontal_span - LB - laid_stretch;
    const test::MooringLineSolution ref = reference(rest);
    EXPECT_NEAR(H / ref.horizontal_force, 1.0, 1e-9);
    EXPECT_NEAR(line.vertical / ref.fairlead_vertical, 1.0, 1e-9);
    EXPECT_NEAR(line.at(LB).x, LB + laid_stretch, 1e-9 * length);
    expectProfileConsistent(line);
  }
}

// A start that never fails: every line of a grid from very slack (L = 1.6 chord) to 5% too
// short, with and without the seabed, solves to the spans' 1e-12 of L (checked 1e-9 at the
// profile's end) in at most 30 Newton iterations (measured 14 at most); on the seabed, a line
// longer than its span plus its fairlead's height would lie slack on the bed and is refused.
TEST(CatenaryLine, SolvesEveryLineOfAGrid) {
  CatenaryLineInputs in = oc3();
  for (bool seabed : {true, false})
    for (double x : {50.0, 300.0, 600.0, 848.67, 1000.0})
      for (double z : {1.0, 100.0, 250.0, 600.0})
        for (double ratio : {1.6, 1.2, 1.02, 1.0, 0.99, 0.95}) {
          in.seabed = seabed;
          in.horizontal_span = x;
          in.vertical_span = z;
          in.unstretched_length = ratio * std::hypot(x, z);
          const double L = in.unstretched_length;
          if (seabed && x < L - z) {  // slack on the bed even with all of z_F hanging
            EXPECT_THROW(solveCatenary(in), CatenaryError) << x << " " << z << " " << ratio;
            continue;
          }
          if (seabed && x < L - z + 1.0) continue;  // within the hanging part's stretch
          const CatenaryLine line = solveCatenary(in);
          const CatenaryPoint end = line.at(in.unstretched_length);
          EXPECT_NEAR(end.x, x, 1e-9 * in.unstretched_length) << x << " " << z << " " << ratio;
          EXPECT_NEAR(end.z, z, 1e-9 * in.unstretched_length) << x << " " << z << " " << ratio;
          EXPECT_LE(line.iterations, 30) << x << " " << z << " " << ratio;
        }
}

TEST(CatenaryLine, RefusesLinesThatCannotBeStarted) {
  CatenaryLineInputs in = oc3();
  in.unstretched_length = 0.85 * std::hypot(in.horizontal_span, in.vertical_span);
  test::expectCatenaryError(in, "too short for its span");
  in = oc3();
  in.vertical_span = -5.0;
  test::expectCatenaryError(in, "below the seabed");
  in = oc3();
  in.weight = -1.0;
  test::expectCatenaryError(in, "submerged weight per length must be positive");
  in = oc3();
  in.axial_stiffness = 0.0;
  test::expectCatenaryError(in, "axial stiffness EA must be positive");
  in = oc3();
  in.unstretched_length = std::nan("");
  test::expectCatenaryError(in, "unstretched length must be positive");
  in = oc3();
  in.horizontal_span = 0.0;
  test::expectCatenaryError(in, "no horizontal span");
  in = oc3();
  in.vertical_span = 0.0;
  in.horizontal_span = 800.0;
  test::expectCatenaryError(in, "slack on the seabed");
  in = oc3();
  in.unstretched_length = 1200.0;
  test::expectCatenaryError(in, "too long for its span");
  in = oc3();
  in.friction = -0.1;
  test::expectCatenaryError(in, "friction coefficient");
}

}  // namespace
}  // namespace flexmoor::hydro

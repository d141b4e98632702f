// The multi-segment elastic catenary (libhydro/mooring/catenary_line, segments and connection
// forces) against (1) the one-segment solve of the same line split into segments of its own type
// (the same equations summed piece by piece: equal to round-off), (2) a direct integration of the
// catenary's differential equations, independent of the closed forms: with H and V(s), the
// vertical force stepping by w_i per length and by -F_c across connection c, dx/ds = H / T + H /
// EA, dz/ds = V / T + V / EA, T = sqrt(H^2 + V^2) on the suspended part and dx/ds = 1 + H / EA on
// the (frictionless) laid part, which runs from the anchor to where V first turns positive,
// integrated by composite Simpson's rule piece by piece (with friction, the laid part stepped in 1
// mm); and (3) its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "libhydro/mooring/catenary_line.hpp"
#include "tests/support/catenary_line_cases.hpp"

namespace flexmoor::hydro {
namespace {

// OC3-Hywind's line (tests/support/catenary_line_cases.hpp).
CatenaryLineInputs oc3() { return test::oc3CatenaryInputs(); }

// The same line as segments of the given fractions of its length, no force at the connections.
CatenaryLineInputs split(CatenaryLineInputs in, const std::vector<double>& fractions) {
  for (const double f : fractions)
    in.segments.push_back({f * in.unstretched_length, in.weight, in.axial_stiffness});
  in.connection_forces.assign(fractions.size() - 1, 0.0);
  in.unstretched_length = in.weight = in.axial_stiffness = 0.0;
  return in;
}

// Split or whole, the same line: forces and laid length to 1e-11 relative (both converge to
// 1e-12 L of the spans; the sum of the pieces' asinh terms differs from one by round-off; measured
// 2e-13 of the fairlead tension at most), the profile to 1e-9 m (measured 1.7e-12 m).
void expectSameLine(const CatenaryLineInputs& whole, const CatenaryLineInputs& parts,
                    const std::string& what) {
  const CatenaryLine a = solveCatenary(whole), b = solveCatenary(parts);
  const double scale = a.fairleadTension();
  EXPECT_NEAR(b.horizontal, a.horizontal, 1e-11 * scale) << what;
  EXPECT_NEAR(b.vertical, a.vertical, 1e-11 * scale) << what;
  EXPECT_NEAR(b.anchor_horizontal, a.anchor_horizontal, 1e-11 * scale) << what;
  EXPECT_NEAR(b.anchor_vertical, a.anchor_vertical, 1e-11 * scale) << what;
  EXPECT_NEAR(b.laid_length, a.laid_length, 1e-11 * whole.unstretched_length) << what;
  for (double f : {0.0, 0.1, 0.25, 0.5, 0.7, 0.93, 1.0}) {
    const double s = f * whole.unstretched_length;
    const CatenaryPoint p = a.at(s), q = b.at(s);
    EXPECT_NEAR(q.x, p.x, 1e-9) << what << " s = " << s;
    EXPECT_NEAR(q.z, p.z, 1e-9) << what << " s = " << s;
    EXPECT_NEAR(q.tension, p.tension, 1e-11 * scale) << what << " s = " << s;
  }
}

// Every branch of the one-segment solve: partly laid (OC3), the laid part's tension in full
// (C_B = 1) and reaching zero (C_B = 8 on a slack line), fully suspended (no seabed), and fully
// laid (fairlead on the bed, with friction); split in two halves, and in three unequal parts.
TEST(MultiSegmentCatenary, OneTypeSplitInSegmentsIsTheOneSegmentLine) {
  std::vector<std::pair<std::string, CatenaryLineInputs>> cases;
  cases.emplace_back("oc3", oc3());
  CatenaryLineInputs in = oc3();
  in.friction = 1.0;
  cases.emplace_back("friction 1", in);
  in.friction = 8.0;
  in.unstretched_length = 1050.0;
  cases.emplace_back("friction 8", in);
  in = oc3();
  in.seabed = false;
  in.unstretched_length = 880.0;
  cases.emplace_back("suspended", in);
  in = oc3();
  in.vertical_span = 0.0;
  in.horizontal_span = 1.0005 * in.unstretched_length;
  in.friction = 1.0;
  cases.emplace_back("fully laid", in);
  for (const auto& [what, whole] : cases) {
    expectSameLine(whole, split(whole, {0.5, 0.5}), what + ", halves");
    expectSameLine(whole, split(whole, {0.3, 0.5, 0.2}), what + ", three parts");
  }
}

// A buoy of zero net force (its buoyancy equal to its weight) changes nothing: the same as the
// line split there (connection forces 0 are what such a buoy gives).
TEST(MultiSegmentCatenary, AttachmentOfZeroNetForceChangesNothing) {
  CatenaryLineInputs parts = split(oc3(), {0.4, 0.6});
  const double rho = 1025.0, g = 9.80665, volume = 2.0, mass = rho * volume;
  parts.connection_forces = {(rho * volume - mass) * g};
  expectSameLine(oc3(), parts, "zero-net buoy");
}

// A chain - wire - chain line (ocean-cases-like: 0.09 m chain, 0.08 m wire) with a clump weight
// and a buoy: see the file's comment.
CatenaryLineInputs chainWireChain() {
  CatenaryLineInputs in;
  in.horizontal_span = 760.0;
  in.vertical_span = 180.0;
  in.segments = {{250.0, 698.09, 384.243e6}, {450.0, 250.0, 5.0e8}, {120.0, 698.09, 384.243e6}};
  in.connection_forces = {-40.0e3, 25.0e3};  // a 40 kN clump, a buoy of 25 kN net uplift
  return in;
}

// The direct integration: x, z at arc length s for fairlead forces (H, V) (see the file's head).
struct Integrated {
  double x = 0.0, z = 0.0;
};

Integrated integrate(const CatenaryLineInputs& in, double H, double V, double upto) {
  const std::vector<CatenarySegment>& segs = in.segments;
  std::vector<double> start = {0.0};
  for (const CatenarySegment& s : segs) start.push_back(start.back() + s.length);
  const size_t n = segs.size();
  // V at the lower end of each segment, from the fairlead down.
  std::vector<double> bottom(n);
  double v = V;
  for (size_t i = n; i-- > 0;) {
    bottom[i] = v - segs[i].weight * segs[i].length;
    v = bottom[i] + (i > 0 ? in.connection_forces[i - 1] : 0.0);
  }
  // The laid part: from the anchor to where V first turns positive.
  double touchdown = 0.0;
  if (in.seabed && bottom[0] < 0.0)
    for (size_t i = 0; i < n; ++i) {
      if (bottom[i] > 0.0) break;
      touchdown = start[i] - bottom[i] / segs[i].weight;
      if (touchdown < start[i + 1]) break;
      touchdown = start[i + 1];
    }
  Integrated r;
  const auto simpson = [](const std::function<double(double)>& f, double a, double b) {
    const int m = 4000;
    const double h = (b - a) / m;
    double sum = f(a) + f(b);
    for (int k = 1; k < m; ++k) sum += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
    return sum * h / 3.0;
  };
  for (size_t i = 0; i < n; ++i) {
    const double a = std::max(start[i], std::min(touchdown, upto)),
                 b = std::min(start[i + 1], upto);
    const double laid_end = std::min(std::min(touchdown, start[i + 1]), upto);
    if (laid_end > start[i]) r.x += (laid_end - start[i]) * (1.0 + H / segs[i].axial_stiffness);
    if (!(b > a)) continue;
    const CatenarySegment& g = segs[i];
    const auto vertical = [&](double s) { return bottom[i] + g.weight * (s - start[i]); };
    const auto tension = [&](double s) { return std::hypot(H, vertical(s)); };
    r.x += simpson([&](double s) { return H / tension(s) + H / g.axial_stiffness; }, a, b);
    r.z += simpson(
        [&](double s) { return vertical(s) / tension(s) + vertical(s) / g.axial_stiffness; }, a, b);
  }
  return r;
}

// The solved line's spans and profile against the integration: 1e-9 of the length (Simpson with
// 4000 intervals a piece: truncation below 1e-10 L here; measured 1.3e-12 m at most, 2e-15 L), laid on the
// seabed and fully suspended; and at every connection and mid-segment point.
TEST(MultiSegmentCatenary, ChainWireChainMatchesTheIntegratedEquations) {
  for (const bool seabed : {true, false}) {
    CatenaryLineInputs in = chainWireChain();
    in.seabed = seabed;
    if (!seabed) in.horizontal_span = 790.0;
    const CatenaryLine line = solveCatenary(in);
    const double L = line.length();
    EXPECT_EQ(line.laid_length > 0.0, seabed) << "the branch this case is meant to check";
    for (const double s : {60.0, 250.0, 475.0, 700.0, 760.0, L}) {
      const Integrated ref = integrate(in, line.horizontal, line.vertical, s);
      const CatenaryPoint p = line.at(s);
      EXPECT_NEAR(p.x, ref.x, 1e-9 * L) << "seabed " << seabed << ", s = " << s;
      EXPECT_NEAR(p.z, ref.z, 1e-9 * L) << "seabed " << seabed << ", s = " << s;
    }
    EXPECT_NEAR(line.at(L).x, in.horizontal_span, 1e-9 * L);
    EXPECT_NEAR(line.at(L).z, in.vertical_span, 1e-9 * L);
  }
}

// A clump weight resting on the bed at the touchdown (the vertical force just above it positive,
// just below it not): the laid length is the clump's arc length exactly, the line matches the
// integration, and its tension steps by the clump's weight across it.
TEST(MultiSegmentCatenary, ClumpWeightAtTheTouchdown) {
  CatenaryLineInputs in = chainWireChain();
  in.connection_forces = {-300.0e3, 0.0};
  in.horizontal_span = 785.0;  // between 780 and 790 m the touchdown stays at the clump
  const CatenaryLine line = solveCatenary(in);
  EXPECT_EQ(line.laid_length, 250.0) << "the branch this case is meant to check";
  const Integrated ref = integrate(in, line.horizontal, line.vertical, line.length());
  EXPECT_NEAR(ref.x, in.horizontal_span, 1e-9 * line.length());
  EXPECT_NEAR(ref.z, in.vertical_span, 1e-9 * line.length());
  EXPECT_GT(line.at(250.0 + 1e-6).tension, line.horizontal);
  EXPECT_LT(line.at(250.0 + 1e-6).tension, std::hypot(line.horizontal, 300.0e3));
}

// A start that never fails: the chain - wire - chain line with its clump and buoy on a grid of
// spans from slack to taut, on the bed and off it: each solves to its spans (1e-9 L at the
// profile's end) in at most 20 Newton iterations (measured 7 at most), or is refused as slack on
// the bed (a CatenaryError, not a NaN).
TEST(MultiSegmentCatenary, SolvesEveryLineOfAGrid) {
  CatenaryLineInputs in = chainWireChain();
  for (bool seabed : {true, false})
    for (double x : {100.0, 400.0, 700.0, 790.0})
      for (double z : {5.0, 100.0, 180.0, 400.0}) {
        in.seabed = seabed;
        in.horizontal_span = x;
        in.vertical_span = z;
        if (std::hypot(x, z) > 1.05 * 820.0) continue;
        try {
          const CatenaryLine line = solveCatenary(in);
          EXPECT_NEAR(line.at(820.0).x, x, 1e-9 * 820.0) << x << " " << z << " " << seabed;
          EXPECT_NEAR(line.at(820.0).z, z, 1e-9 * 820.0) << x << " " << z << " " << seabed;
          EXPECT_LE(line.iterations, 20) << x << " " << z << " " << seabed;
        } catch (const CatenaryError& e) {
          const std::string what = e.what();
          EXPECT_TRUE(seabed && (what.find("slack on the seabed") != std::string::npos ||
                                 what.find("lies on the laid part") != std::string::npos))
              << x << " " << z << " " << seabed << ": " << what;
        }
      }
}

// The laid part with friction, stepped from the touchdown down to the anchor in 1 mm steps: the
// tension falls from H by C_B w per length and by C_B times the weight of each clump passed on
// the bed, never below 0; the laid part spans its length plus int T / EA. Returns that span and
// sets the tension reaching the anchor.
double laidSpan(const CatenaryLineInputs& in, double H, double touchdown, double& anchor_tension) {
  std::vector<double> start = {0.0};
  for (const CatenarySegment& s : in.segments) start.push_back(start.back() + s.length);
  const auto segment = [&](double s) {
    size_t i = 0;
    while (i + 1 < in.segments.size() && s > start[i + 1]) ++i;
    return in.segments[i];
  };
  const int steps = static_cast<int>(std::ceil(touchdown / 1e-3));
  const double ds = touchdown / steps;
  double T = H, span = 0.0;
  for (int k = steps; k > 0; --k) {
    const double hi = k * ds, lo = hi - ds;
    for (size_t c = 0; c < in.connection_forces.size(); ++c)
      if (start[c + 1] > lo && start[c + 1] <= hi && in.connection_forces[c] < 0.0)
        T = std::max(T + in.friction * in.connection_forces[c], 0.0);
    const CatenarySegment g = segment(0.5 * (lo + hi));
    const double below = std::max(T - in.friction * g.weight * ds, 0.0);
    span += ds * (1.0 + 0.5 * (T + below) / g.axial_stiffness);
    T = below;
  }
  anchor_tension = T;
  return span;
}

// Friction on a laid part of two segments with a clump weight resting on it (the touchdown in
// the wire, beyond the clump): C_B = 0.5 (the anchor still pulled) and C_B = 3 (the tension
// reaching zero on the bed). The solved H and V with the stepped laid part and the integrated
// suspended rest (its frictionless laid term replaced) reproduce the spans to 1e-10 L (the 1 mm
// steps: measured 1.2e-11 L at most), and the anchor's force is the stepped tension's at the
// anchor (1e-6 of H; measured 1.3e-7, the steps not landing on the clump).
TEST(MultiSegmentCatenary, FrictionOnALaidPartOfTwoSegmentsWithAClump) {
  for (const auto& [friction, span] : {std::pair{0.5, 780.0}, std::pair{3.0, 760.0}}) {
    CatenaryLineInputs in = chainWireChain();
    in.friction = friction;
    in.horizontal_span = span;
    const CatenaryLine line = solveCatenary(in);
    const double L = line.length(), H = line.horizontal;
    ASSERT_GT(line.laid_length, 250.0) << "the clump lies on the bed: what this case checks";
    double anchor = 0.0;
    const double laid = laidSpan(in, H, line.laid_length, anchor);
    CatenaryLineInputs frictionless = in;
    frictionless.friction = 0.0;
    const Integrated whole = integrate(frictionless, H, line.vertical, L);
    double laid_frictionless = 0.0;  // integrate()'s laid term: L_B (1 + H / EA) a segment
    for (size_t i = 0, s = 0; i < in.segments.size(); s += in.segments[i].length, ++i)
      laid_frictionless += std::max(std::min(line.laid_length - s, in.segments[i].length), 0.0) *
                           (1.0 + H / in.segments[i].axial_stiffness);
    EXPECT_NEAR(whole.x - laid_frictionless + laid, span, 1e-10 * L) << "C_B " << friction;
    EXPECT_NEAR(whole.z, in.vertical_span, 1e-10 * L) << "C_B " << friction;
    EXPECT_NEAR(line.anchor_horizontal, anchor, 1e-6 * H) << "C_B " << friction;
    EXPECT_EQ(anchor > 0.0, friction < 1.0) << "the branch this case is meant to check";
  }
}

TEST(MultiSegmentCatenary, RefusesLinesThatCannotBeStarted) {
  CatenaryLineInputs in = chainWireChain();
  in.connection_forces = {-40.0e3};
  test::expectCatenaryError(in, "1 connection forces for 3 segments");
  in = chainWireChain();
  in.segments[1].weight = -10.0;
  test::expectCatenaryError(in, "submerged weight per length of segment 2 must be positive");
  in = chainWireChain();
  in.connection_forces[0] = std::nan("");
  test::expectCatenaryError(in, "force at connection point 1 must be finite");
  in = chainWireChain();
  in.connection_forces = {30.0e3, 0.0};  // a buoy where the line lies on the bed
  in.horizontal_span = 700.0;
  test::expectCatenaryError(in, "the buoy at connection point 1 lies on the laid part");
  in = chainWireChain();
  in.horizontal_span = 400.0;
  test::expectCatenaryError(in, "slack on the seabed");
  in = chainWireChain();
  in.horizontal_span = 1000.0;
  test::expectCatenaryError(in, "too short for its span");
}

}  // namespace
}  // namespace flexmoor::hydro

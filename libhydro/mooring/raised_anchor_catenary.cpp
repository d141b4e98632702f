#include "libhydro/mooring/raised_anchor_catenary.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace flexmoor::hydro::catenary_detail {
namespace {

// The line at horizontal force H: the anchor part's length s_1 and where the fairlead part
// starts, s_2 (s_1 >= s_2: the parts overlap, the line does not lie on the bed).
struct Parts {
  double H, s1, s2;
};

// The drop from the anchor to s with V = 0 just below s (s the anchor part's touchdown).
double anchorDrop(const Line& l, double H, double s) {
  return -suspendedStretch(l, 0.0, s, verticalBelow(l, 0.0, s, 0.0), H).span.y();
}

// The rise from s (its touchdown, V = 0 just above it) to the fairlead.
double fairleadRise(const Line& l, double H, double s) {
  return suspendedStretch(l, s, l.length(), 0.0, H).span.y();
}

Parts partsAt(const Line& l, double H, int& steps) {
  const double L = l.length(), h_anchor = l.in.anchor_height;
  const double h_fairlead = l.in.vertical_span + h_anchor;
  Parts p{H, L, 0.0};
  // The drop grows with s_1, the rise falls with s_2; a part that cannot reach the bed takes the
  // whole line.
  if (anchorDrop(l, H, L) > h_anchor)
    p.s1 = bisect([&](double s) { return anchorDrop(l, H, s) - h_anchor; }, 0.0, L, steps);
  if (fairleadRise(l, H, 0.0) > h_fairlead)
    p.s2 = bisect([&](double s) { return h_fairlead - fairleadRise(l, H, s); }, 0.0, L, steps);
  return p;
}

// The laid part's horizontal length: each segment's share of [s_1, s_2] stretched by H / EA
// (negative when the parts overlap, continuing the span through s_1 = s_2).
double laidSpan(const Line& l, const Parts& p) {
  if (!(p.s2 > p.s1)) return p.s2 - p.s1;
  double x = 0.0;
  for (size_t i = 0; i < l.segments.size(); ++i) {
    const double r = std::min(p.s2, l.start[i + 1]) - std::max(p.s1, l.start[i]);
    if (r > 0.0) x += r * (1.0 + p.H / l.segments[i].axial_stiffness);
  }
  return x;
}

double horizontalSpan(const Line& l, const Parts& p) {
  const double L = l.length();
  const double anchor_part =
      suspendedStretch(l, 0.0, p.s1, verticalBelow(l, 0.0, p.s1, 0.0), p.H).span.x();
  const double fairlead_part = suspendedStretch(l, p.s2, L, 0.0, p.H).span.x();
  return anchor_part + laidSpan(l, p) + fairlead_part;
}

// A buoy (F_c > 0) on the laid part would lift it off the bed; one on a hanging part that turns
// its vertical force's sign would lift that part below its touchdown.
void checkBuoys(const Line& l, const Parts& p) {
  for (size_t c = 0; c < l.forces.size(); ++c) {
    const double at = l.start[c + 1];
    if (l.forces[c] > 0.0 && at > p.s1 && at < p.s2)
      throw CatenaryError("catenary: the buoy at connection point " + std::to_string(c + 1) +
                          " lies on the laid part (got " + str(l.forces[c]) + " of uplift at " +
                          str(at) + " from the anchor, laid from " + str(p.s1) + " to " +
                          str(p.s2) + "; expected buoys on the suspended parts)");
  }
  const double tolerance = 1e-12 * l.forceScale();
  const Stretch anchor_part = suspendedStretch(l, 0.0, p.s1, verticalBelow(l, 0.0, p.s1, 0.0), p.H);
  const Stretch fairlead_part = suspendedStretch(l, p.s2, l.length(), 0.0, p.H);
  if (anchor_part.largest > tolerance || fairlead_part.least < -tolerance)
    throw CatenaryError(
        "catenary: a buoy lifts a part hanging down to the bed below its touchdown (got a vertical "
        "force of " +
        str(anchor_part.largest > tolerance ? anchor_part.largest : fairlead_part.least) +
        " on it, expected none against the part's slope: a shape this start does not solve)");
}

}  // namespace

std::optional<CatenaryLine> solveLaidBetweenHangingParts(const Line& l) {
  int steps = 0;
  const double x_F = l.in.horizontal_span, scale = l.forceScale();
  // Near H = 0 the parts hang straight down and the rest lies on the bed with no tension.
  const double H_slack = 1e-12 * scale;
  const Parts slack = partsAt(l, H_slack, steps);
  if (!(slack.s1 < slack.s2)) return std::nullopt;  // even hanging straight down, it does not
  const double slack_span = horizontalSpan(l, slack);
  if (!(x_F > slack_span))
    throw CatenaryError(
        "catenary: the line is too long for its span: it would lie slack on the seabed between "
        "the parts hanging from the anchor and the fairlead (got " +
        str(l.length()) + " unstretched for a span of " + str(x_F) + ", with " + str(slack.s1) +
        " hanging straight down from the anchor to the bed and " + str(l.length() - slack.s2) +
        " from the fairlead, expected less than the span and both: the shape of a slack laid line "
        "is not determined)");
  // The H at which the parts meet (they grow with H): the line touching the bed at one point.
  const auto overlap = [&](double H) {
    const Parts p = partsAt(l, H, steps);
    return p.s1 - p.s2;
  };
  double H_touch = scale;
  for (int k = 0; k < 60 && overlap(H_touch) < 0.0; ++k) H_touch *= 4.0;
  H_touch = bisect(overlap, H_slack, H_touch, steps);
  if (horizontalSpan(l, partsAt(l, H_touch, steps)) <= x_F) return std::nullopt;  // taut: clear
  const double H = bisect([&](double H) { return horizontalSpan(l, partsAt(l, H, steps)) - x_F; },
                          H_slack, H_touch, steps);
  const Parts p = partsAt(l, H, steps);
  checkBuoys(l, p);
  CatenaryLine line;
  line.inputs = l.in;
  line.segments = l.segments;
  line.horizontal = H;
  line.vertical = suspendedStretch(l, p.s2, l.length(), 0.0, H).top;
  line.anchor_horizontal = H;
  line.anchor_vertical = verticalBelow(l, 0.0, p.s1, 0.0);
  line.laid_from = p.s1;
  line.laid_length = p.s2 - p.s1;
  line.iterations = steps;
  return line;
}

CatenaryPoint pointLaidBetweenHangingParts(const Line& l, const CatenaryLine& line, double s) {
  const double H = line.horizontal, s1 = line.laid_from, s2 = s1 + line.laid_length;
  s = std::clamp(s, 0.0, l.length());
  CatenaryPoint point;
  const Stretch anchor_part = suspendedStretch(l, 0.0, std::min(s, s1), line.anchor_vertical, H);
  point.x = anchor_part.span.x();
  point.z = anchor_part.span.y();
  point.tension = std::hypot(H, anchor_part.top);
  if (s <= s1) return point;
  point.x += laidSpan(l, {H, s1, std::min(s, s2)});
  point.tension = H;
  if (s <= s2) return point;
  const Stretch fairlead_part = suspendedStretch(l, s2, s, 0.0, H);
  point.x += fairlead_part.span.x();
  point.z += fairlead_part.span.y();
  point.tension = std::hypot(H, fairlead_part.top);
  return point;
}

}  // namespace flexmoor::hydro::catenary_detail

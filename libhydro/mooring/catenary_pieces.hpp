#pragma once
// The pieces an elastic catenary line is made of, shared by its solves (catenary_line.cpp: the
// anchor on the bed or the line hanging clear; raised_anchor_catenary.cpp: a line laid on the bed
// between the parts hanging from a raised anchor and from the fairlead). Internal to
// libhydro/mooring: the product's interface is catenary_line.hpp.
//
// Along the line, s is the unstretched arc length from the anchor; V(s) is the vertical force the
// line above s pulls the line below it up with, H the horizontal force (the same everywhere on a
// line without friction). Going up a segment V grows by its submerged weight w_i per length;
// across connection point c it falls by the point force F_c (+ up: a buoy's net buoyancy), the
// point's force balance V_below = V_above + F_c.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "libhydro/mooring/catenary_line.hpp"

namespace flexmoor::hydro::catenary_detail {

inline std::string str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The anchor lies on the bed that carries the line (the MAP++ equations with a laid part from the
// anchor); a raised anchor's line is solved by raised_anchor_catenary.cpp.
inline bool anchorOnBed(const CatenaryLineInputs& in) {
  return in.seabed && !(in.anchor_height > 0.0);
}

// The line as the solves see it: its segments from the anchor, the force at each connection
// (none for one segment) and the arc length where each segment starts (start[n] = L).
struct Line {
  const CatenaryLineInputs& in;
  std::vector<CatenarySegment> segments;
  std::vector<double> forces;
  std::vector<double> start;
  double length() const { return start.back(); }
  // The submerged weight of the whole line with its point forces, and a scale for forces.
  double netWeight() const;
  double forceScale() const;
};

Line makeLine(const CatenaryLineInputs& in);

// A laid piece [from, to] of one segment: T(s) = max(top_tension - rate (to - s), 0), rate = C_B w.
struct LaidPiece {
  double from, to, top_tension, rate, ea;
  // int T ds over [a, b] (within the piece) and the length of it in tension.
  std::pair<double, double> integral(double a, double b) const {
    const double zero = rate > 0.0 ? to - top_tension / rate : (top_tension > 0.0 ? a : b);
    const double lo = std::max(a, zero);
    if (!(lo < b)) return {0.0, 0.0};
    return {(b - lo) * (tension(lo) + tension(b)) / 2.0, b - lo};
  }
  double tension(double s) const { return std::max(top_tension - rate * (to - s), 0.0); }
};

// A suspended piece of one segment, `length` from `from` up, its vertical force `bottom` at its
// lower end (V at its top: bottom + w length).
struct HangingPiece {
  double from, length, bottom, weight, ea;
};

// What a piece adds to the spans (x, z), and its Jacobian d(x, z)/d(H, V) at fixed length (V
// moving the vertical forces of every piece alike), over the length r from its lower end:
//   x = H/w [asinh(a) - asinh(b)] + H r / EA, z = H/w [sqrt(1 + a^2) - sqrt(1 + b^2)]
//       + (V_b r + w r^2 / 2) / EA, a = (V_b + w r) / H, b = V_b / H.
struct Spans {
  Eigen::Vector2d value = Eigen::Vector2d::Zero();
  Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();
};

Spans hangingSpans(const HangingPiece& p, double H, double r);

// The suspended stretch [a, b] of the line (over any segments and connections) at horizontal
// force H with the vertical force V_a just above a: its spans (x, z) from a, the vertical force
// just below b, and the least and largest V along it.
struct Stretch {
  Eigen::Vector2d span = Eigen::Vector2d::Zero();
  double top = 0.0;
  double least = 0.0, largest = 0.0;
};
Stretch suspendedStretch(const Line& l, double a, double b, double V_a, double H);

// The vertical force just above a on a line whose force just below b is V_b (a < b): V_b less the
// weight between them plus the forces of the connections strictly between them.
double verticalBelow(const Line& l, double a, double b, double V_b);

// Bisection of a monotone increasing g on [lo, hi] (g(lo) <= 0 <= g(hi)) to round-off.
template <class G>
double bisect(G g, double lo, double hi, int& steps) {
  for (int k = 0; k < 200 && hi - lo > 1e-15 * std::max(std::abs(lo), std::abs(hi)); ++k) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) <= 0.0 ? lo : hi) = mid;
    ++steps;
  }
  return 0.5 * (lo + hi);
}

}  // namespace flexmoor::hydro::catenary_detail

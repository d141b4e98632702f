#include "libhydro/mooring/catenary_line.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "libhydro/mooring/catenary_pieces.hpp"
#include "libhydro/mooring/raised_anchor_catenary.hpp"

namespace flexmoor::hydro {
namespace {

using namespace catenary_detail;

// The line at fairlead forces (H, V): its laid pieces (from the touchdown down) and its hanging
// pieces (from the touchdown up).
struct Profile {
  double touchdown = 0.0;  // L_B (beyond L when V < 0 on a laid line: the equations' extension)
  std::vector<LaidPiece> laid;
  std::vector<HangingPiece> hanging;
  double anchor_tension = 0.0;   // T at the anchor, on the bed
  double anchor_vertical = 0.0;  // V at the anchor, suspended
  std::vector<int> laid_buoys;   // connections with F > 0 on the laid part
};

Profile profile(const Line& l, double H, double V) {
  const int n = static_cast<int>(l.segments.size());
  std::vector<double> top(n), bottom(n);  // vertical force at each segment's ends
  double v = V;
  for (int i = n - 1; i >= 0; --i) {
    top[i] = v;
    bottom[i] = v - l.segments[i].weight * l.segments[i].length;
    v = bottom[i] + (i > 0 ? l.forces[i - 1] : 0.0);
  }
  Profile p;
  int touch = -1;              // the segment of the touchdown
  bool at_connection = false;  // at its lower connection: a clump weight resting on the bed
  if (anchorOnBed(l.in) && bottom[0] < 0.0) {
    touch = n - 1;  // V <= 0 all the way up: the top segment's equations, extended
    for (int i = 0; i < n; ++i) {
      if (i > 0 && bottom[i] > 0.0) {
        touch = i;
        at_connection = true;
        break;
      }
      if (top[i] > 0.0) {
        touch = i;
        break;
      }
    }
  }
  const auto hang = [&](int i) {
    p.hanging.push_back({l.start[i], l.segments[i].length, bottom[i], l.segments[i].weight,
                         l.segments[i].axial_stiffness});
  };
  if (touch < 0) {
    for (int i = 0; i < n; ++i) hang(i);
    p.anchor_vertical = bottom[0];
    return p;
  }
  const CatenarySegment& t = l.segments[touch];
  if (at_connection) {
    p.touchdown = l.start[touch];
    hang(touch);
  } else {
    p.touchdown = l.start[touch] - bottom[touch] / t.weight;
    p.hanging.push_back({p.touchdown, top[touch] / t.weight, 0.0, t.weight, t.axial_stiffness});
  }
  for (int i = touch + 1; i < n; ++i) hang(i);
  const int highest = at_connection ? touch - 1 : touch;  // the highest segment with a laid piece
  double T = H;
  for (int i = highest; i >= 0; --i) {
    const double to = i == highest ? p.touchdown : l.start[i + 1];
    if (i < touch) {  // connection i lies on the bed at `to`: its share of the bed's reaction
      const double normal = i == touch - 1 && at_connection ? -top[i] : -l.forces[i];
      if (l.forces[i] > 0.0) p.laid_buoys.push_back(i);
      T = std::max(T - l.in.friction * std::max(normal, 0.0), 0.0);
    }
    const CatenarySegment& s = l.segments[i];
    p.laid.push_back({l.start[i], to, T, l.in.friction * s.weight, s.axial_stiffness});
    T = p.laid.back().tension(l.start[i]);
  }
  p.anchor_tension = T;
  return p;
}

// The spans (x_F, z_F) that the fairlead forces (H, V) give, and their Jacobian: the pieces'
// sum, the laid part adding its length, its stretch int T / EA, and d/dH = d/dV / C_B = the
// length in tension over EA (T rises with H, and by C_B for each unit of V the touchdown's
// friction or a clump's reaction gives up).
Spans spans(const Line& l, double H, double V) {
  const Profile p = profile(l, H, V);
  Spans s;
  s.value(0) = p.touchdown;
  for (const LaidPiece& piece : p.laid) {
    const auto [integral, taut] = piece.integral(piece.from, piece.to);
    s.value(0) += integral / piece.ea;
    s.jacobian(0, 0) += taut / piece.ea;
    s.jacobian(0, 1) += l.in.friction * taut / piece.ea;
  }
  for (const HangingPiece& piece : p.hanging) {
    const Spans h = hangingSpans(piece, H, piece.length);
    s.value += h.value;
    s.jacobian += h.jacobian;
  }
  return s;
}

double residualNorm(const Line& l, const Eigen::Vector2d& f) {
  return (spans(l, f(0), f(1)).value - Eigen::Vector2d(l.in.horizontal_span, l.in.vertical_span))
      .norm();
}

// The residual a converged solve reaches: 1e-12 of the line's length (round-off of the spans).
double tolerance(const Line& l) { return 1e-12 * l.length(); }

// Safeguarded Newton from f; returns whether it converged, counting its iterations.
bool newton(const Line& l, Eigen::Vector2d& f, int& iterations, int max_iterations) {
  const Eigen::Vector2d target(l.in.horizontal_span, l.in.vertical_span);
  double r_norm = residualNorm(l, f);
  for (int it = 0; it < max_iterations; ++it) {
    if (r_norm <= tolerance(l)) return true;
    const Spans s = spans(l, f(0), f(1));
    Eigen::Vector2d step = s.jacobian.partialPivLu().solve(target - s.value);
    if (!step.allFinite()) return false;
    // Keep H above a tenth of its value: the equations hold for H > 0 only.
    if (f(0) + step(0) < 0.1 * f(0)) step *= 0.9 * f(0) / -step(0);
    double scale = 1.0;
    Eigen::Vector2d trial = f + step;
    double trial_norm = residualNorm(l, trial);
    for (int k = 0; k < 40 && !(trial_norm < r_norm); ++k) {  // backtrack
      scale *= 0.5;
      trial = f + scale * step;
      trial_norm = residualNorm(l, trial);
    }
    ++iterations;
    if (!(trial_norm < r_norm)) return trial_norm <= tolerance(l);
    f = trial;
    r_norm = trial_norm;
  }
  return r_norm <= tolerance(l);
}

// The vertical force V at which H gives the vertical span (z_F rises monotonically with V).
double verticalFor(const Line& l, double H, int& steps) {
  const double wl = l.forceScale();
  const auto g = [&](double V) { return spans(l, H, V).value(1) - l.in.vertical_span; };
  double lo = anchorOnBed(l.in) ? 0.0 : -wl, hi = wl;
  while (g(lo) > 0.0) lo -= 2.0 * (hi - lo);
  while (g(hi) < 0.0) hi += 2.0 * (hi - lo);
  return bisect(g, lo, hi, steps);
}

// The bracketing fallback: H for the horizontal span along the curve of the vertical one.
Eigen::Vector2d nestedBisection(const Line& l, int& steps) {
  const auto g = [&](double H) {
    return spans(l, H, verticalFor(l, H, steps)).value(0) - l.in.horizontal_span;
  };
  double lo = 1e-6 * l.forceScale(), hi = l.forceScale();
  while (g(lo) > 0.0) lo *= 1e-3;
  while (g(hi) < 0.0) hi *= 4.0;
  const double H = bisect(g, lo, hi, steps);
  return {H, verticalFor(l, H, steps)};
}

// Peyrot and Goulois' start (MAP++'s): lambda from the length over the chord, the line's mean
// submerged weight (without its buoys, should they outweigh it).
Eigen::Vector2d initialGuess(const Line& l) {
  const double x = l.in.horizontal_span, z = l.in.vertical_span, L = l.length();
  double weight = l.netWeight() / L;
  if (!(weight > 0.0)) {  // without the buoys' uplift
    weight = l.netWeight();
    for (const double f : l.forces) weight += std::max(f, 0.0);
    weight /= L;
  }
  const double lambda =
      L * L <= x * x + z * z ? 0.2 : std::sqrt(3.0 * ((L * L - z * z) / (x * x) - 1.0));
  return {std::max(std::abs(weight * x / (2.0 * lambda)), 1e-6 * weight * L),
          0.5 * weight * (z / std::tanh(lambda) + L)};
}

// The height of the line above arc length s hanging straight down from the fairlead with H = 0
// (its stretch under the weight below included; V = 0 at s): sum of L_i + (V_b L_i + w_i L_i^2
// / 2) / EA_i over the pieces above s. It falls as s rises.
double hangingHeight(const Line& l, double s) {
  double height = 0.0, v = 0.0;
  for (size_t i = 0; i < l.segments.size(); ++i) {
    const CatenarySegment& g = l.segments[i];
    const double r = l.start[i + 1] - std::max(s, l.start[i]);
    if (r <= 0.0) continue;
    if (s < l.start[i] && i > 0) v -= l.forces[i - 1];
    height += r + (v * r + 0.5 * g.weight * r * r) / g.axial_stiffness;
    v += g.weight * r;
  }
  return height;
}

// The unstretched length that hangs straight down to the fairlead when H = 0: L - s with
// hangingHeight(s) = z_F (L or more when the whole line hanging does not reach z_F). Laid out
// straight, the rest reaches L - L_s along the bed: a span not beyond that leaves the line slack
// (H = 0, no catenary).
double hangingLength(const Line& l) {
  const double z = std::max(l.in.vertical_span, 0.0), L = l.length();
  if (hangingHeight(l, 0.0) <= z) return L;
  int steps = 0;
  return L - bisect([&](double s) { return z - hangingHeight(l, s); }, 0.0, L, steps);
}

void checkPositive(double v, const std::string& what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw CatenaryError("catenary: " + what + " must be positive and finite (got " + str(v) + ")");
}

void check(const Line& l) {
  const CatenaryLineInputs& in = l.in;
  const bool several = in.segments.size() > 1;
  for (size_t i = 0; i < l.segments.size(); ++i) {
    const std::string of = several ? " of segment " + std::to_string(i + 1) : "";
    checkPositive(l.segments[i].length, "the unstretched length" + of);
    checkPositive(l.segments[i].weight, "the submerged weight per length" + of);
    checkPositive(l.segments[i].axial_stiffness, "the axial stiffness EA" + of);
  }
  if (!in.segments.empty() && in.connection_forces.size() + 1 != in.segments.size())
    throw CatenaryError("catenary: " + std::to_string(in.connection_forces.size()) +
                        " connection forces for " + std::to_string(in.segments.size()) +
                        " segments (expected one for each connection point, " +
                        std::to_string(in.segments.size() - 1) + ")");
  for (size_t c = 0; c < l.forces.size(); ++c)
    if (!std::isfinite(l.forces[c]))
      throw CatenaryError("catenary: the force at connection point " + std::to_string(c + 1) +
                          " must be finite (got " + str(l.forces[c]) + ")");
  checkPositive(in.max_strain, "the largest strain");
  if (!(in.friction >= 0.0) || !std::isfinite(in.friction))
    throw CatenaryError("catenary: the seabed friction coefficient must be zero or positive (got " +
                        str(in.friction) + ")");
  if (!std::isfinite(in.vertical_span) || !(in.horizontal_span > 0.0) ||
      !std::isfinite(in.horizontal_span))
    throw CatenaryError("catenary: no horizontal span between anchor and fairlead (got " +
                        str(in.horizontal_span) +
                        ", expected > 0: a vertical line has no catenary start)");
  if (in.seabed && (!(in.anchor_height >= 0.0) || !std::isfinite(in.anchor_height)))
    throw CatenaryError("catenary: the anchor is below the seabed (got " + str(in.anchor_height) +
                        " above the bed, expected >= 0)");
  if (in.seabed && in.vertical_span < -in.anchor_height)
    throw CatenaryError("catenary: the fairlead is below the seabed (got " + str(in.vertical_span) +
                        " above the anchor, " + str(in.anchor_height) +
                        " above the bed, expected >= " + str(-in.anchor_height) + ")");
  const double L = l.length(), chord = std::hypot(in.horizontal_span, in.vertical_span);
  const double strain = chord / L - 1;
  if (strain > in.max_strain)
    throw CatenaryError("catenary: the line is too short for its span (got a chord of " +
                        str(chord) + " for " + str(L) + " unstretched, a strain of " + str(strain) +
                        ", expected at most " + str(in.max_strain) + ")");
  if (!anchorOnBed(in)) return;  // a raised anchor's slack line: raised_anchor_catenary.cpp
  const double hanging = hangingLength(l);
  if (in.horizontal_span <= L - hanging)
    throw CatenaryError(
        "catenary: the line is too long for its span: it would lie slack on the seabed (got " +
        str(L) + " unstretched for a span of " + str(in.horizontal_span) + " and " + str(hanging) +
        " hanging straight down to the fairlead, expected "
        "less than their sum: the shape of a slack laid line is not determined)");
}

// A taut line on the bed (z_F = 0, x_F > L): V = 0 and the laid part's stretch x_F - L fixes H
// (it rises with H): bisection to round-off.
double fullyLaidHorizontal(const Line& l, int& steps) {
  const auto g = [&](double H) { return spans(l, H, 0.0).value(0) - l.in.horizontal_span; };
  double hi = l.forceScale();
  for (const CatenarySegment& s : l.segments)
    hi = std::max(hi, s.axial_stiffness * (l.in.horizontal_span / l.length() - 1.0));
  while (g(hi) < 0.0) hi *= 2.0;
  return bisect(g, 0.0, hi, steps);
}

}  // namespace

double CatenaryLine::length() const { return makeLine(inputs).length(); }
double CatenaryLine::fairleadTension() const { return std::hypot(horizontal, vertical); }
double CatenaryLine::anchorTension() const {
  return std::hypot(anchor_horizontal, anchor_vertical);
}

CatenaryPoint CatenaryLine::at(double s) const {
  const Line l = makeLine(inputs);
  if (laid_from > 0.0) return pointLaidBetweenHangingParts(l, *this, s);
  const Profile p = profile(l, horizontal, vertical);
  s = std::clamp(s, 0.0, l.length());
  CatenaryPoint point;
  point.tension = p.laid.empty() ? std::hypot(horizontal, p.anchor_vertical) : p.anchor_tension;
  for (auto piece = p.laid.rbegin(); piece != p.laid.rend() && s > piece->from; ++piece) {
    const double to = std::min(s, piece->to);
    point.x += to - piece->from + piece->integral(piece->from, to).first / piece->ea;
    point.tension = piece->tension(to);
  }
  if (s <= p.touchdown) return point;
  for (const HangingPiece& piece : p.hanging) {
    if (s <= piece.from) break;
    const double r = std::min(s - piece.from, piece.length);
    const Spans h = hangingSpans(piece, horizontal, r);
    point.x += h.value(0);
    point.z += h.value(1);
    point.tension = std::hypot(horizontal, piece.bottom + piece.weight * r);
  }
  return point;
}

CatenaryLine solveCatenary(const CatenaryLineInputs& in) {
  const Line l = makeLine(in);
  check(l);
  if (in.seabed && in.anchor_height > 0.0)
    if (std::optional<CatenaryLine> laid = solveLaidBetweenHangingParts(l)) return *laid;
  CatenaryLine line;  // from here, a raised anchor's line hangs clear of the bed
  line.inputs = in;
  line.segments = l.segments;
  Eigen::Vector2d f;
  const bool fully_laid = anchorOnBed(in) && in.vertical_span == 0.0;
  if (fully_laid) {
    f = {fullyLaidHorizontal(l, line.iterations), 0.0};
  } else {
    f = initialGuess(l);
    if (!newton(l, f, line.iterations, 100)) {
      f = nestedBisection(l, line.iterations);
      if (!newton(l, f, line.iterations, 20))
        throw CatenaryError("catenary: no solution found to " + str(tolerance(l)) +
                            " of the spans (a line this solve should start: please report it)");
    }
  }
  line.horizontal = f(0);
  line.vertical = f(1);
  const Profile p = profile(l, f(0), f(1));
  if (!p.laid_buoys.empty())
    throw CatenaryError(
        "catenary: the buoy at connection point " + std::to_string(p.laid_buoys.front() + 1) +
        " lies on the laid part (got " + str(l.forces[p.laid_buoys.front()]) + " of uplift at " +
        str(l.start[p.laid_buoys.front() + 1]) + " from the anchor, " + str(p.touchdown) +
        " laid; expected buoys on the suspended part: one on the bed would lift it there)");
  line.laid_length = fully_laid ? l.length() : std::min(p.touchdown, l.length());
  if (p.laid.empty()) {
    line.anchor_horizontal = f(0);
    line.anchor_vertical = p.anchor_vertical;
  } else {
    line.anchor_horizontal = p.anchor_tension;
  }
  return line;
}

}  // namespace flexmoor::hydro

#include "libhydro/mooring/catenary_line.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace flexmoor::hydro {
namespace {

std::string str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The spans (x_F, z_F) that the fairlead forces (H, V) give, and their Jacobian d(x, z)/d(H, V).
struct Spans {
  Eigen::Vector2d value;
  Eigen::Matrix2d jacobian;
};

bool onSeabed(const CatenaryLineInputs& in, double V) {
  return in.seabed && V < in.weight * in.unstretched_length;
}

// Stretch of the laid part up to s (<= L_B): (1/EA) int_0^s T, T = max(H - C_B w (L_B - s), 0).
double laidStretch(const CatenaryLineInputs& in, double H, double laid, double s) {
  const double cw = in.friction * in.weight;
  const double start = cw > 0.0 ? std::max(laid - H / cw, 0.0) : 0.0;  // where T reaches 0
  if (s <= start) return 0.0;
  return ((H - cw * laid) * (s - start) + 0.5 * cw * (s * s - start * start)) / in.axial_stiffness;
}

Spans spans(const CatenaryLineInputs& in, double H, double V) {
  const double w = in.weight, L = in.unstretched_length, EA = in.axial_stiffness;
  const double a = V / H, ra = std::sqrt(1.0 + a * a);
  Spans s;
  if (onSeabed(in, V)) {  // partly on the seabed, friction on the laid part
    const double laid = L - V / w;
    const double cw = in.friction * w;
    const double start = cw > 0.0 ? laid - H / cw : -1.0;  // s0 of the friction term
    double friction = 0.0, dfdH = 0.0, dfdV = 0.0;
    if (cw > 0.0 && start > 0.0) {
      friction = cw / (2.0 * EA) * (start * start - laid * laid);
      dfdH = -start / EA;
      dfdV = H / (w * EA);
    } else if (cw > 0.0) {
      friction = -cw / (2.0 * EA) * laid * laid;
      dfdV = in.friction * laid / EA;
    }
    s.value = {laid + H / w * std::asinh(a) + H * L / EA + friction,
               H / w * (ra - 1.0) + V * V / (2.0 * EA * w)};
    s.jacobian << std::asinh(a) / w - a / (w * ra) + L / EA + dfdH,
        -1.0 / w + 1.0 / (w * ra) + dfdV, (1.0 / ra - 1.0) / w, a / (w * ra) + V / (EA * w);
    return s;
  }
  const double b = (V - w * L) / H, rb = std::sqrt(1.0 + b * b);  // suspended
  s.value = {H / w * (std::asinh(a) - std::asinh(b)) + H * L / EA,
             H / w * (ra - rb) + (V * L - 0.5 * w * L * L) / EA};
  s.jacobian << (std::asinh(a) - std::asinh(b)) / w - (a / ra - b / rb) / w + L / EA,
      (1.0 / ra - 1.0 / rb) / w, (1.0 / ra - 1.0 / rb) / w, (a / ra - b / rb) / w + L / EA;
  return s;
}

double residualNorm(const CatenaryLineInputs& in, const Eigen::Vector2d& f) {
  return (spans(in, f(0), f(1)).value - Eigen::Vector2d(in.horizontal_span, in.vertical_span))
      .norm();
}

// The residual a converged solve reaches: 1e-12 of the line's length (round-off of the spans).
double tolerance(const CatenaryLineInputs& in) { return 1e-12 * in.unstretched_length; }

// Safeguarded Newton from f; returns whether it converged, counting its iterations.
bool newton(const CatenaryLineInputs& in, Eigen::Vector2d& f, int& iterations, int max_iterations) {
  const Eigen::Vector2d target(in.horizontal_span, in.vertical_span);
  double r_norm = residualNorm(in, f);
  for (int it = 0; it < max_iterations; ++it) {
    if (r_norm <= tolerance(in)) return true;
    const Spans s = spans(in, f(0), f(1));
    Eigen::Vector2d step = s.jacobian.partialPivLu().solve(target - s.value);
    if (!step.allFinite()) return false;
    // Keep H above a tenth of its value: the equations hold for H > 0 only.
    if (f(0) + step(0) < 0.1 * f(0)) step *= 0.9 * f(0) / -step(0);
    double scale = 1.0;
    Eigen::Vector2d trial = f + step;
    double trial_norm = residualNorm(in, trial);
    for (int k = 0; k < 40 && !(trial_norm < r_norm); ++k) {  // backtrack
      scale *= 0.5;
      trial = f + scale * step;
      trial_norm = residualNorm(in, trial);
    }
    ++iterations;
    if (!(trial_norm < r_norm)) return trial_norm <= tolerance(in);
    f = trial;
    r_norm = trial_norm;
  }
  return r_norm <= tolerance(in);
}

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

// The vertical force V at which H gives the vertical span (z_F rises monotonically with V).
double verticalFor(const CatenaryLineInputs& in, double H, int& steps) {
  const double wl = in.weight * in.unstretched_length;
  const auto g = [&](double V) { return spans(in, H, V).value(1) - in.vertical_span; };
  double lo = in.seabed ? 0.0 : -wl, hi = wl;
  while (g(lo) > 0.0) lo -= 2.0 * (hi - lo);
  while (g(hi) < 0.0) hi += 2.0 * (hi - lo);
  return bisect(g, lo, hi, steps);
}

// The bracketing fallback: H for the horizontal span along the curve of the vertical one.
Eigen::Vector2d nestedBisection(const CatenaryLineInputs& in, int& steps) {
  const auto g = [&](double H) {
    return spans(in, H, verticalFor(in, H, steps)).value(0) - in.horizontal_span;
  };
  double lo = 1e-6 * in.weight * in.unstretched_length, hi = in.weight * in.unstretched_length;
  while (g(lo) > 0.0) lo *= 1e-3;
  while (g(hi) < 0.0) hi *= 4.0;
  const double H = bisect(g, lo, hi, steps);
  return {H, verticalFor(in, H, steps)};
}

// Peyrot and Goulois' start (MAP++'s): lambda from the length over the chord.
Eigen::Vector2d initialGuess(const CatenaryLineInputs& in) {
  const double x = in.horizontal_span, z = in.vertical_span, L = in.unstretched_length;
  const double lambda =
      L * L <= x * x + z * z ? 0.2 : std::sqrt(3.0 * ((L * L - z * z) / (x * x) - 1.0));
  return {std::max(std::abs(in.weight * x / (2.0 * lambda)), 1e-6 * in.weight * L),
          0.5 * in.weight * (z / std::tanh(lambda) + L)};
}

// The unstretched length that hangs straight down from the fairlead when H = 0 (its stretch under
// its own weight included): L_s (1 + w L_s / (2 EA)) = z_F. Laid out straight, the rest reaches
// L - L_s along the bed: a span not beyond that leaves the line slack (H = 0, no catenary).
double hangingLength(const CatenaryLineInputs& in) {
  const double c = in.weight / (2.0 * in.axial_stiffness), z = std::max(in.vertical_span, 0.0);
  return 2.0 * z / (1.0 + std::sqrt(1.0 + 4.0 * c * z));
}

void check(const CatenaryLineInputs& in) {
  const auto positive = [](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw CatenaryError(std::string("catenary: ") + what + " must be positive and finite (got " +
                          str(v) + ")");
  };
  positive(in.unstretched_length, "the unstretched length");
  positive(in.weight, "the submerged weight per length");
  positive(in.axial_stiffness, "the axial stiffness EA");
  positive(in.max_strain, "the largest strain");
  if (!(in.friction >= 0.0) || !std::isfinite(in.friction))
    throw CatenaryError("catenary: the seabed friction coefficient must be zero or positive (got " +
                        str(in.friction) + ")");
  if (!std::isfinite(in.vertical_span) || !(in.horizontal_span > 0.0) ||
      !std::isfinite(in.horizontal_span))
    throw CatenaryError("catenary: no horizontal span between anchor and fairlead (got " +
                        str(in.horizontal_span) +
                        ", expected > 0: a vertical line has no catenary start)");
  if (in.seabed && in.vertical_span < 0.0)
    throw CatenaryError("catenary: the fairlead is below the seabed (got " + str(in.vertical_span) +
                        " above the anchor on the bed, expected >= 0)");
  const double strain =
      std::hypot(in.horizontal_span, in.vertical_span) / in.unstretched_length - 1;
  if (strain > in.max_strain)
    throw CatenaryError("catenary: the line is too short for its span (got a chord of " +
                        str(std::hypot(in.horizontal_span, in.vertical_span)) + " for " +
                        str(in.unstretched_length) + " unstretched, a strain of " + str(strain) +
                        ", expected at most " + str(in.max_strain) + ")");
  if (in.seabed && in.horizontal_span <= in.unstretched_length - hangingLength(in))
    throw CatenaryError(
        "catenary: the line is too long for its span: it would lie slack on the seabed (got " +
        str(in.unstretched_length) + " unstretched for a span of " + str(in.horizontal_span) +
        " and " + str(hangingLength(in)) +
        " hanging straight down to the fairlead, expected "
        "less than their sum: the shape of a slack laid line is not determined)");
}

// A taut line on the bed (z_F = 0, x_F > L): V = 0 and the stretch x_F - L fixes H.
double fullyLaidHorizontal(const CatenaryLineInputs& in) {
  const double stretch = in.horizontal_span - in.unstretched_length;
  const double cw = in.friction * in.weight, L = in.unstretched_length, EA = in.axial_stiffness;
  if (cw > 0.0) {
    const double h = std::sqrt(2.0 * EA * cw * stretch);  // T reaches 0 on the bed
    if (h <= cw * L) return h;
    return (EA * stretch + 0.5 * cw * L * L) / L;  // the whole line in tension
  }
  return EA * stretch / L;
}

}  // namespace

double CatenaryLine::fairleadTension() const { return std::hypot(horizontal, vertical); }
double CatenaryLine::anchorTension() const {
  return std::hypot(anchor_horizontal, anchor_vertical);
}

CatenaryPoint CatenaryLine::at(double s) const {
  const CatenaryLineInputs& in = inputs;
  const double w = in.weight, EA = in.axial_stiffness, H = horizontal;
  s = std::clamp(s, 0.0, in.unstretched_length);
  CatenaryPoint p;
  if (laid_length > 0.0) {
    const double on_bed = std::min(s, laid_length);
    p.x = on_bed + laidStretch(in, H, laid_length, on_bed);
    p.tension = std::max(H - in.friction * w * (laid_length - on_bed), 0.0);
    if (s <= laid_length) return p;
    const double r = s - laid_length, a = w * r / H;
    p.x += H / w * std::asinh(a) + H * r / EA;
    p.z = H / w * (std::sqrt(1.0 + a * a) - 1.0) + w * r * r / (2.0 * EA);
    p.tension = std::hypot(H, w * r);
    return p;
  }
  const double va = vertical - w * in.unstretched_length;
  const double a = (va + w * s) / H, b = va / H;
  p.x = H / w * (std::asinh(a) - std::asinh(b)) + H * s / EA;
  p.z = H / w * (std::sqrt(1.0 + a * a) - std::sqrt(1.0 + b * b)) + (va * s + 0.5 * w * s * s) / EA;
  p.tension = std::hypot(H, va + w * s);
  return p;
}

CatenaryLine solveCatenary(const CatenaryLineInputs& in) {
  check(in);
  CatenaryLine line;
  line.inputs = in;
  Eigen::Vector2d f;
  if (in.seabed && in.vertical_span == 0.0) {
    f = {fullyLaidHorizontal(in), 0.0};
  } else {
    f = initialGuess(in);
    if (!newton(in, f, line.iterations, 100)) {
      f = nestedBisection(in, line.iterations);
      if (!newton(in, f, line.iterations, 20))
        throw CatenaryError("catenary: no solution found to " + str(tolerance(in)) +
                            " of the spans (a line this solve should start: please report it)");
    }
  }
  line.horizontal = f(0);
  line.vertical = f(1);
  const double w = in.weight, L = in.unstretched_length;
  if (in.seabed && f(1) < w * L) {
    line.laid_length = L - f(1) / w;
    line.anchor_horizontal = std::max(f(0) - in.friction * w * line.laid_length, 0.0);
  } else {
    line.anchor_horizontal = f(0);
    line.anchor_vertical = f(1) - w * L;
  }
  return line;
}

}  // namespace flexmoor::hydro

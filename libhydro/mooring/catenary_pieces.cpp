#include "libhydro/mooring/catenary_pieces.hpp"

namespace flexmoor::hydro::catenary_detail {
namespace {

std::vector<CatenarySegment> segmentsOf(const CatenaryLineInputs& in) {
  if (!in.segments.empty()) return in.segments;
  return {{in.unstretched_length, in.weight, in.axial_stiffness}};
}

}  // namespace

Line makeLine(const CatenaryLineInputs& in) {
  Line l{in,
         segmentsOf(in),
         in.segments.empty() ? std::vector<double>() : in.connection_forces,
         {0.0}};
  for (const CatenarySegment& s : l.segments) l.start.push_back(l.start.back() + s.length);
  return l;
}

double Line::netWeight() const {
  double w = 0.0;
  for (const CatenarySegment& s : segments) w += s.weight * s.length;
  for (const double f : forces) w -= f;
  return w;
}

double Line::forceScale() const {
  double w = 0.0;
  for (const CatenarySegment& s : segments) w += s.weight * s.length;
  for (const double f : forces) w += std::abs(f);
  return w;
}

Spans hangingSpans(const HangingPiece& p, double H, double r) {
  const double w = p.weight, EA = p.ea;
  const double a = (p.bottom + w * r) / H, b = p.bottom / H;
  const double ra = std::sqrt(1.0 + a * a), rb = std::sqrt(1.0 + b * b);
  Spans s;
  s.value = {H / w * (std::asinh(a) - std::asinh(b)) + H * r / EA,
             H / w * (ra - rb) + (p.bottom * r + 0.5 * w * r * r) / EA};
  s.jacobian << (std::asinh(a) - std::asinh(b)) / w - (a / ra - b / rb) / w + r / EA,
      (1.0 / ra - 1.0 / rb) / w, (1.0 / ra - 1.0 / rb) / w, (a / ra - b / rb) / w + r / EA;
  return s;
}

Stretch suspendedStretch(const Line& l, double a, double b, double V_a, double H) {
  Stretch out;
  double v = V_a;
  out.least = out.largest = v;
  for (size_t i = 0; i < l.segments.size(); ++i) {
    const double from = std::max(a, l.start[i]), to = std::min(b, l.start[i + 1]);
    if (!(to > from)) continue;
    if (i > 0 && from == l.start[i] && a < l.start[i]) v -= l.forces[i - 1];  // crossing it up
    const CatenarySegment& g = l.segments[i];
    out.span += hangingSpans({from, to - from, v, g.weight, g.axial_stiffness}, H, to - from).value;
    out.least = std::min(out.least, v);
    v += g.weight * (to - from);
    out.largest = std::max(out.largest, v);
  }
  out.top = v;
  return out;
}

double verticalBelow(const Line& l, double a, double b, double V_b) {
  double v = V_b;
  for (size_t i = 0; i < l.segments.size(); ++i) {
    const double from = std::max(a, l.start[i]), to = std::min(b, l.start[i + 1]);
    if (to > from) v -= l.segments[i].weight * (to - from);
    if (i > 0 && l.start[i] > a && l.start[i] < b) v += l.forces[i - 1];
  }
  return v;
}

}  // namespace flexmoor::hydro::catenary_detail

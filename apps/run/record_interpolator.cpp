#include "apps/run/record_interpolator.hpp"

#include <utility>

#include "libstruct/solve/state_interpolation.hpp"

namespace flexmoor::app {

void RecordInterpolator::accepted(const model::State& s) {
  std::swap(before_, after_);
  after_.state = s;
  after_.computed = false;
}

model::State RecordInterpolator::state(double t) const {
  return solve::interpolate(before_.state, after_.state, t);
}

void RecordInterpolator::compute(Accepted& a) const {
  if (a.computed) return;
  assembler_.results(a.state, a.elements, a.reactions);
  a.computed = true;
}

void RecordInterpolator::results(double t, std::vector<element::ElementResult>& elements,
                                 model::NodalField& reactions) {
  compute(before_);
  compute(after_);
  const double w = (t - before_.state.time) / (after_.state.time - before_.state.time);
  const auto blend = [w](double a, double b) { return a + w * (b - a); };
  elements = before_.elements;
  for (size_t e = 0; e < elements.size(); ++e) {
    element::ElementResult& r = elements[e];
    const element::ElementResult& b = after_.elements[e];
    for (size_t p = 0; p < r.point_tension.size(); ++p)
      r.point_tension[p] = blend(r.point_tension[p], b.point_tension[p]);
    for (int k = 0; k < 2; ++k) r.end_tension[k] = blend(r.end_tension[k], b.end_tension[k]);
    for (size_t p = 0; p < r.point_resultant.size(); ++p)
      r.point_resultant[p] += w * (b.point_resultant[p] - r.point_resultant[p]);
  }
  reactions = before_.reactions + w * (after_.reactions - before_.reactions);
}

}  // namespace flexmoor::app

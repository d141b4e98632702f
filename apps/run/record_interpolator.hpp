#pragma once
// The records of an adaptive dynamic step at output times between two accepted steps: the state
// on the steps' Hermite interpolant (solve::interpolate), its element results and reactions
// linear in time between the two steps' own. Results computed from the interpolated positions
// would not do: on a stiff line a millimetre of interpolation error is a strain of 3e-5, 2% of
// the tension of OC4's chain, where the two steps' tensions are each converged.
#include <vector>

#include "libstruct/model/assembler.hpp"

namespace flexmoor::app {

class RecordInterpolator {
 public:
  explicit RecordInterpolator(const model::Assembler& assembler) : assembler_(assembler) {}

  // The next accepted state (the step's first, then each accepted one): the one before becomes
  // the start of the interval the records fall in.
  void accepted(const model::State& s);
  // At time t between the last two accepted states.
  model::State state(double t) const;
  void results(double t, std::vector<element::ElementResult>& elements,
               model::NodalField& reactions);
  // The last two accepted states, and the interpolator put back at them (their results computed
  // anew when asked: the same numbers).
  const model::State& before() const { return before_.state; }
  const model::State& after() const { return after_.state; }
  void resume(const model::State& before, const model::State& after) {
    before_ = Accepted{before, false, {}, {}};
    after_ = Accepted{after, false, {}, {}};
  }

 private:
  struct Accepted {
    model::State state;
    bool computed = false;  // elements and reactions are the state's
    std::vector<element::ElementResult> elements;
    model::NodalField reactions;
  };
  void compute(Accepted& a) const;

  const model::Assembler& assembler_;
  Accepted before_, after_;
};

}  // namespace flexmoor::app

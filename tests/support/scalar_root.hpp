#pragma once
// A bracketed scalar root finder for the closed-form references of the tests (GSL's Brent
// solver), independent of libstruct.
#include <functional>

namespace flexmoor::test {

// The root of f in [lo, hi], where f(lo) and f(hi) have opposite signs, to a relative width of
// the bracket of 1e-15 (or 1e-300 absolute). Throws when the bracket holds no sign change or the
// iteration does not converge.
double findRoot(const std::function<double(double)>& f, double lo, double hi);

}  // namespace flexmoor::test

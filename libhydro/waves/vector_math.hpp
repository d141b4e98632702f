#pragma once
// Element-wise cos, sin and exp of arrays, two doubles at a time with SSE2 on any x86-64, about
// twice as fast as the scalar libm calls an irregular sea makes per component and point
// (docs/performance.md).
// - cos and sin together (cosines_and_sines.cpp): one argument reduction and two polynomials
//   for both, the loop vectorised by the compiler, within 2.3e-16 (an ulp of 1) of std::cos and std::sin
//   (tests/hydro/vector_math_test.cpp); the same bits on every x86-64.
// - exp by glibc's vector math library (libmvec, its maximum error 4 ulp; vector_math.cpp, the
//   one file compiled with -ffast-math, libhydro/CMakeLists.txt: glibc declares the vector
//   variants to the compiler only then). The compiler calls the two-wide variant; glibc picks
//   its implementation by the processor (its SSE4.1 one on any recent x86-64), so the bits are
//   the same between machines that pick the same implementation.
#include <cstddef>

namespace flexmoor::hydro {

// c[i] = cos(x[i]), s[i] = sin(x[i]) for i < n.
void cosinesAndSines(const double* x, double* c, double* s, std::size_t n);
// e[i] = exp(x[i]) for i < n.
void exponentials(const double* x, double* e, std::size_t n);

}  // namespace flexmoor::hydro

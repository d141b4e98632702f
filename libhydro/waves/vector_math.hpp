#pragma once
// Element-wise cos, sin and exp of arrays by glibc's vector math library (libmvec, two doubles
// at a time with SSE2 on any x86-64, its maximum error 4 ulp), about twice as fast as the scalar
// libm calls an irregular sea makes per component and point (docs/performance.md). Only this
// file is compiled with -ffast-math (libhydro/CMakeLists.txt): glibc declares the vector
// variants to the compiler only then. The compiler calls the two-wide variants; glibc picks
// their implementation by the processor (its SSE4.1 one on any recent x86-64), so the bits are
// the same between machines that pick the same implementation.
#include <cstddef>

namespace flexmoor::hydro {

// c[i] = cos(x[i]), s[i] = sin(x[i]) for i < n.
void cosinesAndSines(const double* x, double* c, double* s, std::size_t n);
// e[i] = exp(x[i]) for i < n.
void exponentials(const double* x, double* e, std::size_t n);

}  // namespace flexmoor::hydro

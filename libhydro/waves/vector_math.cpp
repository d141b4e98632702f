#include "libhydro/waves/vector_math.hpp"

#include <math.h>  // glibc's <bits/math-vector.h>: the `omp declare simd` variants

namespace flexmoor::hydro {

// Two loops, not one: the compiler would fuse cos and sin into a sincos call, which does not
// vectorise.
void cosinesAndSines(const double* __restrict x, double* __restrict c, double* __restrict s,
                     std::size_t n) {
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) c[i] = cos(x[i]);
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) s[i] = sin(x[i]);
}

void exponentials(const double* __restrict x, double* __restrict e, std::size_t n) {
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) e[i] = exp(x[i]);
}

}  // namespace flexmoor::hydro

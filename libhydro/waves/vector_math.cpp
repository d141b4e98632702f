#include "libhydro/waves/vector_math.hpp"

#include <math.h>  // glibc's <bits/math-vector.h>: the `omp declare simd` variants

namespace flexmoor::hydro {

void exponentials(const double* __restrict x, double* __restrict e, std::size_t n) {
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) e[i] = exp(x[i]);
}

}  // namespace flexmoor::hydro

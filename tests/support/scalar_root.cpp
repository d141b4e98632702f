#include "tests/support/scalar_root.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <memory>
#include <stdexcept>

namespace flexmoor::test {

double findRoot(const std::function<double(double)>& f, double lo, double hi) {
  const double f_lo = f(lo), f_hi = f(hi);
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo < 0.0) == (f_hi < 0.0)) throw std::invalid_argument("findRoot: no sign change");
  gsl_function F;
  F.function = [](double x, void* params) {
    return (*static_cast<const std::function<double(double)>*>(params))(x);
  };
  F.params = const_cast<std::function<double(double)>*>(&f);
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  const gsl_error_handler_t* previous = gsl_set_error_handler_off();
  gsl_root_fsolver_set(solver.get(), &F, lo, hi);
  int status = GSL_CONTINUE;
  for (int it = 0; it < 500 && status == GSL_CONTINUE; ++it) {
    status = gsl_root_fsolver_iterate(solver.get());
    if (status != GSL_SUCCESS) break;
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()),
                                    gsl_root_fsolver_x_upper(solver.get()), 1e-300, 1e-15);
  }
  gsl_set_error_handler(previous);
  if (status != GSL_SUCCESS) throw std::runtime_error("findRoot did not converge");
  return gsl_root_fsolver_root(solver.get());
}

}  // namespace flexmoor::test

#include "tests/support/elastic_catenary.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace flexmoor::test {
namespace {

// The integral of f over [a, b] by gsl_integration_qags (epsabs 0, epsrel 1e-12).
double integrate(const std::function<double(double)>& f, double a, double b) {
  constexpr std::size_t kLimit = 1000;
  const std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)>
      workspace(gsl_integration_workspace_alloc(kLimit), &gsl_integration_workspace_free);
  gsl_function F;
  F.function = [](double x, void* params) {
    return (*static_cast<const std::function<double(double)>*>(params))(x);
  };
  F.params = const_cast<std::function<double(double)>*>(&f);
  double result = 0.0, error = 0.0;
  const gsl_error_handler_t* previous = gsl_set_error_handler_off();
  const int status =
      gsl_integration_qags(&F, a, b, 0.0, 1e-12, kLimit, workspace.get(), &result, &error);
  gsl_set_error_handler(previous);
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("elastic catenary quadrature failed: ") +
                             gsl_strerror(status));
  return result;
}

void checkInputs(const CatenaryInputs& in) {
  if (!(in.unstretched_length > 0.0 && in.weight > 0.0 && in.horizontal_force > 0.0))
    throw std::invalid_argument("a catenary needs L0 > 0, w > 0 and H > 0");
}

}  // namespace

double greenStrainTension(double stretch, double EA) {
  return 0.5 * EA * stretch * (stretch * stretch - 1.0);
}

double greenStrainStretch(double tension, double EA) {
  if (!(tension >= 0.0 && EA > 0.0))
    throw std::invalid_argument("greenStrainStretch needs T >= 0 and EA > 0");
  // f(l) = l^3 - l - 2 T / EA is increasing and convex for l >= 1, and f(1 + T / EA) >= 0.
  const double t = tension / EA;
  double l = 1.0 + t;
  for (int it = 0; it < 100; ++it) {
    const double f = l * l * l - l - 2.0 * t;
    const double step = f / (3.0 * l * l - 1.0);
    l -= step;
    if (std::abs(step) <= 1e-15 * l) return l;  // quadratic: the next step is below round-off
  }
  throw std::runtime_error("greenStrainStretch: Newton did not converge");
}

CatenaryShape irvineCatenary(const CatenaryInputs& in) {
  checkInputs(in);
  const double H = in.horizontal_force, w = in.weight, L0 = in.unstretched_length;
  const double EA = in.axial_stiffness, V = in.verticalReaction();
  CatenaryShape c;
  c.span = H * L0 / EA + 2.0 * H / w * std::asinh(V / H);
  c.centre_sag = (std::hypot(H, V) - H) / w + w * L0 * L0 / (8.0 * EA);
  c.support_movement = L0 - c.span;
  return c;
}

CatenaryShape inextensibleCatenary(const CatenaryInputs& in) {
  checkInputs(in);
  const double H = in.horizontal_force, w = in.weight, V = in.verticalReaction();
  CatenaryShape c;
  c.span = 2.0 * H / w * std::asinh(V / H);
  c.centre_sag = (std::hypot(H, V) - H) / w;
  c.support_movement = in.unstretched_length - c.span;
  return c;
}

CatenaryShape integrateCatenary(const CatenaryInputs& in,
                                const std::function<double(double)>& stretch) {
  checkInputs(in);
  const double H = in.horizontal_force, w = in.weight, L0 = in.unstretched_length;
  const double V = in.verticalReaction();
  // The span integrates over the whole cable (no use of symmetry); the sag runs to mid-length.
  const auto dxds = [&](double s) {
    const double T = std::hypot(H, V - w * s);
    return stretch(T) * H / T;
  };
  const auto dsag_ds = [&](double s) {
    const double T = std::hypot(H, V - w * s);
    return stretch(T) * (V - w * s) / T;
  };
  CatenaryShape c;
  c.span = integrate(dxds, 0.0, L0);
  c.centre_sag = integrate(dsag_ds, 0.0, 0.5 * L0);
  c.support_movement = L0 - c.span;
  return c;
}

CatenaryShape greenStrainCatenary(const CatenaryInputs& in) {
  const double EA = in.axial_stiffness;
  return integrateCatenary(in, [EA](double T) { return greenStrainStretch(T, EA); });
}

}  // namespace flexmoor::test

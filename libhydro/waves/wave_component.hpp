#pragma once
// One linear (Airy) wave component at finite depth (docs/theory.md): elevation a cos(theta), theta =
// k (x cos beta + y sin beta) - omega t + phi, and its velocity, local acceleration and dynamic
// pressure below the mean level z = 0 over a flat bed at z = -h, with their gradients in closed
// form.
#include <Eigen/Core>

namespace flexmoor::hydro {

struct WaveComponent {
  double amplitude = 0.0;  // a = H / 2
  double omega = 0.0;      // circular frequency, rad/s
  double k = 0.0;          // wave number from the dispersion relation
  double heading = 0.0;    // direction of travel beta, from +x towards +y, rad
  double phase = 0.0;      // phi, rad

  // A component of height H and period T; k from the dispersion relation at depth h.
  static WaveComponent fromHeightAndPeriod(double height, double period, double heading,
                                           double phase, double depth, double g);

  double theta(const Eigen::Vector3d& x, double t) const;
  Eigen::Vector3d direction() const;  // (cos beta, sin beta, 0)
};

// What of a component does not change with the point and the time, computed once when the sea
// is built, so that a point costs one sincos and one exp per component.
struct ComponentTerms {
  double kx = 0.0, ky = 0.0;  // k cos beta, k sin beta
  double k = 0.0, omega = 0.0, phase = 0.0, amplitude = 0.0;
  double velocity = 0.0;      // a omega
  double acceleration = 0.0;  // a omega^2
  double pressure = 0.0;      // rho g a
  // The depth attenuation with e = exp(k z), r = exp(-2 k h) / e^2 (0 in deep water, h = inf or
  // k h > 350): cosh(k (z + h)) / sinh(k h) = e (1 + r) / (1 - exp(-2 k h)), sinh / sinh the
  // same with (1 - r), cosh(k (z + h)) / cosh(k h) = e (1 + r) / (1 + exp(-2 k h)).
  double bed = 0.0;        // exp(-2 k h)
  double over_sinh = 1.0;  // 1 / (1 - exp(-2 k h))
  double over_cosh = 1.0;  // 1 / (1 + exp(-2 k h))
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();

  static ComponentTerms of(const WaveComponent& c, double depth, double rho, double g);
  double theta(const Eigen::Vector3d& x, double t) const {
    return kx * x.x() + ky * x.y() - omega * t + phase;
  }
};

// The linear kinematics of a sum of components at one point (component_sums.hpp) (z <= 0 below the mean level), and
// their partial derivatives: horizontal ones at fixed z (columns x, y; the envelope's slope
// included) and the one in z.
struct LinearKinematics {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // local, du/dt
  double dynamic_pressure = 0.0;                           // p + rho g z, gauge
  Eigen::Matrix<double, 3, 2> velocity_xy = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Matrix<double, 3, 2> acceleration_xy = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Vector2d pressure_xy = Eigen::Vector2d::Zero();
  Eigen::Vector3d velocity_z = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration_z = Eigen::Vector3d::Zero();
  double pressure_z = 0.0;
};

// The amplitude factor of a component at a point (wave_front.hpp): E, dE/dt, dE/dxi and
// d(dE/dt)/dxi, xi the distance along the heading.
struct Envelope {
  double value = 1.0, rate = 0.0, slope = 0.0, rate_slope = 0.0;
};

}  // namespace flexmoor::hydro

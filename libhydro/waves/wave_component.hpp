#pragma once
// One linear (Airy) wave component at finite depth (hydro.md): elevation a cos(theta), theta =
// k (x cos beta + y sin beta) - omega t + phi, and its velocity, local acceleration and dynamic
// pressure below the mean level z = 0 over a flat bed at z = -h.
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

// The linear kinematics of a sum of components at one point (z <= 0 below the mean level).
struct LinearKinematics {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // local, du/dt
  double dynamic_pressure = 0.0;                           // p + rho g z, gauge
};

// Adds the component's kinematics at (x, y, z) and time t, scaled by `envelope` (with its time
// derivative `envelope_rate`, so that the acceleration stays du/dt of the velocity), to `out`.
// depth may be +inf. rho is the water density, g gravity.
void addComponentKinematics(const WaveComponent& c, const Eigen::Vector3d& x, double t,
                            double depth, double rho, double g, double envelope,
                            double envelope_rate, LinearKinematics& out);

}  // namespace flexmoor::hydro

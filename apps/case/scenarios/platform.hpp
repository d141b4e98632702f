#pragma once
// A scenario's rigid platform with a prescribed 6-dof motion about its reference point
// (`platform:` of scenario: spread_mooring), and the histories that move the points it carries
// (histories of type rigid_point, read_histories.cpp):
//
//   platform:
//     reference: [0, 0, 0 m]                                # default: the origin
//     surge: {amplitude: 2 m, period: 10 s, phase: 0}       # sway, heave: lengths too
//     pitch: {amplitude: 3 deg, period: 25 s, phase: 0.5}   # roll, pitch, yaw: angles
//     heave: {table: [[0 s, 0 m], [5 s, 0.4 m], [10 s, 0 m], ...]}
//     yaw: {file: motion.csv, column: yaw, unit: deg}      # time_column: time (default)
//     ramp: 10 s     # default: one period of the slowest sine; 0: start at full speed
//
// each motion optional: a sine A sin(2 pi t / T + phase), a table of samples or a file of time
// series (read_motion.hpp: samples become a cubic spline, the velocities and accelerations its
// derivatives); the rotation is R = Rz(yaw) Ry(pitch) Rx(roll)
// (libstruct/model/rigid_point_motion.hpp), so each fairlead's velocity is v + omega x (R arm)
// of the motion it follows, exactly.
#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <array>
#include <optional>

#include "apps/case/input/yaml_input.hpp"

namespace flexmoor::app {

struct PlatformMotion {
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  // surge, sway, heave, roll, pitch, yaw as given (checked), for the histories to read
  std::array<std::optional<YAML::Node>, 6> motions;
  std::optional<YAML::Node> ramp;  // `ramp:` as given, for the histories to read
};

// Reads `platform:` (errors at their lines in in.diag; nullopt when wrong).
std::optional<PlatformMotion> readPlatform(Input& in, const YAML::Node& n);

// The platform's motion as a history of type rigid_motion, which the case names `platform`.
YAML::Node platformMotionHistory(const PlatformMotion& p);

// The history of component (0, 1, 2 = x, y, z) of the displacement that takes a support from
// `from` to the platform's point now at `point`: (point - from) at rest, plus the motion of the
// history `platform` (platformMotionHistory).
YAML::Node platformPointHistory(const PlatformMotion& p, const Eigen::Vector3d& point,
                                const Eigen::Vector3d& from, int component);

}  // namespace flexmoor::app

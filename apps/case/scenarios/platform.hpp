#pragma once
// A spread mooring's rigid platform with a prescribed 6-dof motion about its reference point,
// which carries the fairleads (`platform:` of scenario: spread_mooring):
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
#include <memory>
#include <optional>

#include "libstruct/model/rigid_body_motion.hpp"

namespace flexmoor::app {

struct CaseBuilder;

// The rigid platform that carries the fairleads: its reference point and its motion about it.
struct PlatformSpec {
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  std::shared_ptr<model::RigidBodyMotion> motion;
};

// Reads `platform:` (errors at their lines; nullopt when wrong).
std::optional<PlatformSpec> readPlatform(CaseBuilder& b, const YAML::Node& n);

}  // namespace flexmoor::app

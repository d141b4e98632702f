#pragma once
// A prescribed motion of one degree of freedom in time: each of a platform's surge, sway, heave,
// roll, pitch and yaw (apps/case/scenarios/platform.hpp, and the rigid_point histories it writes):
//
//   {amplitude: 2 m, period: 10 s, phase: 0}        a sine A sin(2 pi t / T + phase)
//   {table: [[0 s, 0 m], [0.5 s, 0.61 m], ...]}     samples (t, value), each a quantity
//   {file: motion.csv, column: surge, time_column: time, unit: deg}
//   {file: motion.dat, column: 2, time_column: 1, time_offset: -100 s}
//                                                    samples from a file of time series
//
// Samples become the not-a-knot cubic spline through them (libstruct/model/
// cubic_spline_function.hpp): the motion's velocity and acceleration are the spline's
// derivatives, consistent with the positions it passes through, the acceleration continuous;
// outside the samples' times the motion holds its end value. The file, relative to the case
// file, is comma-separated with a line of column names, or whitespace- or tab-separated with or
// without one (motion_file.hpp); a column is named by the header's name or by its number,
// 1-based; the time column (default: `time`, or column 1 in a file without a header) is in the
// case's time unit, shifted by `time_offset` (a time, default 0: the run's time is the file's
// plus the offset), the column's values in the case's units (a length, or an angle in radians)
// unless `unit:` names theirs.
#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>

#include "apps/case/input/yaml_input.hpp"
#include "libstruct/model/time_function.hpp"

namespace flexmoor::app {

// The motion at `n` (errors at their lines in in.diag; nullptr when wrong). `kind`: the values'
// kind (a length, or kind::kNumber for an angle); a file is found next to `case_file`.
std::shared_ptr<const model::TimeFunction> readMotion(Input& in, const YAML::Node& n,
                                                      const std::string& path,
                                                      const QuantityKind& kind,
                                                      const std::string& case_file);

// offset + amplitude sin(2 pi t / period + phase) from the keys of `f` (amplitude of
// `amplitude_kind`, period required; phase and offset 0 unless given): a motion's sine, and a
// history's (read_histories.cpp).
std::shared_ptr<const model::TimeFunction> readSine(Input& in, Fields& f,
                                                    const QuantityKind& amplitude_kind);

}  // namespace flexmoor::app

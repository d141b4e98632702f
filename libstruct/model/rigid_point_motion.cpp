#include "libstruct/model/rigid_point_motion.hpp"

namespace flexmoor::model {

RigidPointMotion::RigidPointMotion(std::shared_ptr<const RigidBodyMotion> body,
                                   const Eigen::Vector3d& arm, int component, double offset)
    : body_(std::move(body)), arm_(arm), component_(component), offset_(offset) {}

RigidPointMotion::RigidPointMotion(RigidBodyMotion::Dofs motions, const Eigen::Vector3d& arm,
                                   int component, double offset)
    : RigidPointMotion(std::make_shared<RigidBodyMotion>(std::move(motions)), arm, component,
                       offset) {}

double RigidPointMotion::value(double t) const { return offset_ + motion(t, 0)[component_]; }
double RigidPointMotion::rate(double t) const { return motion(t, 1)[component_]; }
double RigidPointMotion::acceleration(double t) const { return motion(t, 2)[component_]; }

}  // namespace flexmoor::model

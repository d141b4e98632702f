#include "apps/host/coupled_bodies.hpp"

#include <stdexcept>

#include "libstruct/model/rigid_point_motion.hpp"

namespace flexmoor::app {
namespace {

model::CoupledMotion::Sample sample(double t, const double* x, const double* xd, const double* xdd,
                                    int k) {
  return {t, x[k], xd[k], xdd ? xdd[k] : 0.0, xdd != nullptr};
}

}  // namespace

std::string rigidMotionNames(const Case& c) {
  std::string list;
  for (const auto& entry : c.rigid_motions) list += (list.empty() ? "" : ", ") + entry.first;
  return list.empty() ? "none" : list;
}

CoupledBodies::CoupledBodies(const Case& c, const std::vector<std::string>& names) {
  for (size_t b = 0; b < names.size(); ++b) {
    const auto found = c.rigid_motions.find(names[b]);
    if (found == c.rigid_motions.end())
      throw std::invalid_argument("no rigid motion named '" + names[b] + "' in case " + c.name +
                                  " (its rigid motions: " + rigidMotionNames(c) + ")");
    for (size_t a = 0; a < b; ++a)
      if (names[a] == names[b])
        throw std::invalid_argument("rigid motion '" + names[b] + "' coupled twice");
    Body body{found->second, {}, {}};
    for (int k = 0; k < kDofs; ++k) {
      body.dofs[k] = std::make_shared<model::CoupledMotion>(model::CoupledMotion::Sample{});
      body.motion->drive(k, body.dofs[k]);
    }
    // The nodes the body carries: those with a dof that follows a point of it.
    const model::Model& m = *c.model;
    for (int node = 0; node < m.nodeCount(); ++node)
      for (int component = 0; component < 3; ++component) {
        const auto* point = dynamic_cast<const model::RigidPointMotion*>(m.motion(node, component));
        if (point && &point->body() == body.motion.get()) {
          body.points.push_back({node, point->arm()});
          break;
        }
      }
    bodies_.push_back(std::move(body));
  }
}

void CoupledBodies::hold(double t, const double* x, const double* xd, const double* xdd) {
  for (size_t b = 0; b < bodies_.size(); ++b)
    for (int k = 0; k < kDofs; ++k)
      bodies_[b].dofs[k]->hold(sample(t, x, xd, xdd, kDofs * static_cast<int>(b) + k));
}

void CoupledBodies::next(double t, const double* x, const double* xd, const double* xdd) {
  for (size_t b = 0; b < bodies_.size(); ++b)
    for (int k = 0; k < kDofs; ++k)
      bodies_[b].dofs[k]->next(sample(t, x, xd, xdd, kDofs * static_cast<int>(b) + k));
}

void CoupledBodies::loads(const model::State& s, const model::Assembler& assembler,
                          double* f) const {
  assembler.reactions(s, reactions_);
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    const Eigen::Vector3d translation(body.motion->dof(0, s.time, 0),
                                      body.motion->dof(1, s.time, 0),
                                      body.motion->dof(2, s.time, 0));
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (const Point& p : body.points) {
      const Eigen::Vector3d pull = -reactions_.col(p.node);
      // R arm: the point's place from the reference point where the body is now.
      const Eigen::Vector3d lever =
          p.arm + body.motion->pointMotion(p.arm, s.time, 0) - translation;
      force += pull;
      moment += lever.cross(pull);
    }
    for (int k = 0; k < 3; ++k) {
      f[kDofs * b + k] = force[k];
      f[kDofs * b + 3 + k] = moment[k];
    }
  }
}

std::vector<model::CoupledMotion::Sample> CoupledBodies::save() const {
  std::vector<model::CoupledMotion::Sample> samples;
  for (const Body& body : bodies_)
    for (const auto& dof : body.dofs) {
      samples.push_back(dof->start());
      samples.push_back(dof->end());
    }
  return samples;
}

void CoupledBodies::restore(const std::vector<model::CoupledMotion::Sample>& samples) {
  size_t k = 0;
  for (Body& body : bodies_)
    for (auto& dof : body.dofs) {
      dof->between(samples.at(k), samples.at(k + 1));
      k += 2;
    }
}

}  // namespace flexmoor::app

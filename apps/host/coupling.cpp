#include "apps/host/coupling.hpp"

#include <stdexcept>

#include "libstruct/model/rigid_point_motion.hpp"

namespace flexmoor::app {
namespace {

// The node of a line's end `name` (LINE.start, LINE.end, and LINE.anchor, LINE.fairlead of a
// mooring line); -1 when `name` is no such thing, with `why` saying what is wrong.
int lineEndNode(const Case& c, const std::string& name, std::string& why) {
  const size_t dot = name.rfind('.');
  if (dot == std::string::npos) {
    why = "no rigid motion named '" + name + "' in case " + c.name +
          " (its rigid motions: " + rigidMotionNames(c) +
          "; a point is LINE.fairlead, LINE.anchor, LINE.start or LINE.end)";
    return -1;
  }
  const std::string line = name.substr(0, dot), end = name.substr(dot + 1);
  const CaseLine* found = nullptr;
  for (const CaseLine& l : c.named_lines)
    if (l.name == line) found = &l;
  if (!found || found->nodes.empty()) {
    std::string names;
    for (const CaseLine& l : c.named_lines) names += (names.empty() ? "" : ", ") + l.name;
    why = "no line named '" + line + "' in case " + c.name +
          " (its lines: " + (names.empty() ? "none" : names) + ")";
    return -1;
  }
  const bool mooring = found->anchor != CaseLine::Anchor::None;
  const bool anchor_at_start = found->anchor == CaseLine::Anchor::Start;
  if (end == "start") return found->nodes.front();
  if (end == "end") return found->nodes.back();
  if (mooring && end == "anchor")
    return anchor_at_start ? found->nodes.front() : found->nodes.back();
  if (mooring && end == "fairlead")
    return anchor_at_start ? found->nodes.back() : found->nodes.front();
  why = "'" + name + "': not an end of line " + line + " (expected " + line + ".start, " + line +
        ".end" + (mooring ? ", " + line + ".anchor or " + line + ".fairlead" : "") + ")";
  return -1;
}

// The node of the point `name`, held in x, y and z; std::invalid_argument otherwise.
int pointNode(const Case& c, const std::string& name) {
  std::string why;
  const int node = lineEndNode(c, name, why);
  if (node < 0) throw std::invalid_argument(why);
  for (int k = 0; k < 3; ++k)
    if (!c.model->isConstrained(node, k))
      throw std::invalid_argument("point '" + name + "' is free in " + "xyz"[k] +
                                  " (a coupled point is one the case's supports hold in x, y "
                                  "and z, and the host then moves)");
  return node;
}

}  // namespace

std::string rigidMotionNames(const Case& c) {
  std::string list;
  for (const auto& entry : c.rigid_motions) list += (list.empty() ? "" : ", ") + entry.first;
  return list.empty() ? "none" : list;
}

// The nodes a body carries: those with a dof that follows a point of it, with their arms.
std::vector<Coupling::Carried> Coupling::carried(const model::Model& m,
                                                 const model::RigidBodyMotion& body) {
  std::vector<Carried> points;
  for (int node = 0; node < m.nodeCount(); ++node)
    for (int component = 0; component < 3; ++component) {
      const auto* point = dynamic_cast<const model::RigidPointMotion*>(m.motion(node, component));
      if (point && &point->body() == &body) {
        points.push_back({node, point->arm()});
        break;
      }
    }
  return points;
}

Coupling::Resolved Coupling::resolve(const Case& c, const std::vector<std::string>& names) {
  Resolved r{std::vector<int>(names.size(), -1), std::vector<std::vector<Carried>>(names.size())};
  for (size_t b = 0; b < names.size(); ++b) {
    for (size_t a = 0; a < b; ++a)
      if (names[a] == names[b]) throw std::invalid_argument("'" + names[b] + "' coupled twice");
    const auto found = c.rigid_motions.find(names[b]);
    if (found == c.rigid_motions.end())
      r.point_nodes[b] = pointNode(c, names[b]);
    else
      r.carried_by[b] = carried(*c.model, *found->second);
  }
  for (size_t b = 0; b < names.size(); ++b)
    for (const Carried& p : r.carried_by[b])
      for (size_t a = 0; a < names.size(); ++a)
        if (r.point_nodes[a] == p.node)
          throw std::invalid_argument("point '" + names[a] + "' is carried by the coupled body '" +
                                      names[b] + "' (couple the body or the point, not both)");
  return r;
}

std::vector<int> Coupling::dofsOf(const Case& c, const std::vector<std::string>& names) {
  const Resolved r = resolve(c, names);
  std::vector<int> dofs;
  for (int node : r.point_nodes) dofs.push_back(node >= 0 ? kPointDofs : kBodyDofs);
  return dofs;
}

Coupling::Coupling(const Case& c, const std::vector<std::string>& names) {
  model::Model& m = *c.model;
  // What each name is, found before the model's supports change hands.
  Resolved r = resolve(c, names);
  std::vector<int>& point_nodes = r.point_nodes;
  std::vector<std::vector<Carried>>& carried_by = r.carried_by;
  for (size_t b = 0; b < names.size(); ++b) {
    const int first = dofs();
    if (const int node = point_nodes[b]; node >= 0) {
      points_.push_back({node, first});
      for (int k = 0; k < kPointDofs; ++k) {
        dofs_.push_back({std::make_shared<model::CoupledMotion>(model::CoupledMotion::Sample{}),
                         m.reference()(k, node)});
        m.constrain(node, k, 1.0, dofs_.back().motion);  // its displacement is the motion's
      }
      continue;
    }
    Body body{c.rigid_motions.at(names[b]), std::move(carried_by[b]), first};
    for (int k = 0; k < kBodyDofs; ++k) {
      dofs_.push_back(
          {std::make_shared<model::CoupledMotion>(model::CoupledMotion::Sample{}), 0.0});
      body.motion->drive(k, dofs_.back().motion);
    }
    bodies_.push_back(std::move(body));
  }
}

model::CoupledMotion::Sample Coupling::sample(double t, const double* x, const double* xd,
                                              const double* xdd, int k) const {
  return {t, x[k] - dofs_[k].offset, xd[k], xdd ? xdd[k] : 0.0, xdd != nullptr};
}

void Coupling::hold(double t, const double* x, const double* xd, const double* xdd) {
  for (int k = 0; k < dofs(); ++k) dofs_[k].motion->hold(sample(t, x, xd, xdd, k));
}

void Coupling::next(double t, const double* x, const double* xd, const double* xdd) {
  for (int k = 0; k < dofs(); ++k) dofs_[k].motion->next(sample(t, x, xd, xdd, k));
}

void Coupling::loads(const model::State& s, const model::Assembler& assembler, double* f) const {
  assembler.reactions(s, reactions_);
  for (const Body& body : bodies_) {
    const Eigen::Vector3d translation(body.motion->dof(0, s.time, 0),
                                      body.motion->dof(1, s.time, 0),
                                      body.motion->dof(2, s.time, 0));
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (const Carried& p : body.points) {
      const Eigen::Vector3d pull = -reactions_.col(p.node);
      // R arm: the point's place from the reference point where the body is now.
      const Eigen::Vector3d lever =
          p.arm + body.motion->pointMotion(p.arm, s.time, 0) - translation;
      force += pull;
      moment += lever.cross(pull);
    }
    for (int k = 0; k < 3; ++k) {
      f[body.first_dof + k] = force[k];
      f[body.first_dof + 3 + k] = moment[k];
    }
  }
  for (const Point& p : points_)
    for (int k = 0; k < kPointDofs; ++k) f[p.first_dof + k] = -reactions_(k, p.node);
}

std::vector<model::CoupledMotion::Sample> Coupling::save() const {
  std::vector<model::CoupledMotion::Sample> samples;
  for (const Dof& dof : dofs_) {
    samples.push_back(dof.motion->start());
    samples.push_back(dof.motion->end());
  }
  return samples;
}

void Coupling::restore(const std::vector<model::CoupledMotion::Sample>& samples) {
  for (size_t k = 0; k < dofs_.size(); ++k)
    dofs_[k].motion->between(samples.at(2 * k), samples.at(2 * k + 1));
}

}  // namespace flexmoor::app

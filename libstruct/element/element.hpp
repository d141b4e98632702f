#pragma once
// The interface every structural element implements: given the nodal state, its internal force,
// tangent stiffness, mass and body load, all in the element's 3n dofs ordered node by node
// (x, y, z of its first node, then of its second, ...).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "libstruct/model/line_load.hpp"
#include "libstruct/model/state.hpp"

namespace flexmoor::element {

enum class MassKind { Consistent, Lumped };

// What an element reports after a solution: axial force at integration points and at its ends.
struct ElementResult {
  std::vector<double> point_tension;  // one per integration point, in the element's order
  double end_tension[2] = {0.0, 0.0};
};

struct ElementContext {
  const model::NodalField& reference;  // X of all nodes
  const model::State& state;
  int index = -1;  // this element's index in the model
};

class Element {
 public:
  explicit Element(std::vector<int> nodes) : nodes_(std::move(nodes)) {}
  virtual ~Element() = default;

  const std::vector<int>& nodes() const { return nodes_; }
  int dofCount() const { return 3 * static_cast<int>(nodes_.size()); }
  virtual std::string typeName() const = 0;

  // Internal force f; when K is given, also the tangent stiffness dF/du.
  virtual void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                             Eigen::MatrixXd* K) const = 0;
  // Mass matrix (total Lagrangian: independent of the state).
  virtual void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const = 0;
  // Nodal loads of a body force per unit mass g (gravity; buoyancy when g is reduced).
  virtual void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                        Eigen::VectorXd& p) const = 0;
  // Nodal loads of a distributed line load; elements that are not lines add nothing.
  virtual void lineLoad(const ElementContext&, const model::LineLoad&, Eigen::VectorXd& p) const {
    p.setZero(dofCount());
  }
  virtual ElementResult result(const ElementContext& c) const = 0;

 private:
  std::vector<int> nodes_;
};

}  // namespace flexmoor::element

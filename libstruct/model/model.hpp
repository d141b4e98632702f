#pragma once
// A structural model: nodes, elements, constraints and the load pattern. Each node has three
// translational dofs (x, y, z). A dof is either free (it has an equation number) or constrained
// to a prescribed displacement, which is scaled by the load factor like the loads.
#include <memory>
#include <vector>

#include "libstruct/element/element.hpp"
#include "libstruct/model/load_point.hpp"
#include "libstruct/model/state.hpp"
#include "libstruct/model/time_function.hpp"

namespace flexmoor::model {

// A nodal force: force * load factor, or force * history(t) when it has a history.
struct NodalLoad {
  int node;
  Eigen::Vector3d force;
  std::shared_ptr<const TimeFunction> history;
};

// A follower pressure on surface elements, acting along the current normal y,1 x y,2
// (Eq. 3.30-3.37): pressure * load factor, or pressure * history(t).
struct PressureLoad {
  std::vector<int> elements;
  double pressure;
  std::shared_ptr<const TimeFunction> history;
};

// A pressure field (load_point.hpp's SurfaceLoad: the incident wave pressure) on surface
// elements, along their current normal, scaled by the load factor like the other motion loads.
struct SurfaceLoadOn {
  std::shared_ptr<const SurfaceLoad> load;
  std::vector<int> elements;
};

class Model {
 public:
  int addNode(const Eigen::Vector3d& reference_position);
  // Appends the columns of X as nodes at once (one allocation); returns the first one's index.
  int addNodes(const NodalField& X);
  int addElement(std::unique_ptr<element::Element> element);

  // Constrains dof `component` (0, 1, 2 = x, y, z) of `node` to the prescribed displacement
  // value * load factor, or value * history(t) when a history is given.
  void constrain(int node, int component, double value = 0.0,
                 std::shared_ptr<const TimeFunction> history = nullptr);
  void addNodalLoad(int node, const Eigen::Vector3d& force,
                    std::shared_ptr<const TimeFunction> history = nullptr);
  void addPressure(PressureLoad load) { pressures_.push_back(std::move(load)); }
  void setGravity(const Eigen::Vector3d& g) { gravity_ = g; }
  // Loads that depend on the motion (load_point.hpp), scaled by the load factor like gravity.
  void addLineLoad(std::shared_ptr<const LineLoad> load) { line_loads_.push_back(std::move(load)); }
  void addNodeLoad(std::shared_ptr<const NodeLoad> load);
  void addSurfaceLoad(std::shared_ptr<const SurfaceLoad> load, std::vector<int> elements);
  // A dof's constraint: its prescribed value and history.
  struct Constraint {
    double value = 0.0;
    std::shared_ptr<const TimeFunction> history;
  };
  // Frees a constrained dof (a held buoy let go) and numbers the equations again; an Assembler
  // built before must be built again. Returns what held it, for constrain() to put back.
  Constraint release(int node, int component);

  int nodeCount() const { return static_cast<int>(reference_.cols()); }
  int elementCount() const { return static_cast<int>(elements_.size()); }
  const NodalField& reference() const { return reference_; }
  const element::Element& element(int i) const { return *elements_[i]; }
  const std::vector<std::unique_ptr<element::Element>>& elements() const { return elements_; }
  const std::vector<NodalLoad>& nodalLoads() const { return nodal_loads_; }
  const std::vector<PressureLoad>& pressures() const { return pressures_; }
  const Eigen::Vector3d& gravity() const { return gravity_; }
  const std::vector<std::shared_ptr<const LineLoad>>& lineLoads() const { return line_loads_; }
  const std::vector<std::shared_ptr<const NodeLoad>>& nodeLoads() const { return node_loads_; }
  const std::vector<SurfaceLoadOn>& surfaceLoads() const { return surface_loads_; }
  bool hasMotionLoads() const {
    return !line_loads_.empty() || !node_loads_.empty() || !surface_loads_.empty();
  }
  // Whether a line or node load is contact (LineLoad::contact).
  bool hasContactLoads() const;

  bool isConstrained(int node, int component) const { return constrained_(component, node); }
  double prescribed(int node, int component) const { return prescribed_(component, node); }
  const TimeFunction* motion(int node, int component) const {
    return motion_[3 * node + component].get();
  }

  // Equation number of a dof, or -1 for a constrained dof. Valid after numberEquations().
  int equation(int node, int component) const { return equation_(component, node); }
  int equationCount() const { return equation_count_; }
  void numberEquations();

  // The reference configuration at rest, load factor 0 (what element masses are taken at).
  State initialState() const { return State(nodeCount()); }

  // Where a run starts: the reference unless a starting shape is given, as displacements from
  // the reference (a line's catenary: the reference keeps the unstretched lengths, total
  // Lagrangian) at a load factor (1: the shape under the full static loads, the prescribed
  // displacements included). Nodes without one start at their reference.
  void setStartDisplacement(int node, const Eigen::Vector3d& displacement);
  void setStartLoadFactor(double load_factor) { start_load_factor_ = load_factor; }
  bool hasStartShape() const { return start_displacement_.cols() > 0; }
  State startState() const;

 private:
  NodalField reference_ = NodalField(3, 0);
  std::vector<std::unique_ptr<element::Element>> elements_;
  Eigen::Matrix<bool, 3, Eigen::Dynamic> constrained_ =
      Eigen::Matrix<bool, 3, Eigen::Dynamic>(3, 0);
  NodalField prescribed_ = NodalField(3, 0);
  std::vector<std::shared_ptr<const TimeFunction>> motion_;  // per dof, 3 * node + component
  Eigen::Matrix3Xi equation_ = Eigen::Matrix3Xi(3, 0);
  int equation_count_ = 0;
  std::vector<NodalLoad> nodal_loads_;
  std::vector<PressureLoad> pressures_;
  Eigen::Vector3d gravity_ = Eigen::Vector3d::Zero();
  std::vector<std::shared_ptr<const LineLoad>> line_loads_;
  std::vector<std::shared_ptr<const NodeLoad>> node_loads_;
  std::vector<SurfaceLoadOn> surface_loads_;
  NodalField start_displacement_ = NodalField(3, 0);  // empty, or one column a node
  double start_load_factor_ = 0.0;
};

}  // namespace flexmoor::model

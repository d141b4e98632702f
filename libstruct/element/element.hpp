#pragma once
// The interface every structural element implements: given the nodal state, its internal force,
// tangent stiffness, mass and body load, all in the element's 3n dofs ordered node by node
// (x, y, z of its first node, then of its second, ...).
#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "libstruct/model/load_point.hpp"
#include "libstruct/model/state.hpp"

namespace flexmoor::element {

enum class MassKind { Consistent, Lumped };

// What an element reports after a solution. Lines: axial force at integration points and at
// their ends. Membranes: the stress-resultant tensor (force per current length, Cartesian 3 x 3,
// in the tangent plane) at each integration point.
struct ElementResult {
  std::vector<double> point_tension;  // one per integration point, in the element's order
  // The force on each end point: a line element of two or more nodes leaves it to the
  // assembler, which takes it from the element's nodal force balance (Assembler::elementResults);
  // a hoop (one node) gives its tension.
  double end_tension[2] = {0.0, 0.0};
  std::vector<Eigen::Matrix3d> point_resultant;
  // Empties it, keeping the storage for the next result.
  void clear() {
    point_tension.clear();
    end_tension[0] = end_tension[1] = 0.0;
    point_resultant.clear();
  }
};

// The negative derivatives of an element's nodal loads, the load's share of the tangent:
// stiffness -dp/du, damping -dp/du', mass -dp/du'' (each 3n x 3n, in the element's dofs).
struct LoadMatrices {
  Eigen::MatrixXd stiffness, damping, mass;
  // When set, the element does not keep the three apart: it puts their weighted sum
  // k (-dp/du) + c (-dp/du') + m (-dp/du'') into `stiffness` alone, point by point (what a time
  // step's effective tangent takes of them, Eq. 4.63), and leaves `damping` and `mass` as they
  // are: one matrix to fill and to scatter instead of three.
  struct Weights {
    double stiffness = 1.0, damping = 0.0, mass = 0.0;
  };
  std::optional<Weights> summed;
  // Zero n x n matrices: the three, or `stiffness` alone when summed.
  void setZero(int n) {
    stiffness.setZero(n, n);
    if (summed) return;
    damping.setZero(n, n);
    mass.setZero(n, n);
  }
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
  // True for elements of an axisymmetric meridian, whose forces are per radian of circumference.
  virtual bool axisymmetric() const { return false; }

  // Internal force f; when K is given, also the tangent stiffness dF/du.
  virtual void internalForce(const ElementContext& c, Eigen::VectorXd& f,
                             Eigen::MatrixXd* K) const = 0;
  // Mass matrix (total Lagrangian: independent of the state).
  virtual void mass(const ElementContext& c, MassKind kind, Eigen::MatrixXd& M) const = 0;
  // Nodal loads of a body force per unit mass g (gravity; buoyancy when g is reduced).
  virtual void bodyLoad(const ElementContext& c, const Eigen::Vector3d& g,
                        Eigen::VectorXd& p) const = 0;
  // Nodal loads p = int N^T f ds of a line load f evaluated at the integration points on the
  // current configuration; when J is given, also its matrices (-dp/du, -dp/du', -dp/du'') from
  // int N^T (df/dq) N ds and the derivative of ds. Elements that are not lines add nothing.
  // Returns false when the load is zero at every integration point (a seabed under a hanging
  // part): p and J are zero, and the assembler has nothing to add.
  // Whether lineLoad can be non-zero (line elements): the assembler skips the others.
  virtual bool takesLineLoads() const { return false; }
  virtual bool lineLoad(const ElementContext&, const model::LineLoad&, Eigen::VectorXd& p,
                        LoadMatrices* J) const {
    p.setZero(dofCount());
    if (J) J->setZero(dofCount());
    return false;
  }
  // A pressure field on the deformed surface (Eq. 3.30-3.37 with p = p(y, t)), acting along the
  // current normal: the PointPressure at each integration point on the current configuration.
  using PressureField = std::function<model::PointPressure(const model::LoadPoint&, bool)>;
  // The follower-pressure kernel of surface elements: nodal forces
  // f = int p(y) M^I (y,1 x y,2) dxi1 dxi2 and, when dfdu is given, the load stiffness df/du
  // (non-symmetric): the constant-pressure part plus the gradient part int M^I n (dp/dy)^T M^J.
  // Elements that are not surfaces add nothing.
  virtual void followerPressure(const ElementContext&, const PressureField&, Eigen::VectorXd& f,
                                Eigen::MatrixXd* dfdu) const {
    f.setZero(dofCount());
    if (dfdu) dfdu->setZero(dofCount(), dofCount());
  }
  // Internal damping (a line's axial Kelvin-Voigt term): the viscous internal force f_d(u, u'),
  // zero at rest, on the same side as internalForce; when J is given, also J.stiffness = df_d/du
  // and J.damping = df_d/du' (J.mass zero): the matrices of the load -f_d. Elements without
  // internal damping (hasDamping() false) add nothing.
  virtual bool hasDamping() const { return false; }
  virtual void dampingForce(const ElementContext&, Eigen::VectorXd& f, LoadMatrices* J) const {
    f.setZero(dofCount());
    if (J) J->setZero(dofCount());
  }
  // A uniform follower pressure p: nodal forces f and, when dfdu is given, df/du.
  void pressureLoad(const ElementContext& c, double p, Eigen::VectorXd& f,
                    Eigen::MatrixXd* dfdu) const {
    followerPressure(
        c,
        [p](const model::LoadPoint&, bool) {
          return model::PointPressure{p, {0.0, 0.0, 0.0}};
        },
        f, dfdu);
  }
  // A surface load's nodal forces f and, when J is given, its matrices: stiffness -df/du
  // (damping and mass zero: the pressure does not depend on the motion's rates; J.summed: the
  // stiffness times its weight).
  void surfaceLoad(const ElementContext& c, const model::SurfaceLoad& load, Eigen::VectorXd& f,
                   LoadMatrices* J) const {
    const auto field = [&load](const model::LoadPoint& p, bool jacobians) {
      return load.evaluate(p, jacobians);
    };
    if (!J) return followerPressure(c, field, f, nullptr);
    followerPressure(c, field, f, &J->stiffness);  // sets the whole matrix
    J->stiffness *= J->summed ? -J->summed->stiffness : -1.0;
    if (J->summed) return;
    J->damping.setZero(dofCount(), dofCount());
    J->mass.setZero(dofCount(), dofCount());
  }
  // The result at the state into `out`, whose storage is reused: a record of a long run
  // allocates nothing.
  virtual void result(const ElementContext& c, ElementResult& out) const = 0;
  ElementResult result(const ElementContext& c) const {
    ElementResult r;
    result(c, r);
    return r;
  }
  // The reference area each node carries: the element's area shared out as its HRZ-lumped mass
  // is (nodal_mass.hpp), so every share is positive (per radian for axisymmetric elements). What
  // a quantity spread over the surface (a mass per unit area) puts on each node. Elements that
  // are not surfaces: zeros.
  virtual Eigen::VectorXd nodalAreas(const model::NodalField&) const {
    return Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nodes_.size()));
  }
  // The smallest Jacobian of the map from natural coordinates to the reference geometry X over
  // the element's integration points, relative to a regular element of its size
  // (reference_jacobian.hpp): <= 0 when the element is folded, inverted or collapsed. Elements
  // without such a map (springs, point masses, hoops) return 1.
  virtual double minRelativeJacobian(const model::NodalField&) const { return 1.0; }

 private:
  std::vector<int> nodes_;
};

}  // namespace flexmoor::element

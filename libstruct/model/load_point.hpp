#pragma once
// The load-point interface: how anything outside libstruct (libhydro's Morison loads, buoys,
// seabed and wave pressure, a wind model, a test) puts a load that depends on the motion on the
// structure. An element evaluates a line load at its integration points on the current
// configuration, a surface load (a pressure field) at its surface integration points, a node
// load at its node; the load returns its value and derivatives, which the element
// integrates (N^T f, N^T J N) and the assembler adds to the residual and to the stiffness,
// damping and mass of the one sparsity pattern, as Project Chrono's ChLoad does (K = -dQ/dx,
// R = -dQ/dv, M = -dQ/da). libstruct never includes a libhydro header.
#include <Eigen/Core>
#include <algorithm>

namespace flexmoor::model {

// The state of the structure at one load point.
struct LoadPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      // current position y
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // u'
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // u''
  // Line points: the unit tangent of the deformed axis. Node points: zero.
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
  double stretch = 1.0;  // line points: current length / reference length
  double time = 0.0;
  // A static solve's point: loads that vary in time as an excitation (waves) leave it out and
  // keep their steady part (gravity, buoyancy, current, the seabed); State::still.
  bool still = false;
  int element = -1;  // line and surface points: the element's index in the model
  int node = -1;     // node points: the node's index
};

// A force at a load point and its derivatives (3 x 3 each). Derivatives a load does not have stay
// zero; d_tangent is used by line points only.
struct PointForce {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Matrix3d d_position = Eigen::Matrix3d::Zero();      // df/dy
  Eigen::Matrix3d d_tangent = Eigen::Matrix3d::Zero();       // df/dt
  Eigen::Matrix3d d_velocity = Eigen::Matrix3d::Zero();      // df/du'
  Eigen::Matrix3d d_acceleration = Eigen::Matrix3d::Zero();  // df/du''
};

// Which length a line load is per: the deformed line's (the dissertation's Eq. E.1) or the
// unstretched line's (MoorDyn's convention).
enum class LengthMeasure { Current, Reference };

// A distributed load on line elements: force per unit length at a line point.
class LineLoad {
 public:
  virtual ~LineLoad() = default;
  // The force per unit length at `p`; when `jacobians` is true, its derivatives too.
  virtual PointForce evaluate(const LoadPoint& p, bool jacobians) const = 0;
  virtual LengthMeasure measure() const { return LengthMeasure::Current; }
  // False for a load whose derivatives should stay out of the tangent (a load the caller knows to
  // be weak, or one being measured without them).
  virtual bool stiff() const { return true; }
  // True for contact: a load that acts only on one side of a surface (the seabed), so that its
  // force and matrices switch on as a point crosses it. The time integrator then takes the
  // loads' matrices where its iterations start (TimeIntegrator::attempt).
  virtual bool contact() const { return false; }
};

// A load at a node (a buoy, a clump weight, a fairlead's host): its force and derivatives.
class NodeLoad {
 public:
  virtual ~NodeLoad() = default;
  virtual int node() const = 0;
  virtual PointForce evaluate(const LoadPoint& p, bool jacobians) const = 0;
  virtual bool stiff() const { return true; }
  virtual bool contact() const { return false; }  // as LineLoad::contact
};

// A pressure at a surface point and its gradient in the point's position. It acts along the
// current normal y,1 x y,2 of the deformed surface, the follower pressure's convention (Eq. 3.37):
// a positive pressure pushes the surface towards the side its normal points to.
struct PointPressure {
  double pressure = 0.0;
  Eigen::Vector3d d_position = Eigen::Vector3d::Zero();  // dp/dy
};

// A pressure field on surface elements (the incident wave pressure on a membrane), evaluated at
// the surface's integration points on the current configuration (LoadPoint: position, velocity,
// acceleration, time, element; tangent zero). The element integrates it along its current
// normal and adds the load stiffness of the constant-pressure part and of the gradient.
class SurfaceLoad {
 public:
  virtual ~SurfaceLoad() = default;
  // The pressure at `p`; when `jacobians` is true, its gradient too.
  virtual PointPressure evaluate(const LoadPoint& p, bool jacobians) const = 0;
  virtual bool stiff() const { return true; }
};

// The finite-difference fallback for a load without analytic derivatives: central differences of
// `force(p)` in position, tangent (line points; the perturbed tangent is not renormalised),
// velocity and acceleration, with steps scaled to each vector.
template <class Force>
PointForce numericalJacobians(const LoadPoint& p, const Force& force) {
  PointForce out;
  out.force = force(p);
  const auto column = [&](Eigen::Vector3d LoadPoint::*field, Eigen::Matrix3d& d) {
    const double h = 1e-6 * std::max(1.0, (p.*field).norm());
    for (int k = 0; k < 3; ++k) {
      LoadPoint plus = p, minus = p;
      (plus.*field)(k) += h;
      (minus.*field)(k) -= h;
      d.col(k) = (force(plus) - force(minus)) / (2.0 * h);
    }
  };
  column(&LoadPoint::position, out.d_position);
  if (!p.tangent.isZero(0.0)) column(&LoadPoint::tangent, out.d_tangent);
  column(&LoadPoint::velocity, out.d_velocity);
  column(&LoadPoint::acceleration, out.d_acceleration);
  return out;
}

}  // namespace flexmoor::model

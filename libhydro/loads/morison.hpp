#pragma once
// Morison's load per unit length on a line (Appendix E, Eq. E.1-E.12; docs/theory.md) at one point of
// the deformed line with unit tangent t, from the relative flow split into its normal and
// tangential parts:
//   f = 1/2 rho d Cn |v_rn| v_rn + 1/2 rho A_t Ct |v_rt| v_rt            drag (A_t = pi d or d)
//     + rho A [(1 + Ca) a_n + (1 + CaAx) a_t]                             Froude-Krylov + added mass
//     - rho A [Ca u''_n + CaAx u''_t]                                     added mass of the line
// with v_r = v - u', A = pi d^2 / 4; buoyancy is a separate load (it depends on wetness only).
// Its derivatives are what the Newton tangent needs: with respect to the point's velocity (drag
// damping), acceleration (added mass), the tangent, and the fluid velocity and acceleration (so
// that a caller chains them with the flow's gradient for the derivative in position).
#include <Eigen/Core>

namespace flexmoor::hydro {

struct MorisonCoefficients {
  // Whose tangential drag area: MoorDyn's pi d (skin friction over the wetted perimeter, the
  // default) or the dissertation's d (Eq. E.2).
  enum class TangentialDragArea { Perimeter, Diameter };
  double diameter = 0.0;  // hydrodynamic (volume-equivalent) diameter d
  double cn = 0.0;        // normal drag Cn (MoorDyn Cdn)
  double ct = 0.0;        // tangential drag Ct (MoorDyn Cdt)
  double ca = 0.0;        // normal added mass Ca (MoorDyn Can)
  double ca_axial = 0.0;  // tangential added mass CaAx (MoorDyn Cat)
  TangentialDragArea tangential_area = TangentialDragArea::Perimeter;
};

struct MorisonPointLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();                 // per unit length
  Eigen::Matrix3d d_velocity = Eigen::Matrix3d::Zero();            // df/du'  (= -damping)
  Eigen::Matrix3d d_acceleration = Eigen::Matrix3d::Zero();        // df/du'' (= -added mass)
  Eigen::Matrix3d d_tangent = Eigen::Matrix3d::Zero();             // df/dt
  Eigen::Matrix3d d_fluid_velocity = Eigen::Matrix3d::Zero();      // df/dv
  Eigen::Matrix3d d_fluid_acceleration = Eigen::Matrix3d::Zero();  // df/da
};

// t: unit tangent; u_dot, u_ddot: the line's velocity and acceleration; v, a: the fluid's
// velocity and local acceleration at the point; rho: water density.
MorisonPointLoad morisonLoad(const MorisonCoefficients& c, double rho, const Eigen::Vector3d& t,
                             const Eigen::Vector3d& u_dot, const Eigen::Vector3d& u_ddot,
                             const Eigen::Vector3d& v, const Eigen::Vector3d& a);

// The added-mass matrix per unit length rho A [Ca (I - t t^T) + CaAx t t^T] (docs/theory.md): the
// negative of morisonLoad's d_acceleration.
Eigen::Matrix3d addedMassPerLength(const MorisonCoefficients& c, double rho,
                                   const Eigen::Vector3d& t);

}  // namespace flexmoor::hydro

#pragma once
// A liquid enclosed by a membrane (the dissertation's Example 9, a fluid-filled tube):
// "the presence of the fluid inside the tube was simulated by the static resultant pressure and
// by lumping the internal mass at the membrane nodal points". Both halves of that model:
//
// - The pressure: the liquid's hydrostatic pressure p(z) = p_ref + rho_f g (z_ref - z) at the
//   deformed position of every integration point, pushing the wall outwards, as a follower load
//   (load_point.hpp's SurfaceLoad, integrated by the elements' one follower-pressure kernel,
//   Eq. 3.30-3.37, with its gradient stiffness). The internal gradient is included: with the
//   incident sea's pressure outside (wave_pressure_load.hpp: hydrostatic -rho g z plus the waves)
//   the net static load on the wall is the dissertation's resultant, (p_ref - rho g |z_ref|) +
//   (rho - rho_f) g (z_ref - z), whose integral over the wall is buoyancy minus the liquid's
//   weight. The liquid's weight therefore reaches the wall through this gradient: its lumped
//   masses carry no weight of their own (PointMassElement with weighs = false), or it would count
//   twice. The pressure does not change with the enclosed volume (the dissertation's static
//   pressure; a liquid that is compressible or fills a stiff wall would need more).
// - The mass: rho_f V, with V the enclosed volume of the reference configuration, lumped at the
//   wall's nodes in proportion to the area each carries (Element::nodalAreas): m_I = rho_f (V / A)
//   A_I. For a circular tube V / A = R / 2 (mass per unit wall area rho_f R / 2); the total is
//   rho_f V to round-off. In a rigid translation the lumped liquid moves with the wall, which is
//   what the real liquid does; in a deformation it moves with the nearest wall, a lumping (the
//   potential-flow added mass of an inextensional ovalling mode n of a tube is rho_f R / n per
//   area on the normal motion instead).
//
// The volume is V = int z n_z dA over the wall (the divergence theorem with the field z e_z),
// which holds for a closed surface and for one whose openings lie in vertical planes (a tube
// with a horizontal axis modelled between symmetry planes). The sign of V says where the normal
// n = y,1 x y,2 points: out of the liquid when V > 0.
#include <utility>
#include <vector>

#include "libstruct/model/load_point.hpp"
#include "libstruct/model/model.hpp"

namespace flexmoor::hydro {

struct EnclosedFluid {
  double density = 0.0;      // rho_f
  double pressure = 0.0;     // p_ref, gauge, at the elevation reference_z
  double reference_z = 0.0;  // z_ref
  double gravity = 0.0;      // g, acting along -z (0: no gradient, no weight)
};

class EnclosedFluidPressure final : public model::SurfaceLoad {
 public:
  // outward: +1 when the surface normal y,1 x y,2 points out of the liquid, -1 when into it.
  EnclosedFluidPressure(EnclosedFluid fluid, double outward);

  model::PointPressure evaluate(const model::LoadPoint& p, bool jacobians) const override;
  const EnclosedFluid& fluid() const { return fluid_; }

 private:
  EnclosedFluid fluid_;
  double outward_;
};

// What the wall of an enclosure measures on a configuration.
struct Enclosure {
  double volume = 0.0;         // int z n_z dA: signed, > 0 when the normals point out
  double area = 0.0;           // reference area, sum of the nodal areas
  double vertical_area = 0.0;  // int n_z dA: zero for a closed surface or vertical openings
  Eigen::Vector3d vector_area = Eigen::Vector3d::Zero();  // int n dA
  bool axisymmetric = false;  // every element a meridian: volume and areas per radian
  bool mixed = false;         // axisymmetric and 3-D elements together (not an enclosure)
};
Enclosure measureEnclosure(const model::Model& model, const std::vector<int>& elements,
                           const model::State& state);

// The liquid's mass at each wall node, (node, mass), m_I = density (|V| / A) A_I: per radian for
// an axisymmetric wall. Their sum is density |V|.
std::vector<std::pair<int, double>> lumpedFluidMasses(const model::Model& model,
                                                      const std::vector<int>& elements,
                                                      const Enclosure& enclosure, double density);

// Puts the liquid on the model: its pressure as a surface load on the elements (outward from the
// sign of the reference volume) and its lumped masses as weightless point masses. Returns the
// number of point-mass elements added (they come after the model's other elements).
int addEnclosedFluid(model::Model& model, const std::vector<int>& elements,
                     const EnclosedFluid& fluid);

}  // namespace flexmoor::hydro

#include "libstruct/material/cable_material.hpp"

#include <cmath>

namespace flexmoor::material {

CableStress CableMaterial::stress(double a11, double A11) const {
  const double stretch = std::sqrt(A11 / a11);
  if (compression_ == Compression::TensionOnly && stretch < 1.0) return {0.0, 0.0};
  const PhysicalStress p = law(stretch);
  return {p.S / a11, p.dSdStretch / (stretch * a11 * a11)};
}

double CableMaterial::tension(double a11, double A11, double A0) const {
  const double stretch = std::sqrt(A11 / a11);
  if (compression_ == Compression::TensionOnly && stretch < 1.0) return 0.0;
  return law(stretch).S * stretch * A0;  // T11 a11 = S
}

LinearElasticCable::LinearElasticCable(double youngs_modulus, Compression compression)
    : CableMaterial(compression), E_(youngs_modulus) {}

PhysicalStress LinearElasticCable::law(double stretch) const {
  return {0.5 * E_ * (stretch * stretch - 1.0), E_ * stretch};
}

EngineeringStrainCable::EngineeringStrainCable(double youngs_modulus, Compression compression)
    : CableMaterial(compression), E_(youngs_modulus) {}

PhysicalStress EngineeringStrainCable::law(double stretch) const {
  return {E_ * (stretch - 1.0) / stretch, E_ / (stretch * stretch)};
}

MooneyRivlinCable::MooneyRivlinCable(double C1, double C2, Compression compression)
    : CableMaterial(compression), C1_(C1), C2_(C2) {}

PhysicalStress MooneyRivlinCable::law(double stretch) const {
  const double l = stretch;
  const double l3 = l * l * l;
  const double shape = 1.0 - 1.0 / l3;  // 1 - lambda^-3
  const double moduli = C1_ + C2_ / l;  // C1 + C2 / lambda
  const double S = 2.0 * shape * moduli;
  const double dS = 2.0 * (3.0 / (l3 * l) * moduli - shape * C2_ / (l * l));
  return {S, dS};
}

}  // namespace flexmoor::material

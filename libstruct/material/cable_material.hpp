#pragma once
// Constitutive laws of a cable, behind one interface (Eq. 2.53, 2.54).
//
// A law is written in physical form: the second Piola-Kirchhoff stress S(lambda) per unit
// reference area and dS/dlambda, with lambda = sqrt(A11 / a11) the stretch. The interface turns
// it into the convected components the element needs: T^11 = S / a11 and
// C^1111 = dT^11 / d gamma11 = (dS/dlambda) / (lambda a11^2), since d gamma11 = lambda a11 dlambda.
#include <memory>
#include <string>

namespace flexmoor::material {

// What a cable does when it is shortened below its unstretched length.
enum class Compression {
  Carry,        // the law is used as it stands: the cable resists compression (a bar)
  TensionOnly,  // slack: zero stress and zero stiffness when lambda < 1 (a real rope or chain)
};

struct CableStress {
  double T11;    // contravariant Kirchhoff stress (Eq. 2.53 / 2.54)
  double C1111;  // dT11 / d gamma11, the material part of the tangent (Eq. 4.48)
};

struct PhysicalStress {
  double S;  // second Piola-Kirchhoff stress, force per unit reference area
  double dSdStretch;
};

class CableMaterial {
 public:
  explicit CableMaterial(Compression compression) : compression_(compression) {}
  virtual ~CableMaterial() = default;

  // Stress and tangent for reference metric a11 and current metric A11.
  CableStress stress(double a11, double A11) const;

  // Axial force in the deformed cable for a reference cross-section A0: N = S lambda A0.
  double tension(double a11, double A11, double A0) const;

  // The modulus at the unstretched length, dS/dlambda at lambda = 1 (E; 6 (C1 + C2) for
  // Mooney-Rivlin): the axial stiffness EA of a section is this times its area.
  double initialModulus() const { return law(1.0).dSdStretch; }
  Compression compression() const { return compression_; }
  virtual std::string name() const = 0;

 protected:
  virtual PhysicalStress law(double stretch) const = 0;

 private:
  Compression compression_;
};

// Eq. 2.53: S = E * (lambda^2 - 1) / 2, the Green strain times Young's modulus.
class LinearElasticCable final : public CableMaterial {
 public:
  LinearElasticCable(double youngs_modulus, Compression compression);
  std::string name() const override { return "linear_elastic"; }

 protected:
  PhysicalStress law(double stretch) const override;

 private:
  double E_;
};

// The linear law of mooring codes (Irvine's elastic catenary, MAP++, MoorDyn): the axial force
// N = E A0 (lambda - 1), linear in the engineering strain, so S = N / (lambda A0) =
// E (lambda - 1) / lambda. It equals Eq. 2.53 to first order in the strain; at strain e the
// force of Eq. 2.53 is larger by the factor (1 + e)(1 + e / 2).
class EngineeringStrainCable final : public CableMaterial {
 public:
  EngineeringStrainCable(double youngs_modulus, Compression compression);
  std::string name() const override { return "linear_elastic (engineering strain)"; }

 protected:
  PhysicalStress law(double stretch) const override;

 private:
  double E_;
};

// Eq. 2.54, incompressible Mooney-Rivlin: S = 2 (1 - lambda^-3)(C1 + C2 / lambda).
class MooneyRivlinCable final : public CableMaterial {
 public:
  MooneyRivlinCable(double C1, double C2, Compression compression);
  std::string name() const override { return "mooney_rivlin"; }

 protected:
  PhysicalStress law(double stretch) const override;

 private:
  double C1_, C2_;
};

}  // namespace flexmoor::material

#pragma once
// Physical units of case files. A value is either a plain number, taken to be in the case's
// consistent system already, or "NUMBER UNIT" ("0.163 in", "500000 psi", "0.031056 slug/ft^3"),
// converted once on reading into the case's system (US: ft, slug, s; SI: m, kg, s).
//
// A unit expression is a product of base units with optional integer exponents, '*' or a space
// multiplying and '/' dividing the factor that follows it; parentheses group:
//   "lbf/ft^2", "slug/ft^3", "kg m^-3", "lbf s^2/ft", "N/(m s)", "1/s".
// Base units: m um mm cm km in ft nmi | kg mg g t slug lbm | s ms us min h d |
// N mN kN MN GN kgf tf lbf lb kip | Pa hPa kPa MPa GPa mbar bar psi psf ksi ksf | rad deg Hz kHz
// (um and us also as µm, µs and μm, μs). Conversion factors are exact: 1 ft = 0.3048 m,
// 1 in = 0.0254 m, 1 nmi = 1852 m, 1 lbm = 0.45359237 kg, 1 lbf = 4.4482216152605 N,
// 1 slug = 1 lbf s^2/ft, 1 kgf = 9.80665 N, 1 tf = 1000 kgf, 1 bar = 1e5 Pa, 1 d = 86400 s.
#include <stdexcept>
#include <string>

#include "apps/problem/unit_system.hpp"

namespace flexmoor::app {

// Exponents of mass, length and time.
struct Dimension {
  int mass = 0, length = 0, time = 0;
  bool operator==(const Dimension& o) const {
    return mass == o.mass && length == o.length && time == o.time;
  }
  bool operator!=(const Dimension& o) const { return !(*this == o); }
};

// What a case field holds, named for messages ("expected a pressure").
struct QuantityKind {
  const char* name;  // with its article: "a pressure", "an area"
  Dimension dimension;
};

namespace kind {
inline constexpr QuantityKind kNumber{"a plain number", {0, 0, 0}};
inline constexpr QuantityKind kLength{"a length", {0, 1, 0}};
inline constexpr QuantityKind kArea{"an area", {0, 2, 0}};
inline constexpr QuantityKind kMass{"a mass", {1, 0, 0}};
inline constexpr QuantityKind kTime{"a time", {0, 0, 1}};
inline constexpr QuantityKind kForce{"a force", {1, 1, -2}};
inline constexpr QuantityKind kPressure{"a pressure", {1, -1, -2}};
inline constexpr QuantityKind kDensity{"a density (mass per volume)", {1, -3, 0}};
inline constexpr QuantityKind kAcceleration{"an acceleration", {0, 1, -2}};
inline constexpr QuantityKind kStiffness{"a force per length", {1, 0, -2}};
inline constexpr QuantityKind kVolume{"a volume", {0, 3, 0}};
inline constexpr QuantityKind kVelocity{"a velocity", {0, 1, -1}};
// A frequency in hertz or a circular frequency in rad/s (rad is a plain number: the case says
// which); a wave spectrum's density per hertz or per rad/s.
inline constexpr QuantityKind kFrequency{"a frequency (like Hz or rad/s)", {0, 0, -1}};
inline constexpr QuantityKind kSpectralDensity{"a spectral density (like m^2/Hz or m^2 s/rad)",
                                               {0, 2, 1}};
// A seabed's penalty stiffness and damping per projected area (MoorDyn's kBot and cBot).
inline constexpr QuantityKind kBedStiffness{"a pressure per length (like Pa/m)", {1, -2, -2}};
inline constexpr QuantityKind kBedDamping{"a pressure per velocity (like Pa s/m)", {1, -2, -1}};
// A line's axial Kelvin-Voigt coefficient, force per unit strain rate (MoorDyn's BA).
inline constexpr QuantityKind kAxialDamping{"a force times a time (like N*s)", {1, 1, -1}};
// A dashpot's coefficient, force per velocity.
inline constexpr QuantityKind kDashpot{"a force per velocity (like N*s/m)", {1, 0, -1}};
}  // namespace kind

// A malformed value or unit expression, or a unit of the wrong dimension.
class UnitError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A unit expression as a multiple of the SI base units.
struct Unit {
  double si_factor = 1.0;  // value in SI of one of this unit
  Dimension dimension;
};

// Parses a unit expression ("lbf/ft^2"); throws UnitError naming what it could not read.
Unit parseUnit(const std::string& expression);

// Size, in SI, of one unit of `dimension` in the case system (US: 0.3048 for a length).
double systemScale(Dimension dimension, UnitSystem system);

// Standard gravity 9.80665 m/s^2 in the case system (32.174 ft/s^2 in US units).
double standardGravity(UnitSystem system);

// Reads "NUMBER" or "NUMBER UNIT" as a value of `expected` in the case system. Throws UnitError
// for text that is not a number, an unknown unit, or a unit of another dimension
// ("expected a pressure, got 'ft' (a length)").
double parseValue(const std::string& text, const QuantityKind& expected, UnitSystem system);

// "a length", "a pressure" when the dimension is one of the named kinds, else "kg^a m^b s^c".
std::string describeDimension(Dimension dimension);

// CF (udunits) units of `dimension` in the case system: SI "m", "s", "N", "Pa", "kg m-3",
// "m s-1"; US "ft", "s", "lbf", "lbf ft-2", "slug ft-3", "ft s-1" (a force times lengths as lbf,
// a mass otherwise as slug); "1" for none.
std::string systemUnits(Dimension dimension, UnitSystem system);

}  // namespace flexmoor::app

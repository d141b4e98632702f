// Units of case files: exact conversions into the US (ft, slug, s) and SI (m, kg, s) systems,
// unit expressions, and refusal of units of the wrong dimension.
#include "apps/case/input/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>

namespace flexmoor::app {
namespace {

constexpr double kFoot = 0.3048;
constexpr double kPoundForce = 4.4482216152605;

double us(const std::string& text, const QuantityKind& k) {
  return parseValue(text, k, UnitSystem::US);
}
double si(const std::string& text, const QuantityKind& k) {
  return parseValue(text, k, UnitSystem::SI);
}

void expectRelative(double actual, double expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << actual << " vs " << expected;
}

TEST(Units, PsiToPoundsPerSquareFoot) {
  expectRelative(us("500000 psi", kind::kPressure), 7.2e7);  // 500000 * 144
  expectRelative(us("1.0e6 psf", kind::kPressure), 1.0e6);
  expectRelative(us("3.6e6 ksf", kind::kPressure), 3.6e9);
  expectRelative(us("24 psi", kind::kPressure), 24.0 * 144.0);
}

TEST(Units, KipIsAThousandPoundsForce) {
  expectRelative(us("1 kip", kind::kForce), 1000.0);
  expectRelative(us("13.608 kip", kind::kForce), 13608.0);
  expectRelative(us("5.8 lbf", kind::kForce), 5.8);
  expectRelative(us("5.8 lb", kind::kForce), 5.8);
  expectRelative(us("100 kN", kind::kForce), 1.0e5 / kPoundForce);
}

TEST(Units, SlugPerCubicFootToKilogramPerCubicMetre) {
  expectRelative(si("1 slug/ft^3", kind::kDensity), 515.378818, 1e-8);
  expectRelative(us("0.031056 slug/ft^3", kind::kDensity), 0.031056);
  expectRelative(us("515.378818 kg/m^3", kind::kDensity), 1.0, 1e-8);
}

TEST(Units, LengthsAreasAndAccelerations) {
  expectRelative(us("71.56 in", kind::kLength), 71.56 / 12.0);
  expectRelative(us("0.163 in", kind::kLength), 0.163 / 12.0);
  expectRelative(si("200 ft", kind::kLength), 200.0 * kFoot);
  expectRelative(si("0.1 ft^2", kind::kArea), 0.1 * kFoot * kFoot);
  expectRelative(si("32.2 ft/s^2", kind::kAcceleration), 32.2 * kFoot);
  expectRelative(si("2.381e-3 lbf/ft", kind::kStiffness), 2.381e-3 * kPoundForce / kFoot);
  expectRelative(us("1 t", kind::kMass), 1000.0 / (kPoundForce / kFoot));
}

TEST(Units, PlainNumberIsAlreadyInTheCaseSystem) {
  EXPECT_EQ(us("200", kind::kLength), 200.0);
  EXPECT_EQ(si("-32.2", kind::kAcceleration), -32.2);
  EXPECT_EQ(us("1e-8", kind::kNumber), 1e-8);
  EXPECT_EQ(us("+2.5", kind::kLength), 2.5);
}

TEST(Units, ProductsQuotientsExponentsAndParentheses) {
  const Unit slug = parseUnit("lbf s^2/ft");
  EXPECT_EQ(slug.dimension, (Dimension{1, 0, 0}));
  expectRelative(slug.si_factor, kPoundForce / kFoot);
  EXPECT_EQ(parseUnit("kg m^-3").dimension, kind::kDensity.dimension);
  EXPECT_EQ(parseUnit("kg*m/s^2").dimension, kind::kForce.dimension);
  const Unit viscosity = parseUnit("kg/(m s)");
  EXPECT_EQ(viscosity.dimension, (Dimension{1, -1, -1}));
  EXPECT_EQ(parseUnit("N s/m^2").dimension, viscosity.dimension);
  EXPECT_EQ(parseUnit("lbf/ft^2").dimension, kind::kPressure.dimension);
  expectRelative(parseUnit("ksi").si_factor, 1000.0 * kPoundForce / (0.0254 * 0.0254));
}

// Every prefixed and metric unit: its factor to SI, exactly as defined (SI prefixes; 1 nmi = 1852 m;
// 1 kgf = 9.80665 N, standard gravity; 1 tf = 1000 kgf; 1 bar = 1e5 Pa; 1 d = 86400 s), and its
// dimension. Equality, not a tolerance: each factor is one literal.
TEST(Units, PrefixedUnitsHaveTheirExactFactors) {
  struct Expected {
    const char* name;
    double factor;
    Dimension dimension;
  };
  const Dimension L{0, 1, 0}, M{1, 0, 0}, T{0, 0, 1}, F = kind::kForce.dimension,
                                                      P = kind::kPressure.dimension, f{0, 0, -1};
  for (const Expected& e : std::initializer_list<Expected>{
           {"um", 1e-6, L},     {"µm", 1e-6, L},    {"μm", 1e-6, L},    {"mm", 1e-3, L},
           {"cm", 1e-2, L},     {"km", 1e3, L},     {"nmi", 1852.0, L}, {"mg", 1e-6, M},
           {"g", 1e-3, M},      {"kg", 1.0, M},     {"t", 1e3, M},      {"us", 1e-6, T},
           {"µs", 1e-6, T},     {"μs", 1e-6, T},    {"ms", 1e-3, T},    {"s", 1.0, T},
           {"min", 60.0, T},    {"h", 3600.0, T},   {"d", 86400.0, T},  {"mN", 1e-3, F},
           {"N", 1.0, F},       {"kN", 1e3, F},     {"MN", 1e6, F},     {"GN", 1e9, F},
           {"kgf", 9.80665, F}, {"tf", 9806.65, F}, {"Pa", 1.0, P},     {"hPa", 1e2, P},
           {"kPa", 1e3, P},     {"MPa", 1e6, P},    {"GPa", 1e9, P},    {"mbar", 1e2, P},
           {"bar", 1e5, P},     {"Hz", 1.0, f},     {"kHz", 1e3, f}}) {
    const Unit u = parseUnit(e.name);
    EXPECT_EQ(u.si_factor, e.factor) << e.name;
    EXPECT_EQ(u.dimension, e.dimension) << e.name;
  }
  // In values: a time step in milliseconds, a modulus in GPa, a line's weight in kN/m.
  EXPECT_EQ(si("10 ms", kind::kTime), 10.0 * 1e-3);
  EXPECT_EQ(si("200 GPa", kind::kPressure), 2.0e11);
  EXPECT_EQ(si("1.5 kN/m", kind::kStiffness), 1500.0);
  expectRelative(us("250 ms", kind::kTime), 0.25, 1e-16);
  expectRelative(us("1 tf", kind::kForce), 9806.65 / kPoundForce, 1e-15);
  EXPECT_THROW(si("1 ms", kind::kLength), UnitError);  // a time, not a metre times a second
}

TEST(Units, DegreesAreRadians) {
  expectRelative(us("180 deg", kind::kNumber), 3.14159265358979323846);
  EXPECT_EQ(us("0.5 rad", kind::kNumber), 0.5);
}

TEST(Units, WrongDimensionIsRejected) {
  try {
    us("1.0e6 ft", kind::kPressure);
    FAIL() << "a length accepted as a pressure";
  } catch (const UnitError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a pressure, got 'ft' (a length)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(us("0.1 ft", kind::kArea), UnitError);
  EXPECT_THROW(us("5 kg", kind::kForce), UnitError);  // mass is not weight
  EXPECT_THROW(us("3 deg", kind::kLength), UnitError);
}

TEST(Units, UnknownUnitsAndMalformedValuesAreRejected) {
  EXPECT_THROW(us("200 fts", kind::kLength), UnitError);
  EXPECT_THROW(us("ft", kind::kLength), UnitError);
  EXPECT_THROW(us("", kind::kLength), UnitError);
  EXPECT_THROW(us("inf", kind::kLength), UnitError);
  EXPECT_THROW(us("2 ft^", kind::kLength), UnitError);
  EXPECT_THROW(us("2 lbf/(ft", kind::kStiffness), UnitError);
  EXPECT_THROW(us("2 ft^x", kind::kLength), UnitError);
}

TEST(Units, UnitNamesOfEachSystem) {
  const UnitNames u = unitNames(UnitSystem::US);
  EXPECT_EQ(u.length, "ft");
  EXPECT_EQ(u.mass, "slug");
  EXPECT_EQ(u.time, "s");
  EXPECT_EQ(u.force, "lbf");
  EXPECT_EQ(u.pressure, "lbf/ft^2");
  const UnitNames s = unitNames(UnitSystem::SI);
  EXPECT_EQ(s.length, "m");
  EXPECT_EQ(s.mass, "kg");
  EXPECT_EQ(s.force, "N");
  EXPECT_EQ(s.pressure, "Pa");
}

}  // namespace
}  // namespace flexmoor::app

// Units of case files: exact conversions into the US (ft, slug, s) and SI (m, kg, s) systems,
// unit expressions, and refusal of units of the wrong dimension.
#include "apps/case/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

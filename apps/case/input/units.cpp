#include "apps/case/input/units.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace flexmoor::app {
namespace {

constexpr double kFoot = 0.3048;                        // m, exact
constexpr double kInch = 0.0254;                        // m, exact
constexpr double kPoundMass = 0.45359237;               // kg, exact
constexpr double kPoundForce = 4.4482216152605;         // N, exact: lbm * 9.80665 m/s^2
constexpr double kSlug = kPoundForce / kFoot;           // kg: 1 lbf s^2 / ft
constexpr double kPsi = kPoundForce / (kInch * kInch);  // Pa
constexpr double kPsf = kPoundForce / (kFoot * kFoot);  // Pa
constexpr double kPi = 3.14159265358979323846;
constexpr double kStandardGravity = 9.80665;  // m/s^2, exact (CGPM 1901): kgf and tf

constexpr Dimension kDimensionless{0, 0, 0};
constexpr Dimension kL{0, 1, 0}, kM{1, 0, 0}, kT{0, 0, 1};
constexpr Dimension kF = kind::kForce.dimension, kP = kind::kPressure.dimension;

struct BaseUnit {
  const char* name;
  double si_factor;
  Dimension dimension;
};

// SI prefixes where they are in common use; "µ" (U+00B5) and "μ" (U+03BC) as well as "u".
constexpr BaseUnit kBaseUnits[] = {
    {"m", 1.0, kL},
    {"um", 1e-6, kL},
    {"µm", 1e-6, kL},
    {"μm", 1e-6, kL},
    {"mm", 1e-3, kL},
    {"cm", 1e-2, kL},
    {"km", 1e3, kL},
    {"in", kInch, kL},
    {"ft", kFoot, kL},
    {"nmi", 1852.0, kL},  // nautical mile, exact
    {"kg", 1.0, kM},
    {"mg", 1e-6, kM},
    {"g", 1e-3, kM},
    {"t", 1e3, kM},
    {"slug", kSlug, kM},
    {"lbm", kPoundMass, kM},
    {"s", 1.0, kT},
    {"ms", 1e-3, kT},
    {"us", 1e-6, kT},
    {"µs", 1e-6, kT},
    {"μs", 1e-6, kT},
    {"min", 60.0, kT},
    {"h", 3600.0, kT},
    {"d", 86400.0, kT},
    {"N", 1.0, kF},
    {"mN", 1e-3, kF},
    {"kN", 1e3, kF},
    {"MN", 1e6, kF},
    {"GN", 1e9, kF},
    {"kgf", kStandardGravity, kF},
    {"tf", 1e3 * kStandardGravity, kF},  // tonne-force, the unit of a mooring line's MBL
    {"lbf", kPoundForce, kF},
    {"lb", kPoundForce, kF},
    {"kip", 1e3 * kPoundForce, kF},
    {"Pa", 1.0, kP},
    {"hPa", 1e2, kP},
    {"kPa", 1e3, kP},
    {"MPa", 1e6, kP},
    {"GPa", 1e9, kP},
    {"mbar", 1e2, kP},
    {"bar", 1e5, kP},
    {"psi", kPsi, kP},
    {"psf", kPsf, kP},
    {"ksi", 1e3 * kPsi, kP},
    {"ksf", 1e3 * kPsf, kP},
    {"rad", 1.0, kDimensionless},
    {"deg", kPi / 180.0, kDimensionless},
    {"Hz", 1.0, {0, 0, -1}},
    {"kHz", 1e3, {0, 0, -1}},
};

constexpr QuantityKind kNamedKinds[] = {
    kind::kLength,       kind::kArea,
    kind::kMass,         kind::kTime,
    kind::kForce,        kind::kPressure,
    kind::kDensity,      kind::kAcceleration,
    kind::kStiffness,    kind::kVolume,
    kind::kVelocity,     kind::kBedStiffness,
    kind::kBedDamping,   {"a frequency", {0, 0, -1}},
    kind::kAxialDamping, kind::kDashpot,
};

std::string baseUnitList() {
  std::string list;
  for (const BaseUnit& u : kBaseUnits) list += (list.empty() ? "" : ", ") + std::string(u.name);
  return list;
}

Unit power(Unit u, int exponent) {
  return {
      std::pow(u.si_factor, exponent),
      {u.dimension.mass * exponent, u.dimension.length * exponent, u.dimension.time * exponent}};
}

Unit times(const Unit& a, const Unit& b) {
  return {a.si_factor * b.si_factor,
          {a.dimension.mass + b.dimension.mass, a.dimension.length + b.dimension.length,
           a.dimension.time + b.dimension.time}};
}

// Recursive descent over
//   product := factor { ('*' | '/' | spaces) factor }
//   factor  := (NAME | '(' product ')') ['^' ['-' | '+'] DIGITS]
class UnitParser {
 public:
  explicit UnitParser(const std::string& text) : text_(text) {}

  Unit parse() {
    skipSpaces();
    const Unit u = product();
    skipSpaces();
    if (pos_ != text_.size()) fail("unexpected '" + text_.substr(pos_) + "'");
    return u;
  }

 private:
  Unit product() {
    Unit u = factor();
    for (;;) {
      const size_t before = pos_;
      skipSpaces();
      if (pos_ == text_.size() || peek() == ')') return u;
      int sign = 1;
      if (peek() == '*' || peek() == '/') {
        sign = text_[pos_++] == '/' ? -1 : 1;
        skipSpaces();
      } else if (pos_ == before) {
        fail("unexpected '" + text_.substr(pos_) + "'");
      }
      u = times(u, power(factor(), sign));
    }
  }

  Unit factor() {
    Unit u;
    if (peek() == '(') {
      ++pos_;
      skipSpaces();
      u = product();
      if (peek() != ')') fail("missing ')'");
      ++pos_;
    } else {
      const size_t start = pos_;
      while (pos_ < text_.size() && isNameByte(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      u = lookup(text_.substr(start, pos_ - start));
    }
    if (peek() == '^') {
      ++pos_;
      u = power(u, exponent());
    }
    return u;
  }

  Unit lookup(const std::string& name) const {
    if (name.empty()) fail("expected a unit name at '" + text_.substr(pos_) + "'");
    for (const BaseUnit& b : kBaseUnits)
      if (name == b.name) return {b.si_factor, b.dimension};
    throw UnitError("unknown unit '" + name + "' (expected units built from " + baseUnitList() +
                    ")");
  }

  int exponent() {
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    if (first != last && *first == '+') ++first;
    int e = 0;
    const auto [end, error] = std::from_chars(first, last, e);
    if (error != std::errc()) fail("expected an integer exponent after '^'");
    pos_ = static_cast<size_t>(end - text_.data());
    return e;
  }

  // A letter, or a byte of a UTF-8 sequence (the micro signs).
  static bool isNameByte(unsigned char c) { return std::isalpha(c) || c >= 0x80; }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void skipSpaces() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw UnitError("cannot read unit '" + text_ + "': " + what);
  }

  const std::string& text_;
  size_t pos_ = 0;
};

std::string trim(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

Unit parseUnit(const std::string& expression) { return UnitParser(expression).parse(); }

double systemScale(Dimension d, UnitSystem system) {
  if (system == UnitSystem::SI) return 1.0;
  return std::pow(kSlug, d.mass) * std::pow(kFoot, d.length);  // US: slug, ft, s
}

std::string systemUnits(Dimension d, UnitSystem system) {
  const bool us = system == UnitSystem::US;
  const std::string length = us ? "ft" : "m";
  if (d.mass == 1 && d.length == 1 && d.time == -2) return us ? "lbf" : "N";
  if (!us && d.mass == 1 && d.length == -1 && d.time == -2) return "Pa";
  std::vector<std::pair<std::string, int>> factors;
  if (us && d.mass == 1 && d.time <= -2) {  // a force times what is left: lbf ft-2, lbf s ft-1
    factors = {{"lbf", 1}, {"ft", d.length - 1}, {"s", d.time + 2}};
  } else {
    factors = {{us ? "slug" : "kg", d.mass}, {length, d.length}, {"s", d.time}};
  }
  std::string units;
  for (const auto& [name, exponent] : factors) {
    if (exponent == 0) continue;
    units += (units.empty() ? "" : " ") + name + (exponent == 1 ? "" : std::to_string(exponent));
  }
  return units.empty() ? "1" : units;
}

double standardGravity(UnitSystem system) {
  return kStandardGravity / systemScale(kind::kAcceleration.dimension, system);
}

double parseValue(const std::string& text, const QuantityKind& expected, UnitSystem system) {
  const std::string t = trim(text);
  const char* first = t.data();
  const char* last = t.data() + t.size();
  if (first != last && *first == '+') ++first;
  double number = 0.0;
  const auto [end, error] = std::from_chars(first, last, number);
  if (error != std::errc() || !std::isfinite(number))
    throw UnitError("not a number (got '" + t + "', expected " + expected.name +
                    ", a number with an optional unit)");
  const std::string unit_text = trim(std::string(end, last));
  if (unit_text.empty()) return number;  // already in the case's system
  const Unit unit = parseUnit(unit_text);
  if (unit.dimension != expected.dimension)
    throw UnitError("wrong unit: expected " + std::string(expected.name) + ", got '" + unit_text +
                    "' (" + describeDimension(unit.dimension) + ")");
  return number * unit.si_factor / systemScale(unit.dimension, system);
}

std::string describeDimension(Dimension d) {
  if (d == kDimensionless) return "dimensionless";
  for (const QuantityKind& k : kNamedKinds)
    if (k.dimension == d) return k.name;
  std::ostringstream s;
  const char* sep = "";
  for (const auto& [symbol, exponent] :
       {std::pair{"kg", d.mass}, std::pair{"m", d.length}, std::pair{"s", d.time}}) {
    if (exponent == 0) continue;
    s << sep << symbol;
    if (exponent != 1) s << "^" << exponent;
    sep = " ";
  }
  return s.str();
}

}  // namespace flexmoor::app

#include "libstruct/shape/triangle_quadrature.hpp"

#include <array>
#include <mutex>
#include <stdexcept>
#include <string>

#include "libstruct/shape/gauss_legendre.hpp"

namespace flexmoor::shape {
namespace {

// A symmetric rule is a list of orbits of the vertex permutations, in area coordinates:
// the centroid (1/3, 1/3, 1/3), a median orbit (a, a, 1 - 2a) of 3 points, or a general orbit
// (a, b, 1 - a - b) of 6 points. w is the weight of each point on a triangle of unit area.
enum OrbitKind { kCentroid, kMedian, kGeneral };

struct Orbit {
  OrbitKind kind;
  double a, b, w;
};

struct Table {
  int degree;
  std::vector<Orbit> orbits;
};

// D. A. Dunavant, High degree efficient symmetrical Gaussian quadrature rules for the triangle,
// Int. J. Numer. Meth. Engng 21 (1985) 1129-1148. The published 15-digit values were refined
// by Newton's method on the moment equations in 50-digit arithmetic, so each rule is exact to
// rounding (the tests check every monomial).
const std::vector<Table>& tables() {
  static const std::vector<Table> t = {
      {1, {{kCentroid, 0, 0, 1.0}}},
      {2, {{kMedian, 1.0 / 6.0, 0, 1.0 / 3.0}}},
      {4,
       {{kMedian, 0.44594849091596488632, 0, 0.2233815896780114657},
        {kMedian, 0.09157621350977074346, 0, 0.10995174365532186764}}},
      {5,
       {{kCentroid, 0, 0, 0.225},
        {kMedian, 0.47014206410511508977, 0, 0.13239415278850618074},
        {kMedian, 0.1012865073234563388, 0, 0.1259391805448271526}}},
      {6,
       {{kMedian, 0.24928674517091042129, 0, 0.11678627572637936603},
        {kMedian, 0.06308901449150222834, 0, 0.050844906370206816921},
        {kGeneral, 0.31035245103378440542, 0.63650249912139864723, 0.082851075618373575194}}},
      {8,
       {{kCentroid, 0, 0, 0.14431560767778716825},
        {kMedian, 0.17056930775176020662, 0, 0.10321737053471825028},
        {kMedian, 0.050547228317030975458, 0, 0.032458497623198080311},
        {kMedian, 0.45929258829272315603, 0, 0.095091634267284624794},
        {kGeneral, 0.26311282963463811342, 0.72849239295540428124, 0.027230314174434994265}}},
      {9,
       {{kCentroid, 0, 0, 0.097135796282798833819},
        {kMedian, 0.48968251919873762778, 0, 0.031334700227139070537},
        {kMedian, 0.43708959149293663727, 0, 0.077827541004774279317},
        {kMedian, 0.18820353561903273024, 0, 0.079647738927210253033},
        {kMedian, 0.044729513394452709865, 0, 0.025577675658698031262},
        {kGeneral, 0.22196298916076569568, 0.74119859878449802069, 0.043283539377289377289}}},
      {10,
       {{kCentroid, 0, 0, 0.090817990382753580095},
        {kMedian, 0.48557763338365737737, 0, 0.036725957756466704717},
        {kMedian, 0.1094815754850370548, 0, 0.045321059435527934783},
        {kGeneral, 0.14170721941487995476, 0.30793983876412095017, 0.072757916845420108604},
        {kGeneral, 0.025003534762686386074, 0.24667256063990269392, 0.028327242531057484837},
        {kGeneral, 0.0095408154002994575802, 0.066803251012200265774, 0.0094216669637328234599}}},
      {12,
       {{kMedian, 0.48821738977380488256, 0, 0.025731066440455335418},
        {kMedian, 0.43972439229446027298, 0, 0.043692544538038402135},
        {kMedian, 0.27121038501211592235, 0, 0.062858224217885100354},
        {kMedian, 0.12757614554158592467, 0, 0.034796112930708942989},
        {kMedian, 0.021317350453210370247, 0, 0.0061662610515590172339},
        {kGeneral, 0.11534349453469799917, 0.27571326968551419397, 0.040371557766380929518},
        {kGeneral, 0.02283833222225702961, 0.28132558098993954825, 0.022356773202303445712},
        {kGeneral, 0.025734050548330228168, 0.11625191590759714124, 0.017316231108658892372}}},
      {13,
       {{kCentroid, 0, 0, 0.052520923400802328149},
        {kMedian, 0.49504818493970458945, 0, 0.011280145209329582474},
        {kMedian, 0.46871663510957406454, 0, 0.031423518362454018241},
        {kMedian, 0.41452133680127692599, 0, 0.047072502504194459231},
        {kMedian, 0.22939957204283099258, 0, 0.047363586536354833992},
        {kMedian, 0.11442449519633029589, 0, 0.031167529045793884281},
        {kMedian, 0.024811391363458949582, 0, 0.0079757714650743531111},
        {kGeneral, 0.094853828379578049828, 0.26879499705876144245, 0.03684840272873217013},
        {kGeneral, 0.018100773278806748346, 0.29173006673428766072, 0.01740146330382192061},
        {kGeneral, 0.022233076674090163319, 0.12635738549166861433, 0.01552178683904495557}}},
      {14,
       {{kMedian, 0.48896391036217863868, 0, 0.021883581369428890641},
        {kMedian, 0.41764471934045392251, 0, 0.032788353544125350641},
        {kMedian, 0.27347752830883865975, 0, 0.051774104507291586315},
        {kMedian, 0.17720553241254343696, 0, 0.042162588736993017538},
        {kMedian, 0.061799883090872601267, 0, 0.014433699669776667602},
        {kMedian, 0.019390961248701048178, 0, 0.0049234036024000816818},
        {kGeneral, 0.057124757403647939036, 0.17226668782135557838, 0.024665753212563673963},
        {kGeneral, 0.092916249356971824758, 0.33686145979634500174, 0.038571510787060683228},
        {kGeneral, 0.014646950055654409671, 0.29837288213625775297, 0.014436308113533840496},
        {kGeneral, 0.0012683309328720250872, 0.1189744976969568454, 0.0050102288385006717699}}},
  };
  return t;
}

// Expands the orbits into points (r, s) = (L1, L2) and weights on the triangle of area 1/2.
QuadratureRule2D expand(const Table& table) {
  QuadratureRule2D rule;
  auto add = [&rule](double r, double s, double w) {
    rule.points.emplace_back(r, s);
    rule.weights.push_back(0.5 * w);
  };
  for (const Orbit& o : table.orbits) {
    switch (o.kind) {
      case kCentroid:
        add(1.0 / 3.0, 1.0 / 3.0, o.w);
        break;
      case kMedian: {
        const double c = 1.0 - 2.0 * o.a;
        add(o.a, o.a, o.w);
        add(c, o.a, o.w);
        add(o.a, c, o.w);
        break;
      }
      case kGeneral: {
        const double c = 1.0 - o.a - o.b;
        add(o.a, o.b, o.w);
        add(o.b, o.a, o.w);
        add(o.b, c, o.w);
        add(c, o.b, o.w);
        add(c, o.a, o.w);
        add(o.a, c, o.w);
        break;
      }
    }
  }
  return rule;
}

QuadratureRule2D tensorProduct(int n) {
  const QuadratureRule1D& g = gaussLegendre(n);
  QuadratureRule2D rule;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      rule.points.emplace_back(g.points[i], g.points[j]);
      rule.weights.push_back(g.weights[i] * g.weights[j]);
    }
  return rule;
}

constexpr int kMaxQuadPoints = 32;  // that of gaussLegendre

}  // namespace

const QuadratureRule2D& triangleRule(int degree) {
  if (degree < 1 || degree > kMaxTriangleDegree)
    throw std::invalid_argument("triangle quadrature degree must be 1.." +
                                std::to_string(kMaxTriangleDegree) + " (got " +
                                std::to_string(degree) + ")");
  static std::array<QuadratureRule2D, kMaxTriangleDegree + 1> cache;
  static std::array<std::once_flag, kMaxTriangleDegree + 1> once;
  std::call_once(once[degree], [degree] {
    for (const Table& t : tables())
      if (t.degree >= degree) {
        cache[degree] = expand(t);
        return;
      }
  });
  return cache[degree];
}

const QuadratureRule2D& gaussLegendreQuad(int n) {
  if (n < 1 || n > kMaxQuadPoints)
    throw std::invalid_argument("Gauss-Legendre order must be 1.." +
                                std::to_string(kMaxQuadPoints) + " (got " + std::to_string(n) +
                                ")");
  static std::array<QuadratureRule2D, kMaxQuadPoints + 1> cache;
  static std::array<std::once_flag, kMaxQuadPoints + 1> once;
  std::call_once(once[n], [n] { cache[n] = tensorProduct(n); });
  return cache[n];
}

}  // namespace flexmoor::shape

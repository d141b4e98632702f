#include "libhydro/loads/enclosed_fluid.hpp"

#include <cmath>
#include <map>
#include <memory>

#include "libstruct/element/spring_element.hpp"

namespace flexmoor::hydro {

EnclosedFluidPressure::EnclosedFluidPressure(EnclosedFluid fluid, double outward)
    : fluid_(fluid), outward_(outward) {}

model::PointPressure EnclosedFluidPressure::evaluate(const model::LoadPoint& p, bool) const {
  const double rho_g = fluid_.density * fluid_.gravity;
  model::PointPressure out;
  out.pressure = outward_ * (fluid_.pressure + rho_g * (fluid_.reference_z - p.position.z()));
  out.d_position = Eigen::Vector3d(0.0, 0.0, -outward_ * rho_g);
  return out;
}

Enclosure measureEnclosure(const model::Model& model, const std::vector<int>& elements,
                           const model::State& state) {
  // The follower-pressure kernel gives f_I = int p M^I n dA; summed over the nodes (sum M^I = 1)
  // it is int p n dA: p = z gives the volume, p = 1 the vector area.
  const element::Element::PressureField height = [](const model::LoadPoint& p, bool) {
    return model::PointPressure{p.position.z(), Eigen::Vector3d::Zero()};
  };
  const element::Element::PressureField unit = [](const model::LoadPoint&, bool) {
    return model::PointPressure{1.0, Eigen::Vector3d::Zero()};
  };
  Enclosure out;
  int meridians = 0;
  Eigen::VectorXd f;
  for (int e : elements) {
    const element::Element& el = model.element(e);
    const element::ElementContext c{model.reference(), state, e};
    el.followerPressure(c, height, f, nullptr);
    for (int I = 0; I < f.size() / 3; ++I) out.volume += f(3 * I + 2);
    el.followerPressure(c, unit, f, nullptr);
    for (int I = 0; I < f.size() / 3; ++I) out.vector_area += f.segment<3>(3 * I);
    out.area += el.nodalAreas(model.reference()).sum();
    meridians += el.axisymmetric() ? 1 : 0;
  }
  out.vertical_area = out.vector_area.z();
  out.axisymmetric = !elements.empty() && meridians == static_cast<int>(elements.size());
  out.mixed = meridians > 0 && !out.axisymmetric;
  return out;
}

std::vector<std::pair<int, double>> lumpedFluidMasses(const model::Model& model,
                                                      const std::vector<int>& elements,
                                                      const Enclosure& enclosure, double density) {
  const double per_area = density * std::abs(enclosure.volume) / enclosure.area;
  std::map<int, double> mass;
  for (int e : elements) {
    const element::Element& el = model.element(e);
    const Eigen::VectorXd areas = el.nodalAreas(model.reference());
    for (int I = 0; I < areas.size(); ++I) mass[el.nodes()[I]] += per_area * areas(I);
  }
  return {mass.begin(), mass.end()};
}

int addEnclosedFluid(model::Model& model, const std::vector<int>& elements,
                     const EnclosedFluid& fluid) {
  const Enclosure enclosure = measureEnclosure(model, elements, model.initialState());
  const double outward = enclosure.volume >= 0.0 ? 1.0 : -1.0;
  model.addSurfaceLoad(std::make_shared<EnclosedFluidPressure>(fluid, outward), elements);
  const auto masses = lumpedFluidMasses(model, elements, enclosure, fluid.density);
  for (const auto& [node, m] : masses)
    model.addElement(std::make_unique<element::PointMassElement>(node, m, false));
  return static_cast<int>(masses.size());
}

}  // namespace flexmoor::hydro

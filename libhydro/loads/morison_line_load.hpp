#pragma once
// Morison's load on line elements in a sea (Appendix E, Eq. E.1-E.12; docs/theory.md), through
// libstruct's load-point interface: at every integration point of the deformed line, the normal
// and tangential drag on the relative velocity, Froude-Krylov and added mass (morison.hpp), and
// the buoyancy rho g A of the displaced area, on the submerged part only (a point above the local
// surface elevation carries nothing, so a line may pierce the surface). Its derivatives: in
// velocity, acceleration and tangent from morisonLoad, in position from the flow's gradient
// (d f/d v . grad v + d f/d a . grad a).
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "libhydro/loads/morison.hpp"
#include "libhydro/waves/held_kinematics.hpp"
#include "libhydro/waves/sea.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::hydro {

class MorisonLineLoad final : public model::LineLoad {
 public:
  // sections[e]: the hydrodynamic section of model element e; nullopt (or e past the end) for an
  // element without one (a dry line, a membrane, a spring). `measure`: per deformed length (the
  // dissertation, the default) or per unstretched length (MoorDyn).
  MorisonLineLoad(std::shared_ptr<const Sea> sea,
                  std::vector<std::optional<MorisonCoefficients>> sections,
                  model::LengthMeasure measure = model::LengthMeasure::Current);
  // The flow taken from `held` (held_kinematics.hpp, over the same sea) instead of Sea::at at
  // every call: one evaluation a point and time step, Taylor-expanded over its iterations.
  void holdKinematics(std::shared_ptr<const HeldKinematics> held) { held_ = std::move(held); }
  const HeldKinematics* heldKinematics() const { return held_.get(); }

  model::PointForce evaluate(const model::LoadPoint& p, bool jacobians) const override;
  model::LengthMeasure measure() const override { return measure_; }

 private:
  std::shared_ptr<const Sea> sea_;
  std::shared_ptr<const Sea>
      still_;  // sea_ without its waves, for static solves (LoadPoint::still)
  std::shared_ptr<const HeldKinematics> held_;  // null: Sea::at at every call
  std::vector<std::optional<MorisonCoefficients>> sections_;
  model::LengthMeasure measure_;
};

}  // namespace flexmoor::hydro

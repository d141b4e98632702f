#include "libstruct/model/assembler.hpp"

#include <algorithm>
#include <stdexcept>

namespace flexmoor::model {

namespace {

// Value slot in the compressed pattern of each (a, b) of a block of equations (-1 where a or b is
// constrained), column-major like the block.
std::vector<int> blockSlots(const SparseMatrix& pattern, const std::vector<int>& eq) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  const int m = static_cast<int>(eq.size());
  std::vector<int> slots(m * m, -1);
  for (int b = 0; b < m; ++b) {
    if (eq[b] < 0) continue;
    for (int a = 0; a < m; ++a) {
      if (eq[a] < 0) continue;
      const int* begin = inner + outer[eq[b]];
      const int* end = inner + outer[eq[b] + 1];
      slots[a + m * b] = static_cast<int>(std::lower_bound(begin, end, eq[a]) - inner);
    }
  }
  return slots;
}

}  // namespace

Assembler::Assembler(const Model& model) : model_(model) {
  const int n_eq = model.equationCount();
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n_eq; ++i) entries.emplace_back(i, i, 0.0);
  const auto add_block = [&](const std::vector<int>& eq) {
    for (int a : eq)
      for (int b : eq)
        if (a >= 0 && b >= 0) entries.emplace_back(a, b, 0.0);
  };
  const auto node_equations = [&](int n) {
    return std::vector<int>{model.equation(n, 0), model.equation(n, 1), model.equation(n, 2)};
  };
  full_index_.resize(model.elementCount());
  std::vector<std::vector<int>> equations(model.elementCount());
  for (int e = 0; e < model.elementCount(); ++e) {
    for (int n : model.element(e).nodes())
      for (int k = 0; k < 3; ++k) {
        full_index_[e].push_back(3 * n + k);
        equations[e].push_back(model.equation(n, k));
      }
    add_block(equations[e]);
  }
  for (const auto& load : model.nodeLoads()) add_block(node_equations(load->node()));
  pattern_.resize(n_eq, n_eq);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();
  double sizes = 0.0;
  int sized = 0;
  for (int e = 0; e < model.elementCount(); ++e) {
    const std::vector<int>& nodes = model.element(e).nodes();
    double largest = 0.0;
    for (size_t a = 0; a < nodes.size(); ++a)
      for (size_t b = a + 1; b < nodes.size(); ++b)
        largest = std::max(
            largest, (model.reference().col(nodes[a]) - model.reference().col(nodes[b])).norm());
    if (largest > 0.0) {
      sizes += largest;
      ++sized;
    }
  }
  if (sized > 0) element_size_ = sizes / sized;
  if (!model.gravity().isZero()) {
    Eigen::VectorXd weight = Eigen::VectorXd::Zero(3 * model.nodeCount());
    const std::vector<Eigen::MatrixXd> masses = elementMasses(element::MassKind::Lumped);
    for (int e = 0; e < model.elementCount(); ++e)
      for (size_t a = 0; a < full_index_[e].size(); ++a)
        weight(full_index_[e][a]) += masses[e](a, a) * model.gravity()(full_index_[e][a] % 3);
    weight_norm_ = weight.norm();
  }

  for (int e = 0; e < model.elementCount(); ++e)
    slot_.push_back(blockSlots(pattern_, equations[e]));
  for (const auto& load : model.nodeLoads())
    node_slot_.push_back(blockSlots(pattern_, node_equations(load->node())));
  for (int e = 0; e < model.elementCount(); ++e)
    if (model.element(e).hasDamping()) damped_.push_back(e);
  element_offset_.assign(1, 0);
  for (int e = 0; e < model.elementCount(); ++e)
    element_offset_.push_back(element_offset_.back() + model.element(e).dofCount());
}

template <class ElementMatrix>
void Assembler::scatterMatrix(const std::vector<int>& slots, const ElementMatrix& k,
                              SparseMatrix& K, double scale) const {
  double* values = K.valuePtr();
  const int m = static_cast<int>(k.rows());
  for (int b = 0; b < m; ++b)
    for (int a = 0; a < m; ++a) {
      const int s = slots[a + m * b];
      if (s >= 0) values[s] += scale * k(a, b);
    }
}

void Assembler::zeroOnPattern(SparseMatrix& m) const {
  // The column starts and the count of nonzeros identify the pattern among the matrices this
  // assembler fills (comparing the row indices too would cost as much as the copy it saves).
  const Eigen::Index n = pattern_.outerSize();
  const bool same =
      m.isCompressed() && m.rows() == pattern_.rows() && m.cols() == pattern_.cols() &&
      m.nonZeros() == pattern_.nonZeros() &&
      std::equal(pattern_.outerIndexPtr(), pattern_.outerIndexPtr() + n + 1, m.outerIndexPtr());
  if (same)
    m.coeffs().setZero();
  else
    m = pattern_;  // the pattern's values are zero
}

void Assembler::zeroLoadMatrices(LoadMatrices& J) const {
  zeroOnPattern(J.stiffness);
  if (J.summed) return;
  zeroOnPattern(J.damping);
  zeroOnPattern(J.mass);
}

void Assembler::scatterNodeMatrices(const std::vector<int>& slots, const PointForce& f,
                                    LoadMatrices& J, double scale) const {
  if (!J.summed) {
    scatterMatrix(slots, f.d_position, J.stiffness, scale);
    scatterMatrix(slots, f.d_velocity, J.damping, scale);
    scatterMatrix(slots, f.d_acceleration, J.mass, scale);
    return;
  }
  const LoadMatrices::Weights& w = *J.summed;
  const Eigen::Matrix3d sum =
      w.stiffness * f.d_position + w.damping * f.d_velocity + w.mass * f.d_acceleration;
  scatterMatrix(slots, sum, J.stiffness, scale);
}

void Assembler::scatterElementMatrices(const std::vector<int>& slots,
                                       const element::LoadMatrices& k, LoadMatrices& J,
                                       double scale) const {
  scatterMatrix(slots, k.stiffness, J.stiffness, scale);
  if (J.summed) return;
  scatterMatrix(slots, k.damping, J.damping, scale);
  scatterMatrix(slots, k.mass, J.mass, scale);
}

void Assembler::internalForce(const State& state, Eigen::VectorXd& force, SparseMatrix* K) const {
  ForceMemo& memo = internal_memo_;
  // F depends on the displacement alone: the self-corrective scheme's first evaluation of a step
  // is at the displacement its last one accepted, whose forces are still here.
  if (!K && sameDisplacement(memo, state)) {
    force = memo.assembled;
    return;
  }
  force.setZero(3 * model_.nodeCount());
  if (K) zeroOnPattern(*K);
  memo.elements.resize(model_.elementCount());
  Eigen::MatrixXd& k = element_tangent_;
  for (int e = 0; e < model_.elementCount(); ++e) {
    Eigen::VectorXd& f = memo.elements[e];
    model_.element(e).internalForce(context(state, e), f, K ? &k : nullptr);
    const auto& index = full_index_[e];
    for (size_t a = 0; a < index.size(); ++a) force(index[a]) += f(a);
    if (K) scatterMatrix(slot_[e], k, *K);
  }
  memo.valid = true;
  memo.state.displacement = state.displacement;
  memo.assembled = force;
}

bool Assembler::sameDisplacement(const ForceMemo& m, const State& s) {
  return m.valid && model::sameDisplacement(m.state, s);
}

bool Assembler::sameState(const ForceMemo& m, const State& s) {
  return m.valid && model::sameState(m.state, s);
}

void Assembler::elementLoad(const State& state, int e, Eigen::VectorXd& load,
                            LoadMatrices* J) const {
  load.setZero(model_.element(e).dofCount());
  Eigen::VectorXd& p = element_load_;
  if (J) element_jacobians_.summed = J->summed;
  if (!model_.gravity().isZero()) {
    if (gravity_loads_.empty() || gravity_of_loads_ != model_.gravity()) {
      gravity_of_loads_ = model_.gravity();
      gravity_loads_.resize(model_.elementCount());
      for (int i = 0; i < model_.elementCount(); ++i)
        model_.element(i).bodyLoad(context(state, i), model_.gravity(), gravity_loads_[i]);
    }
    load += gravity_loads_[e];
  }
  const double lambda = state.load_factor;
  if (model_.element(e).takesLineLoads())
    for (const auto& line : model_.lineLoads()) {
      const bool jacobians = J && line->stiff();
      if (!model_.element(e).lineLoad(context(state, e), *line, p,
                                      jacobians ? &element_jacobians_ : nullptr))
        continue;  // zero on this element
      load += p;
      if (jacobians) scatterElementMatrices(slot_[e], element_jacobians_, *J, lambda);
    }
  load *= lambda;
}

void Assembler::externalLoad(const State& state, Eigen::VectorXd& load, LoadMatrices* J) const {
  if (J) zeroLoadMatrices(*J);
  const double lambda = state.load_factor;
  load.setZero(3 * model_.nodeCount());
  for (const NodalLoad& p : model_.nodalLoads())
    if (!p.history) load.segment<3>(3 * p.node) += lambda * p.force;
  ForceMemo& memo = external_memo_;
  memo.per_element = !model_.gravity().isZero() || !model_.lineLoads().empty();
  if (memo.per_element) {
    memo.elements.resize(model_.elementCount());
    for (int e = 0; e < model_.elementCount(); ++e) {
      Eigen::VectorXd& p = memo.elements[e];
      elementLoad(state, e, p, J);
      const auto& index = full_index_[e];
      for (size_t a = 0; a < index.size(); ++a) load(index[a]) += p(a);
    }
  }
  Eigen::VectorXd p;
  for (const NodalLoad& p : model_.nodalLoads())
    if (p.history) load.segment<3>(3 * p.node) += p.history->value(state.time) * p.force;
  const auto& node_loads = model_.nodeLoads();
  for (size_t i = 0; i < node_loads.size(); ++i) {
    const bool jacobians = J && node_loads[i]->stiff();
    const PointForce f =
        node_loads[i]->evaluate(nodePoint(state, node_loads[i]->node()), jacobians);
    load.segment<3>(3 * node_loads[i]->node()) += lambda * f.force;
    if (jacobians) scatterNodeMatrices(node_slot_[i], f, *J, -lambda);
  }
  for (const PressureLoad& pressure : model_.pressures()) {
    const double value = pressureFactor(pressure, state);
    for (int e : pressure.elements) {
      model_.element(e).pressureLoad(context(state, e), value, p, nullptr);
      const auto& index = full_index_[e];
      for (size_t a = 0; a < index.size(); ++a) load(index[a]) += p(a);
    }
  }
  for (const SurfaceLoadOn& surface : model_.surfaceLoads()) {
    const bool jacobians = J && surface.load->stiff();
    if (J) element_jacobians_.summed = J->summed;
    for (int e : surface.elements) {
      model_.element(e).surfaceLoad(context(state, e), *surface.load, p,
                                    jacobians ? &element_jacobians_ : nullptr);
      const auto& index = full_index_[e];
      for (size_t a = 0; a < index.size(); ++a) load(index[a]) += lambda * p(a);
      // Stiffness alone (the pressure does not depend on the rates); summed: times its weight.
      if (jacobians) scatterMatrix(slot_[e], element_jacobians_.stiffness, J->stiffness, lambda);
    }
  }
  memo.valid = true;
  memo.state = state;
  memo.assembled = load;
}

LoadPoint Assembler::nodePoint(const State& state, int node) const {
  LoadPoint p;
  p.position = model_.reference().col(node) + state.displacement.col(node);
  p.velocity = state.velocity.col(node);
  p.acceleration = state.acceleration.col(node);
  p.time = state.time;
  p.still = state.still;
  p.node = node;
  return p;
}

void Assembler::loadMatrices(const State& state, LoadMatrices& J) const {
  Eigen::VectorXd load;
  externalLoad(state, load, &J);
}

void Assembler::dampingForce(const State& state, Eigen::VectorXd& force, LoadMatrices* J) const {
  force.setZero(3 * model_.nodeCount());
  if (J) zeroLoadMatrices(*J);
  Eigen::VectorXd& f = element_load_;
  element::LoadMatrices& k = element_jacobians_;
  if (J) k.summed = J->summed;
  for (int e : damped_) {
    model_.element(e).dampingForce(context(state, e), f, J ? &k : nullptr);
    const auto& index = full_index_[e];
    for (size_t a = 0; a < index.size(); ++a) force(index[a]) += f(a);
    if (J) scatterElementMatrices(slot_[e], k, *J, 1.0);
  }
}

double Assembler::pressureFactor(const PressureLoad& load, const State& state) const {
  return load.pressure * (load.history ? load.history->value(state.time) : state.load_factor);
}

void Assembler::subtractLoadStiffness(const State& state, SparseMatrix& K) const {
  Eigen::VectorXd p;
  Eigen::MatrixXd dp;
  for (const PressureLoad& pressure : model_.pressures()) {
    const double value = pressureFactor(pressure, state);
    for (int e : pressure.elements) {
      model_.element(e).pressureLoad(context(state, e), value, p, &dp);
      scatterMatrix(slot_[e], dp, K, -1.0);
    }
  }
}

std::vector<Eigen::MatrixXd> Assembler::elementMasses(element::MassKind kind) const {
  const State reference = model_.initialState();
  std::vector<Eigen::MatrixXd> masses(model_.elementCount());
  for (int e = 0; e < model_.elementCount(); ++e)
    model_.element(e).mass(context(reference, e), kind, masses[e]);
  return masses;
}

void Assembler::inertiaForce(const std::vector<Eigen::MatrixXd>& masses, const State& state,
                             Eigen::VectorXd& force) const {
  force.setZero(3 * model_.nodeCount());
  Eigen::VectorXd &a = element_acceleration_, &f = element_load_;
  for (int e = 0; e < model_.elementCount(); ++e) {
    const auto& index = full_index_[e];
    a.resize(index.size());
    for (size_t k = 0; k < index.size(); ++k) a(k) = state.acceleration.data()[index[k]];
    f.noalias() = masses[e] * a;
    for (size_t k = 0; k < index.size(); ++k) force(index[k]) += f(k);
  }
}

void Assembler::mass(const State& state, element::MassKind kind, SparseMatrix& M) const {
  zeroOnPattern(M);
  Eigen::MatrixXd m;
  for (int e = 0; e < model_.elementCount(); ++e) {
    model_.element(e).mass(context(state, e), kind, m);
    scatterMatrix(slot_[e], m, M);
  }
}

Eigen::VectorXd Assembler::restrictToFree(const Eigen::Ref<const Eigen::VectorXd>& full) const {
  Eigen::VectorXd r;
  restrictToFree(full, r);
  return r;
}

void Assembler::restrictToFree(const Eigen::Ref<const Eigen::VectorXd>& full,
                               Eigen::VectorXd& free) const {
  free.resize(model_.equationCount());
  for (int n = 0; n < model_.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (const int eq = model_.equation(n, k); eq >= 0) free(eq) = full(3 * n + k);
}

void Assembler::addFree(const Eigen::VectorXd& free_values, NodalField& field, double scale) const {
  for (int n = 0; n < model_.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (const int eq = model_.equation(n, k); eq >= 0) field(k, n) += scale * free_values(eq);
}

void Assembler::applyPrescribed(State& state) const {
  for (int n = 0; n < model_.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (model_.isConstrained(n, k)) {
        const double value = model_.prescribed(n, k);
        if (const TimeFunction* f = model_.motion(n, k)) {
          state.displacement(k, n) = value * f->value(state.time);
          state.velocity(k, n) = value * f->rate(state.time);
          state.acceleration(k, n) = value * f->acceleration(state.time);
        } else {
          state.displacement(k, n) = state.load_factor * value;
        }
      }
}

// A line element (cable or spring: two ends, axial forces, no membrane resultants) reports at
// each end the force its end node exerts on it, from its own nodal force balance: internal force
// f and its internal damping f_d, minus its consistent external load p (gravity, line loads), plus
// its inertia M u'' when the structure accelerates (Rayleigh damping, a property of the whole
// model, is left out). That is the force on the end point a mooring user reads (a fairlead's, an
// anchor's), and at a support that only this element joins it is the reaction. Its magnitude is
// the end tension; a force that pushes the end towards the element's next node is a compression
// and is reported negative. The axial force from the strain at xi = +-1 converges more slowly and
// can be far off when EA / T is large (a curved quadratic element cannot keep its stretch
// uniform); the integration points keep their strain-based tension.
void Assembler::setEndTensions(const State& state, int e, const ElementForces& forces,
                               element::ElementResult& r) const {
  const std::vector<int>& nodes = model_.element(e).nodes();
  const int last = static_cast<int>(nodes.size()) - 1;
  const auto at = [last](const double* v, int end) {
    return Eigen::Map<const Eigen::Vector3d>(v + 3 * (end == 0 ? 0 : last));
  };
  for (const int end : {0, 1}) {
    Eigen::Vector3d force = at(forces.internal, end);
    if (forces.load) force -= at(forces.load, end);
    if (forces.damping) force += at(forces.damping, end);
    if (forces.accelerating) {  // the end rows of M_e times u''_e, column by column
      const Eigen::Matrix<double, 6, Eigen::Dynamic>& rows = end_masses_[e];
      const auto& index = full_index_[e];
      for (size_t j = 0; j < index.size(); ++j)
        force += rows.col(static_cast<Eigen::Index>(j)).segment<3>(3 * end) *
                 state.acceleration.data()[index[j]];
    }
    const int local = end == 0 ? 0 : last;
    const int next = end == 0 ? 1 : last - 1;
    const Eigen::Vector3d along =
        model_.reference().col(nodes[next]) - model_.reference().col(nodes[local]) +
        state.displacement.col(nodes[next]) - state.displacement.col(nodes[local]);
    const double magnitude = force.norm();
    r.end_tension[end] = force.dot(along) > 0.0 ? -magnitude : magnitude;
  }
}

void Assembler::endMasses() const {
  const std::vector<Eigen::MatrixXd> masses = elementMasses(element::MassKind::Consistent);
  end_masses_.resize(masses.size());
  for (size_t e = 0; e < masses.size(); ++e) {
    const Eigen::Index n = masses[e].rows();
    if (n < 6) continue;  // not a line of two ends: never asked
    end_masses_[e].resize(6, n);
    end_masses_[e] << masses[e].topRows<3>(), masses[e].bottomRows<3>();
  }
}

void Assembler::elementResult(const State& state, int e, const ElementForces& forces,
                              element::ElementResult& r) const {
  model_.element(e).result(context(state, e), r);
  const bool line = model_.element(e).nodes().size() >= 2 && !r.point_tension.empty() &&
                    r.point_resultant.empty();
  if (line) setEndTensions(state, e, forces, r);
}

void Assembler::memoiseForces(const State& state) const {
  Eigen::VectorXd unused;
  if (!sameDisplacement(internal_memo_, state)) internalForce(state, unused, nullptr);
  if (!sameState(external_memo_, state)) externalLoad(state, unused);
}

bool Assembler::prepareInertia(const State& state) const {
  const bool accelerating = !state.acceleration.isZero(0.0);
  if (accelerating && end_masses_.empty()) endMasses();
  return accelerating;
}

void Assembler::resultInputs(const State& state, ResultInputs& in) const {
  memoiseForces(state);
  const auto flatten = [this](const std::vector<Eigen::VectorXd>& per_element,
                              Eigen::VectorXd& flat) {
    flat.resize(element_offset_.back());
    for (size_t e = 0; e < per_element.size(); ++e)
      flat.segment(element_offset_[e], per_element[e].size()) = per_element[e];
  };
  flatten(internal_memo_.elements, in.internal);
  if (external_memo_.per_element)
    flatten(external_memo_.elements, in.loads);
  else
    in.loads.resize(0);
  in.internal_assembled = internal_memo_.assembled;
  in.external_assembled = external_memo_.assembled;
  in.accelerating = prepareInertia(state);
}

Assembler::ElementForces Assembler::elementForces(const State& state, int e, const double* internal,
                                                  const double* load, bool accelerating,
                                                  Eigen::VectorXd& damping) const {
  ElementForces forces{internal, load, nullptr, accelerating};
  if (model_.element(e).hasDamping()) {
    model_.element(e).dampingForce(context(state, e), damping, nullptr);
    forces.damping = damping.data();
  }
  return forces;
}

void Assembler::elementResults(const State& state, const ResultInputs& in,
                               std::vector<element::ElementResult>& elements,
                               Eigen::VectorXd* viscous) const {
  elements.resize(model_.elementCount());
  Eigen::VectorXd damping;
  if (viscous && hasDamping()) viscous->setZero(3 * model_.nodeCount());
  for (int e = 0; e < model_.elementCount(); ++e) {
    const double* load = in.loads.size() ? in.loads.data() + element_offset_[e] : nullptr;
    const ElementForces forces = elementForces(state, e, in.internal.data() + element_offset_[e],
                                               load, in.accelerating, damping);
    if (viscous && forces.damping) {
      const auto& index = full_index_[e];
      for (size_t a = 0; a < index.size(); ++a) (*viscous)(index[a]) += damping(a);
    }
    elementResult(state, e, forces, elements[e]);
  }
}

void Assembler::results(const State& state, const ResultInputs& in,
                        std::vector<element::ElementResult>& elements,
                        NodalField& reactions) const {
  Eigen::VectorXd viscous;  // only for a model with internal damping
  elementResults(state, in, elements, &viscous);
  supportReactions(in.internal_assembled, in.external_assembled, viscous, reactions);
}

void Assembler::supportReactions(const Eigen::VectorXd& internal, const Eigen::VectorXd& external,
                                 const Eigen::VectorXd& viscous, NodalField& r) const {
  r.setZero(3, model_.nodeCount());
  for (int n = 0; n < model_.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (model_.isConstrained(n, k))
        r(k, n) =
            internal(3 * n + k) - external(3 * n + k) + (viscous.size() ? viscous(3 * n + k) : 0.0);
}

void Assembler::results(const State& state, std::vector<element::ElementResult>& elements,
                        NodalField& reactions) const {
  resultInputs(state, result_inputs_);
  results(state, result_inputs_, elements, reactions);
}

NodalField Assembler::reactions(const State& state) const {
  NodalField r;
  reactions(state, r);
  return r;
}

void Assembler::reactions(const State& state, NodalField& r) const {
  memoiseForces(state);
  Eigen::VectorXd viscous;  // only for a model with internal damping
  if (hasDamping()) dampingForce(state, viscous, nullptr);
  supportReactions(internal_memo_.assembled, external_memo_.assembled, viscous, r);
}

element::ElementResult Assembler::elementResult(const State& state, int e) const {
  memoiseForces(state);
  const double* load = external_memo_.per_element ? external_memo_.elements[e].data() : nullptr;
  Eigen::VectorXd damping;
  const ElementForces forces = elementForces(state, e, internal_memo_.elements[e].data(), load,
                                             prepareInertia(state), damping);
  element::ElementResult r;
  elementResult(state, e, forces, r);
  return r;
}

std::vector<element::ElementResult> Assembler::elementResults(const State& state) const {
  std::vector<element::ElementResult> results;
  elementResults(state, results);
  return results;
}

void Assembler::elementResults(const State& state,
                               std::vector<element::ElementResult>& results) const {
  resultInputs(state, result_inputs_);
  elementResults(state, result_inputs_, results, nullptr);  // no reactions asked
}

}  // namespace flexmoor::model

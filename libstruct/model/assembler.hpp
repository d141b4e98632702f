#pragma once
// Sparse assembly. The pattern of the free dofs is built once from the element connectivity, with
// a map from every element matrix entry to its slot in the compressed storage, so an update only
// scatters values. Full vectors are indexed 3 * node + component (the layout of NodalField).
#include <Eigen/Sparse>
#include <optional>
#include <vector>

#include "libstruct/model/model.hpp"

namespace flexmoor::model {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The negative derivatives of the motion-dependent loads (line, surface and node loads) on the
// free dofs, on the assembler's pattern: stiffness -dP/du, damping -dP/du', mass -dP/du''.
struct LoadMatrices {
  SparseMatrix stiffness, damping, mass;
  // When set, the three are not kept apart: every element's (and node's) three matrices go
  // into `stiffness` as one weighted sum, k K + c C + m M (what a time step's effective tangent
  // takes of them, Eq. 4.63), and `damping` and `mass` stay as they are. One sparse matrix to
  // zero and one scatter an element instead of three; the elements sum their own (at each
  // integration point, element::LoadMatrices::summed).
  using Weights = element::LoadMatrices::Weights;
  std::optional<Weights> summed;
};

// What a state's element results and reactions are computed from besides the state and the
// model: the forces of the Newton sweep that accepted it (or computed anew), taken by
// Assembler::resultInputs. Assembler::results(state, inputs, ...) reads nothing else that a run
// changes (no memo, no load with caches of its own: sea kinematics), so another thread may
// compute a record's results from a copy of its state and these while the run goes on.
struct ResultInputs {
  Eigen::VectorXd internal;  // every element's internal force, element after element
  Eigen::VectorXd loads;     // every element's own loads (gravity, line loads) so; empty if none
  Eigen::VectorXd internal_assembled, external_assembled;  // F and P, full vectors
  bool accelerating = false;                               // some u'' is not zero
};

class Assembler {
 public:
  explicit Assembler(const Model& model);

  const Model& model() const { return model_; }
  int equationCount() const { return model_.equationCount(); }
  // The model's mean element size: over its elements of two nodes or more, the mean of the
  // largest distance between two of an element's nodes in the reference configuration (1 when
  // there is none). The length a Newton increment is measured against (equilibrium.hpp).
  double elementSize() const { return element_size_; }
  // |W|, the norm of the model's weight at load factor 1 (the lumped masses times gravity): a
  // force in play even where the loads cancel at every node (a line resting on the seabed, whose
  // weight, buoyancy and bed reaction sum to nothing), so a residual is measured against it too.
  double weightNorm() const { return weight_norm_; }
  const SparseMatrix& pattern() const { return pattern_; }

  // Internal force F(u) as a full vector; with K, also the tangent on the free dofs (Eq. 4.48).
  // Without K at the displacement of the last evaluation, that evaluation's force (F depends on
  // u alone).
  void internalForce(const State& state, Eigen::VectorXd& force, SparseMatrix* K) const;
  // External load P at the state's load factor: nodal loads, gravity, line, surface and node
  // loads, follower pressures. With J, also the motion-dependent loads' matrices at the state,
  // from the same evaluation of each load (zero when the model has none; loads that are not
  // stiff() add nothing to them).
  void externalLoad(const State& state, Eigen::VectorXd& load, LoadMatrices* J = nullptr) const;
  // The motion-dependent loads' matrices alone (externalLoad's J).
  void loadMatrices(const State& state, LoadMatrices& J) const;
  // Whether an element has internal damping (a line's axial Kelvin-Voigt term, BA).
  bool hasDamping() const { return !damped_.empty(); }
  // The elements' viscous internal forces F_d(u, u') as a full vector (zero at rest, on the side
  // of F); with J, also J.stiffness = dF_d/du and J.damping = dF_d/du' on the free dofs (J.mass
  // zero), on the assembler's pattern: the matrices of the load -F_d.
  void dampingForce(const State& state, Eigen::VectorXd& force, LoadMatrices* J) const;
  // Subtracts the follower-pressure load stiffness dP/du from K (K - dP/du: non-symmetric).
  void subtractLoadStiffness(const State& state, SparseMatrix& K) const;
  // Element mass matrices (Eq. 4.40, 4.49), in element order. They depend on the reference
  // configuration only (total Lagrangian), so a time integration computes them once.
  std::vector<Eigen::MatrixXd> elementMasses(element::MassKind kind) const;
  // Inertia force M u'' over all dofs, prescribed supports' accelerations included, from the
  // element mass matrices of elementMasses().
  void inertiaForce(const std::vector<Eigen::MatrixXd>& masses, const State& state,
                    Eigen::VectorXd& force) const;
  // Mass matrix on the free dofs, in the same pattern as the tangent (Eq. 4.49).
  void mass(const State& state, element::MassKind kind, SparseMatrix& M) const;

  // Free-dof part of a full vector (into `free`, whose storage is reused), and the inverse
  // scatter into a nodal field.
  Eigen::VectorXd restrictToFree(const Eigen::Ref<const Eigen::VectorXd>& full) const;
  void restrictToFree(const Eigen::Ref<const Eigen::VectorXd>& full, Eigen::VectorXd& free) const;
  void addFree(const Eigen::VectorXd& free_values, NodalField& field, double scale = 1.0) const;
  // Sets the constrained dofs to their prescribed value times the load factor, or to their
  // history at the state's time (with its velocity and acceleration).
  void applyPrescribed(State& state) const;

  // Every element's result at the state. A line element's end tensions are the forces on its end
  // nodes from its nodal force balance (see setEndTensions); its point tensions stay the
  // element's own, from the strain.
  std::vector<element::ElementResult> elementResults(const State& state) const;
  // The same into `results`, whose storage is reused.
  void elementResults(const State& state, std::vector<element::ElementResult>& results) const;
  // Element e's result alone (0-based), as elementResults gives it: what a quantity of one
  // element needs in every time step.
  element::ElementResult elementResult(const State& state, int e) const;
  // Support reactions F + F_d - P at the constrained dofs (inertia not included), zero elsewhere.
  NodalField reactions(const State& state) const;
  // The same into `r`, whose storage is reused.
  void reactions(const State& state, NodalField& r) const;
  // elementResults and reactions of one state in one sweep, into storage that is reused: what a
  // result record needs.
  void results(const State& state, std::vector<element::ElementResult>& elements,
               NodalField& reactions) const;
  // The same in two halves: the inputs at the state (on the run's thread, where the memos are
  // that state's), then the results from them (on any thread, while the run goes on, as long as
  // this assembler lives and the model is not changed).
  void resultInputs(const State& state, ResultInputs& inputs) const;
  void results(const State& state, const ResultInputs& inputs,
               std::vector<element::ElementResult>& elements, NodalField& reactions) const;

 private:
  double element_size_ = 1.0;
  double weight_norm_ = 0.0;
  element::ElementContext context(const State& state, int e) const {
    return {model_.reference(), state, e};
  }
  template <class ElementMatrix>
  // Adds scale * k into K's slots (no temporary for the scaled matrix).
  void scatterMatrix(const std::vector<int>& slots, const ElementMatrix& k, SparseMatrix& K,
                     double scale = 1.0) const;
  LoadPoint nodePoint(const State& state, int node) const;

  double pressureFactor(const PressureLoad& load, const State& state) const;
  // Element e's own share of the proportional loads (gravity, line loads) at the load factor;
  // with J, its line loads' matrices are added into J.
  void elementLoad(const State& state, int e, Eigen::VectorXd& load,
                   LoadMatrices* J = nullptr) const;
  // Sets m to the pattern with zero values, without reallocating when m has it already.
  void zeroOnPattern(SparseMatrix& m) const;
  // zeroOnPattern of the matrices of J that it fills (J.summed: its stiffness alone).
  void zeroLoadMatrices(LoadMatrices& J) const;
  // Adds scale times a node's matrices into J: each into its own, or their weighted sum into
  // J.stiffness (J.summed).
  void scatterNodeMatrices(const std::vector<int>& slots, const PointForce& f, LoadMatrices& J,
                           double scale) const;
  // Adds scale times an element's matrices into J: each into its own, or the weighted sum the
  // element made (J.summed: element_jacobians_.summed set) into J.stiffness.
  void scatterElementMatrices(const std::vector<int>& slots, const element::LoadMatrices& k,
                              LoadMatrices& J, double scale) const;
  // One line element's forces for its end-force balance (its dofs' values, in element order):
  // internal force, own loads and internal damping (null: none).
  struct ElementForces {
    const double* internal = nullptr;
    const double* load = nullptr;
    const double* damping = nullptr;
    bool accelerating = false;
  };
  void setEndTensions(const State& state, int e, const ElementForces& forces,
                      element::ElementResult& r) const;
  void elementResult(const State& state, int e, const ElementForces& forces,
                     element::ElementResult& r) const;
  // Element e's forces from its internal force and own loads (null: none); its internal damping
  // force, when it has one, is computed into `damping`.
  ElementForces elementForces(const State& state, int e, const double* internal, const double* load,
                              bool accelerating, Eigen::VectorXd& damping) const;
  // Every element's result from the inputs; with `viscous`, the assembled internal damping
  // force too (left empty without internal damping), for the reactions.
  void elementResults(const State& state, const ResultInputs& inputs,
                      std::vector<element::ElementResult>& elements,
                      Eigen::VectorXd* viscous) const;
  // F + F_d - P at the constrained dofs (viscous empty: no internal damping), zero elsewhere.
  void supportReactions(const Eigen::VectorXd& internal, const Eigen::VectorXd& external,
                        const Eigen::VectorXd& viscous, NodalField& r) const;
  // Makes the memos below hold the state's internal force and external load.
  void memoiseForces(const State& state) const;
  // Whether the state accelerates; if so, the end masses exist from here on.
  bool prepareInertia(const State& state) const;

  // The last internal force and external load computed, assembled and per element, with the
  // state they belong to. A record of an accepted time step asks for the forces of the very
  // state the last Newton iteration evaluated: elementResults and reactions take them from here
  // instead of computing them again. A memo matches a state when the fields its forces depend on
  // are equal, exactly.
  struct ForceMemo {
    bool valid = false;
    State state;  // internal: its displacement alone
    Eigen::VectorXd assembled;
    std::vector<Eigen::VectorXd> elements;
    bool per_element = true;  // external: false when no element has a load of its own
  };
  static bool sameDisplacement(const ForceMemo& m, const State& s);
  static bool sameState(const ForceMemo& m, const State& s);

  const Model& model_;
  SparseMatrix pattern_;
  std::vector<std::vector<int>> full_index_;  // per element: full index of each local dof
  std::vector<std::vector<int>> slot_;        // per element: value slot of each (a, b), or -1
  std::vector<std::vector<int>> node_slot_;   // per node load: slot of each (a, b) of its node
  std::vector<int> damped_;                   // the elements with internal damping
  // The rows of the end nodes (first, last) of every consistent element mass, for the end-force
  // balance: computed on first use (total Lagrangian: they depend on the reference configuration
  // only).
  mutable std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic>> end_masses_;
  void endMasses() const;
  std::vector<Eigen::Index> element_offset_;  // element e's first dof in ResultInputs' vectors
  mutable ResultInputs result_inputs_;        // results()' inputs, reused
  mutable element::LoadMatrices element_jacobians_;  // one element's load matrices, reused
  mutable Eigen::VectorXd element_load_;             // one element's share of a load, reused
  mutable Eigen::MatrixXd element_tangent_;          // one element's tangent, reused
  // Every element's gravity load, computed on first use and again when the model's gravity
  // changes: it depends on the reference configuration alone (total Lagrangian), not on the
  // state.
  mutable std::vector<Eigen::VectorXd> gravity_loads_;
  mutable Eigen::Vector3d gravity_of_loads_ = Eigen::Vector3d::Zero();
  mutable Eigen::VectorXd element_acceleration_;  // inertiaForce's element vectors, reused
  mutable ForceMemo internal_memo_, external_memo_;
};

}  // namespace flexmoor::model

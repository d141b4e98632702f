#include "apps/output/support_reactions.hpp"

namespace flexmoor::app {

model::NodalField supportReactions(const model::Assembler& assembler, const model::State& state) {
  const model::Model& m = assembler.model();
  Eigen::VectorXd F, P;
  assembler.internalForce(state, F, nullptr);
  assembler.externalLoad(state, P);
  model::NodalField r = model::NodalField::Zero(3, m.nodeCount());
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (m.isConstrained(n, k)) r(k, n) = F(3 * n + k) - P(3 * n + k);
  return r;
}

}  // namespace flexmoor::app

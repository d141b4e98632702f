#include "libstruct/solve/diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace flexmoor::solve {

LargestMove largestMove(const model::Model& m, const Eigen::VectorXd& du) {
  LargestMove best;
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k) {
      const int eq = m.equation(n, k);
      if (eq < 0 || eq >= du.size()) continue;
      // a NaN increment is the one to name
      if (best.node < 0 || std::abs(du(eq)) > std::abs(best.value) || std::isnan(du(eq))) {
        best = {n, k, du(eq)};
        if (std::isnan(du(eq))) return best;
      }
    }
  return best;
}

std::string dofName(const SolveLog& log, int node, int component) {
  return log.nodeName(node) + " " + "xyz"[component];
}

void NewtonTrace::increment(const model::Model& m, const Eigen::VectorXd& du) {
  last_move_ = largestMove(m, du);
}

bool NewtonTrace::diverging() const {
  if (residuals_.size() < 3 || !std::isfinite(residuals_.back())) return false;
  const double least = *std::min_element(residuals_.begin(), residuals_.end());
  return residuals_.back() > 10.0 * least;
}

bool NewtonTrace::lost() const {
  if (residuals_.size() < 3 || !std::isfinite(residuals_.back())) return false;
  return diverging() || residuals_.back() > 0.1 * residuals_.front();
}

std::string NewtonTrace::diagnosis(const SolveLog& log) const {
  if (residuals_.empty()) return "";
  std::ostringstream s;
  const size_t iterations = residuals_.size() - 1;
  const double last = residuals_.back();
  if (!std::isfinite(last)) {
    s << "the residual became " << (std::isnan(last) ? "NaN" : "infinite") << " after "
      << iterations << " iterations: an element degenerated or turned inside out";
  } else if (diverging()) {
    s << "the iterations diverge (residual " << residuals_.front() << " at the start, " << last
      << " after " << iterations << " iterations)";
  } else if (iterations >= 3 && last > 0.1 * residuals_[iterations - 3]) {
    s << "the residual stalls near " << last << " (" << residuals_.front() << " at the start)";
  } else {
    s << "the iterations converge too slowly (residual " << residuals_.front() << " at the start, "
      << last << " after " << iterations << " iterations)";
  }
  if (last_move_.node >= 0)
    s << "; the largest displacement increment of the last iteration, " << last_move_.value
      << ", is at " << dofName(log, last_move_.node, last_move_.component);
  return s.str();
}

}  // namespace flexmoor::solve

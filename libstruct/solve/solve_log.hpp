#pragma once
// What the solvers tell the outside world while they work, and the error they raise when they
// cannot converge. The state handed back on failure is the last converged one.
#include <functional>
#include <stdexcept>
#include <string>

namespace flexmoor::solve {

struct IterationRecord {
  int increment = 0;  // increment (static) or pseudo-time step (relaxation), from 1
  int iteration = 0;  // Newton iteration within it, from 1
  double load_factor = 0.0;
  double displacement_norm = 0.0;  // Eq. 5.1: sqrt(sum du^2 / sum u^2)
  double residual_norm = 0.0;      // |R| / max(|P|, |F|)
};

// Receives one record per iteration and a line of text per finished increment. `node_name`
// names a model node (0-based) in failure messages as the user knows it (a case file's id);
// without it, "node K" with K the 1-based model index.
struct SolveLog {
  std::function<void(const IterationRecord&)> iteration;
  std::function<void(const std::string&)> message;
  std::function<std::string(int)> node_name;

  void report(const IterationRecord& r) const {
    if (iteration) iteration(r);
  }
  void say(const std::string& s) const {
    if (message) message(s);
  }
  std::string nodeName(int node) const {
    return node_name ? node_name(node) : "node " + std::to_string(node + 1);
  }
};

class ConvergenceError : public std::runtime_error {
 public:
  ConvergenceError(const std::string& what, IterationRecord last)
      : std::runtime_error(what), last_(last) {}
  const IterationRecord& last() const { return last_; }

 private:
  IterationRecord last_;
};

}  // namespace flexmoor::solve

#pragma once
// Nodes found by position within a tolerance, over a hash of cubic cells 4 tolerances wide: a
// query visits only the cells within a tolerance of the point (one to eight, on average 3.4),
// so that matching every node of a model against the others takes linear time.
#include <Eigen/Core>
#include <array>
#include <unordered_map>
#include <vector>

#include "libstruct/model/state.hpp"

namespace flexmoor::app {

class NodeIndex {
 public:
  explicit NodeIndex(double tolerance) : tolerance_(tolerance) {}
  // Every column of X, as node = its column.
  NodeIndex(const model::NodalField& X, double tolerance);

  void add(const Eigen::Vector3d& x, int node);
  // A node within the tolerance of x, or -1.
  int find(const Eigen::Vector3d& x) const;
  // Calls visit(node) for every node within the tolerance of x (in no particular order), until
  // visit returns false.
  template <class Visit>
  void visitNear(const Eigen::Vector3d& x, Visit visit) const;

 private:
  using Cell = std::array<long long, 3>;
  static size_t hash(const Cell& c) {
    return std::hash<long long>()(c[0]) ^ (std::hash<long long>()(c[1]) * 0x9E3779B97F4A7C15ULL) ^
           (std::hash<long long>()(c[2]) * 0xC2B2AE3D27D4EB4FULL);
  }
  double width() const { return 4.0 * tolerance_; }

  double tolerance_;
  // Cells by hash (cells that share a hash share a chain: harmless, positions are compared);
  // each holds the index of its last point, chained through next_.
  std::unordered_map<size_t, int> last_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<int> nodes_, next_;
};

template <class Visit>
void NodeIndex::visitNear(const Eigen::Vector3d& x, Visit visit) const {
  // The cell of x and, along each axis, its neighbour when x is within a tolerance of the face.
  std::array<std::array<long long, 2>, 3> range;
  for (int k = 0; k < 3; ++k) {
    const double u = x(k) / width();
    const long long c = std::llround(u);
    range[k] = {c - (u - c < -0.25 ? 1 : 0), c + (u - c >= 0.25 ? 1 : 0)};
  }
  for (long long i = range[0][0]; i <= range[0][1]; ++i)
    for (long long j = range[1][0]; j <= range[1][1]; ++j)
      for (long long k = range[2][0]; k <= range[2][1]; ++k) {
        const auto cell = last_.find(hash({i, j, k}));
        if (cell == last_.end()) continue;
        for (int p = cell->second; p >= 0; p = next_[p])
          if ((points_[p] - x).norm() <= tolerance_ && !visit(nodes_[p])) return;
      }
}

}  // namespace flexmoor::app

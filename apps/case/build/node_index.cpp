#include "apps/case/build/node_index.hpp"

#include <cmath>

namespace flexmoor::app {

NodeIndex::NodeIndex(const model::NodalField& X, double tolerance) : tolerance_(tolerance) {
  last_.reserve(X.cols());
  points_.reserve(X.cols());
  nodes_.reserve(X.cols());
  next_.reserve(X.cols());
  for (int node = 0; node < X.cols(); ++node) add(X.col(node), node);
}

void NodeIndex::add(const Eigen::Vector3d& x, int node) {
  const Cell c = {std::llround(x(0) / width()), std::llround(x(1) / width()),
                  std::llround(x(2) / width())};
  const auto [cell, added] = last_.emplace(hash(c), static_cast<int>(points_.size()));
  next_.push_back(added ? -1 : cell->second);
  if (!added) cell->second = static_cast<int>(points_.size());
  points_.push_back(x);
  nodes_.push_back(node);
}

int NodeIndex::find(const Eigen::Vector3d& x) const {
  int found = -1;
  visitNear(x, [&found](int node) {
    found = node;
    return false;
  });
  return found;
}

}  // namespace flexmoor::app

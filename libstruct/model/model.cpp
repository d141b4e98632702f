#include "libstruct/model/model.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace flexmoor::model {

int Model::addNode(const Eigen::Vector3d& reference_position) {
  const int n = nodeCount();
  reference_.conservativeResize(3, n + 1);
  reference_.col(n) = reference_position;
  constrained_.conservativeResize(3, n + 1);
  constrained_.col(n).setConstant(false);
  prescribed_.conservativeResize(3, n + 1);
  prescribed_.col(n).setZero();
  motion_.resize(3 * (n + 1));
  return n;
}

int Model::addNodes(const NodalField& X) {
  const int n = nodeCount(), count = static_cast<int>(X.cols());
  reference_.conservativeResize(3, n + count);
  reference_.rightCols(count) = X;
  constrained_.conservativeResize(3, n + count);
  constrained_.rightCols(count).setConstant(false);
  prescribed_.conservativeResize(3, n + count);
  prescribed_.rightCols(count).setZero();
  motion_.resize(3 * (n + count));
  return n;
}

int Model::addElement(std::unique_ptr<element::Element> element) {
  for (int n : element->nodes())
    if (n < 0 || n >= nodeCount())
      throw std::out_of_range("element refers to node " + std::to_string(n) + " of " +
                              std::to_string(nodeCount()));
  elements_.push_back(std::move(element));
  return elementCount() - 1;
}

void Model::constrain(int node, int component, double value,
                      std::shared_ptr<const TimeFunction> history) {
  constrained_(component, node) = true;
  prescribed_(component, node) = value;
  motion_[3 * node + component] = std::move(history);
}

void Model::addNodalLoad(int node, const Eigen::Vector3d& force,
                         std::shared_ptr<const TimeFunction> history) {
  nodal_loads_.push_back({node, force, std::move(history)});
}

void Model::addNodeLoad(std::shared_ptr<const NodeLoad> load) {
  if (load->node() < 0 || load->node() >= nodeCount())
    throw std::out_of_range("node load at node " + std::to_string(load->node()) + " of " +
                            std::to_string(nodeCount()));
  node_loads_.push_back(std::move(load));
}

void Model::addSurfaceLoad(std::shared_ptr<const SurfaceLoad> load, std::vector<int> elements) {
  for (int e : elements)
    if (e < 0 || e >= elementCount())
      throw std::out_of_range("surface load on element " + std::to_string(e) + " of " +
                              std::to_string(elementCount()));
  surface_loads_.push_back({std::move(load), std::move(elements)});
}

Model::Constraint Model::release(int node, int component) {
  Constraint held{prescribed_(component, node), motion_[3 * node + component]};
  constrained_(component, node) = false;
  prescribed_(component, node) = 0.0;
  motion_[3 * node + component] = nullptr;
  numberEquations();
  return held;
}

void Model::setStartDisplacement(int node, const Eigen::Vector3d& displacement) {
  if (node < 0 || node >= nodeCount())
    throw std::out_of_range("start displacement at node " + std::to_string(node) + " of " +
                            std::to_string(nodeCount()));
  if (start_displacement_.cols() != nodeCount()) {
    const NodalField given = start_displacement_;
    start_displacement_ = NodalField::Zero(3, nodeCount());
    start_displacement_.leftCols(given.cols()) = given;
  }
  start_displacement_.col(node) = displacement;
}

State Model::startState() const {
  State s(nodeCount());
  s.load_factor = start_load_factor_;
  s.displacement.leftCols(start_displacement_.cols()) = start_displacement_;
  return s;
}

void Model::numberEquations() {
  equation_.resize(3, nodeCount());
  equation_count_ = 0;
  for (int n = 0; n < nodeCount(); ++n)
    for (int k = 0; k < 3; ++k) equation_(k, n) = constrained_(k, n) ? -1 : equation_count_++;
}

bool Model::hasContactLoads() const {
  return std::any_of(line_loads_.begin(), line_loads_.end(),
                     [](const auto& load) { return load->contact(); }) ||
         std::any_of(node_loads_.begin(), node_loads_.end(),
                     [](const auto& load) { return load->contact(); });
}

}  // namespace flexmoor::model

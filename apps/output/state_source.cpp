#include "apps/output/state_source.hpp"

namespace flexmoor::app {

const model::NodalField& StateSource::reactions() const {
  if (!reactions_) reactions_ = assembler_.reactions(state_);
  return *reactions_;
}

const element::ElementResult& StateSource::element(int e) const {
  if (all_) return all_->at(e);
  auto it = one_.find(e);
  if (it == one_.end()) it = one_.emplace(e, assembler_.elementResult(state_, e)).first;
  return it->second;
}

const std::vector<element::ElementResult>& StateSource::elements() const {
  if (!all_) all_ = assembler_.elementResults(state_);
  return *all_;
}

}  // namespace flexmoor::app

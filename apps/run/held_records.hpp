#pragma once
// The records of a run held back from its sinks while a checkpoint that may take them back is
// alive (Simulation::save): a restore drops those after its time, the others go on to the sinks
// once no checkpoint before them is left. Each record is kept whole (its state copied, its
// results computed).
#include <deque>
#include <utility>

#include "apps/output/result_frame.hpp"

namespace flexmoor::app {

class HeldRecords {
 public:
  bool empty() const { return records_.empty(); }
  void hold(const ResultFrame& frame) {
    records_.emplace_back(*frame.state, frame);
    records_.back().second.state = &records_.back().first;  // a deque keeps its elements in place
  }
  // Drops the time records after `t` (a restore to t).
  void dropAfter(double t) {
    while (!records_.empty() && !records_.back().second.stage && records_.back().first.time > t)
      records_.pop_back();
  }
  // Hands the records up to time `t` (all of them for +infinity), in order, to `write`.
  template <class Write>
  void release(double t, Write&& write) {
    while (!records_.empty() && records_.front().first.time <= t) {
      write(records_.front().second);
      records_.pop_front();
    }
  }

 private:
  std::deque<std::pair<model::State, ResultFrame>> records_;
};

}  // namespace flexmoor::app

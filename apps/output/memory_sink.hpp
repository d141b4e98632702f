#pragma once
// A result sink that keeps every record in memory (states copied), for a caller that reads a
// run's records without a file.
#include <deque>
#include <vector>

#include "apps/output/result_sink.hpp"

namespace flexmoor::app {

class MemorySink final : public ResultSink {
 public:
  void write(const ResultFrame& frame) override {
    states_.push_back(*frame.state);
    frames_.push_back(frame);
    frames_.back().state = &states_.back();  // a deque keeps its elements in place
  }
  const std::vector<ResultFrame>& frames() const { return frames_; }

 private:
  std::deque<model::State> states_;
  std::vector<ResultFrame> frames_;
};

}  // namespace flexmoor::app

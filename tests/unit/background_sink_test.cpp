// BackgroundSink (apps/output/background_sink.hpp): the frames it is given reach the sink it
// wraps whole, in order and one call at a time on a thread other than the caller's, whether
// copied (write) or swapped (take); a failure of that sink comes back to the caller; frames still
// waiting are written when it is destroyed, and a frame given and then left reaches the sink
// without a flush. Reference: the frames as given; tolerance 0 (copies of the same values).
#include "apps/output/background_sink.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "apps/output/memory_sink.hpp"

namespace flexmoor::app {
namespace {

// The frame of record k: every value tells k apart (nodal fields, reactions, element results).
ResultFrame frameOf(int k, model::State& state) {
  state = model::State(3);
  state.time = 0.01 * k;
  state.displacement.setConstant(k);
  state.velocity.setConstant(2.0 * k);
  state.acceleration.setConstant(3.0 * k);
  ResultFrame f;
  f.step_index = k % 3;
  f.step_name = "step " + std::to_string(k);
  f.state = &state;
  f.reactions = model::NodalField::Constant(3, 3, -k);
  f.elements.resize(2);
  for (element::ElementResult& r : f.elements) {
    r.point_tension = {1.0 * k, 1.5 * k};
    r.end_tension[0] = 0.5 * k;
    r.end_tension[1] = 0.25 * k;
  }
  return f;
}

void expectFrameOf(int k, const ResultFrame& f) {
  ASSERT_NE(f.state, nullptr) << k;
  EXPECT_EQ(f.step_index, k % 3);
  EXPECT_EQ(f.step_name, "step " + std::to_string(k));
  EXPECT_EQ(f.state->time, 0.01 * k);
  EXPECT_TRUE((f.state->displacement.array() == k).all()) << k;
  EXPECT_TRUE((f.state->velocity.array() == 2.0 * k).all()) << k;
  EXPECT_TRUE((f.state->acceleration.array() == 3.0 * k).all()) << k;
  EXPECT_TRUE((f.reactions.array() == -k).all()) << k;
  ASSERT_EQ(f.elements.size(), 2u) << k;
  for (const element::ElementResult& r : f.elements) {
    EXPECT_EQ(r.point_tension, (std::vector<double>{1.0 * k, 1.5 * k})) << k;
    EXPECT_EQ(r.end_tension[0], 0.5 * k);
    EXPECT_EQ(r.end_tension[1], 0.25 * k);
  }
}

// A MemorySink that notes the threads calling it and fails if two calls overlap.
class WatchedSink final : public ResultSink {
 public:
  void write(const ResultFrame& frame) override {
    enter();
    memory.write(frame);
    ++written;
    if (fail_at >= 0 && static_cast<int>(memory.frames().size()) == fail_at + 1)
      failure("cannot write record " + std::to_string(fail_at));
    leave();
  }
  void flush() override {
    enter();
    ++flushes;
    leave();
  }
  MemorySink memory;
  std::atomic<size_t> written{0};  // what another thread may read while the writing goes on
  int fail_at = -1;
  int flushes = 0;
  std::vector<std::thread::id> threads;
  bool overlapped = false;

 private:
  void enter() {
    if (busy_.exchange(true)) overlapped = true;
    threads.push_back(std::this_thread::get_id());
  }
  void leave() { busy_ = false; }
  [[noreturn]] void failure(const std::string& what) {
    leave();
    throw std::runtime_error(what);
  }
  std::atomic<bool> busy_{false};
};

TEST(BackgroundSink, FramesReachTheSinkWholeInOrderOnAnotherThread) {
  WatchedSink inner;
  constexpr int kFrames = 10000;  // more than the ring holds: it wraps around and waits
  {
    BackgroundSink sink(inner);
    model::State state;
    ResultFrame reused;
    for (int k = 0; k < kFrames; ++k) {
      if (k % 2 == 0) {
        sink.write(frameOf(k, state));
      } else {  // a reused frame, as a dynamic step streams: swapped into the ring
        const ResultFrame f = frameOf(k, state);
        reused.step_index = f.step_index;
        reused.step_name = f.step_name;
        reused.state = f.state;
        reused.reactions = f.reactions;
        reused.elements = f.elements;
        sink.take(reused);
      }
    }
    sink.flush();
    EXPECT_EQ(inner.flushes, 1);
    ASSERT_EQ(inner.memory.frames().size(), static_cast<size_t>(kFrames));
  }
  for (int k = 0; k < kFrames; ++k) expectFrameOf(k, inner.memory.frames()[k]);
  EXPECT_FALSE(inner.overlapped);
  for (const std::thread::id id : inner.threads) EXPECT_NE(id, std::this_thread::get_id());
}

TEST(BackgroundSink, AFailureOfTheSinkReachesTheCallerAndStopsTheWriting) {
  WatchedSink inner;
  inner.fail_at = 5;
  BackgroundSink sink(inner);
  model::State state;
  bool thrown = false;
  try {
    for (int k = 0; k < 100; ++k) sink.write(frameOf(k, state));
    sink.flush();
  } catch (const std::runtime_error& e) {
    thrown = true;
    EXPECT_STREQ(e.what(), "cannot write record 5");
  }
  EXPECT_TRUE(thrown);
  EXPECT_EQ(inner.memory.frames().size(), 6u);  // records 0 to 5; none after the failed one
  EXPECT_EQ(inner.flushes, 0);
  EXPECT_THROW(sink.write(frameOf(100, state)), std::runtime_error);  // and every later call
  EXPECT_THROW(sink.flush(), std::runtime_error);
}

TEST(BackgroundSink, WhatIsWaitingIsWrittenWhenTheSinkIsDestroyed) {
  WatchedSink inner;
  {
    BackgroundSink sink(inner);
    model::State state;
    for (int k = 0; k < 10; ++k) sink.write(frameOf(k, state));
  }
  ASSERT_EQ(inner.memory.frames().size(), 10u);
  for (int k = 0; k < 10; ++k) expectFrameOf(k, inner.memory.frames()[k]);
}

// A run whose records come slowly: each reaches the sink within the writer's wake-up interval,
// without a flush (the test allows 50 times that before it calls it lost).
TEST(BackgroundSink, AFrameLeftAloneReachesTheSinkWithoutAFlush) {
  WatchedSink inner;
  BackgroundSink sink(inner);
  model::State state;
  sink.write(frameOf(0, state));
  const auto limit = 50 * BackgroundSink::kWakeInterval;
  const auto start = std::chrono::steady_clock::now();
  while (inner.written < 1 && std::chrono::steady_clock::now() - start < limit)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(inner.written, 1u);
  EXPECT_EQ(inner.flushes, 0);
}

}  // namespace
}  // namespace flexmoor::app

#pragma once
// A sink that passes every record to another sink on a thread of its own, so that the run goes
// on while the records are gathered, handed to HDF5 and copied by the kernel into the page
// cache, and while the element results and reactions of each record are computed from the
// inputs the run's thread took (ResultFrame::pending): on a machine with a free core, writing
// every step of a small model costs the run's thread little more than handing each frame over
// (docs/performance.md, "Output cost").
//
// The frames wait in a ring (at most kRingBytes of them, at least two). The run's thread fills a
// free frame and publishes it with one atomic store; the writing thread looks for published
// frames by itself, kFirstPoll after it last found some and twice as late each time it found
// none, up to kWakeInterval, and writes them. The run's thread wakes it only when three quarters
// of the ring wait, when the ring is full and on a flush: a wake-up costs the waking thread
// 10-30 us on a virtual machine, more than a small model's time step. So a record reaches the
// sink (and, at the sink's own flush interval, the disk) within kWakeInterval at most, within
// about kFirstPoll while records keep coming, and the writing overlaps the run. write() blocks
// only while the ring is full. Every call on the sink is made from the writing thread, one
// at a time: a sink that is not thread-safe (netCDF, HDF5) may be wrapped as it is.
//
// An exception of the sink's write or flush stops the writing: the frames after it are dropped
// and every later write() or flush() of this sink throws it, in the run's thread. flush() returns
// once every frame given so far is written and the sink flushed. The destructor writes what is
// still waiting (a run that fails for another reason keeps its records) and joins the thread.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "apps/output/result_frame.hpp"
#include "apps/output/result_sink.hpp"

namespace flexmoor::app {

class BackgroundSink final : public ResultSink {
 public:
  static constexpr size_t kRingBytes = 8u << 20;
  static constexpr size_t kMaxFrames = 1024;
  static constexpr std::chrono::milliseconds kFirstPoll{1};
  static constexpr std::chrono::milliseconds kWakeInterval{100};

  explicit BackgroundSink(ResultSink& sink);
  ~BackgroundSink() override;
  BackgroundSink(const BackgroundSink&) = delete;
  BackgroundSink& operator=(const BackgroundSink&) = delete;

  void write(const ResultFrame& frame) override;
  // Swaps the frame's element results, reactions and result inputs with those of the ring's free
  // frame.
  void take(ResultFrame& frame) override;
  void flush() override;
  bool needsResults() const override { return needs_results_; }
  // Pending results are computed on the writing thread, just before the frame is written.
  bool completesResults() const override { return true; }

 private:
  struct Held {
    model::State state;
    ResultFrame frame;  // frame.state points to `state`
  };
  void work();
  // Writes the published frames not yet written; false once the sink has failed.
  bool writePublished();
  // Sizes the ring for frames like `frame` (the first one).
  void allocate(const ResultFrame& frame);
  // The ring's next free frame, once there is one, with frame's state and labels copied into it
  // (write and take add the rest).
  Held& next(const ResultFrame& frame);
  // Publishes the frame next() gave, filled.
  void publish();
  void wakeWriter();
  // Throws the sink's exception, if it threw one.
  void rethrowError();

  ResultSink& sink_;
  const bool needs_results_;
  std::vector<Held> ring_;  // sized by the first frame, before any is published
  // Frames published and frames written since the start (frame n is ring_[n % size]): the run's
  // thread alone stores published_, the writing thread alone written_.
  std::atomic<size_t> published_{0}, written_{0};
  std::atomic<bool> failed_{false}, writer_asleep_{false};
  // Under the lock.
  bool flush_asked_ = false, flushed_ = false, stop_ = false;
  std::exception_ptr error_;
  std::mutex mutex_;
  std::condition_variable work_, done_;
  std::thread thread_;
};

}  // namespace flexmoor::app

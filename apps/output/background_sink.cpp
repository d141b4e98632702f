#include "apps/output/background_sink.hpp"

#include <algorithm>
#include <utility>

namespace flexmoor::app {

BackgroundSink::BackgroundSink(ResultSink& sink)
    : sink_(sink), needs_results_(sink.needsResults()), thread_([this] { work(); }) {}

BackgroundSink::~BackgroundSink() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  work_.notify_one();
  thread_.join();
}

void BackgroundSink::rethrowError() {
  if (!failed_.load(std::memory_order_acquire)) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  std::rethrow_exception(error_);
}

// A frame's values in bytes, roughly: the ring holds what kRingBytes allow of them.
void BackgroundSink::allocate(const ResultFrame& frame) {
  size_t values = 4 * static_cast<size_t>(frame.state->displacement.size());  // u, u', u'', R
  for (const element::ElementResult& r : frame.elements)
    values += 2 + r.point_tension.size() + 9 * r.point_resultant.size();
  const size_t bytes = sizeof(double) * std::max<size_t>(values, 1);
  ring_.resize(std::clamp<size_t>(kRingBytes / bytes, 2, kMaxFrames));
}

void BackgroundSink::wakeWriter() {
  { const std::lock_guard<std::mutex> lock(mutex_); }  // the writer is waiting or sees the news
  work_.notify_one();
}

BackgroundSink::Held& BackgroundSink::next(const ResultFrame& frame) {
  rethrowError();
  if (ring_.empty()) allocate(frame);  // nothing published yet: the writer reads no frame
  const size_t n = published_.load(std::memory_order_relaxed);
  while (n - written_.load(std::memory_order_acquire) == ring_.size()) {  // full
    std::unique_lock<std::mutex> lock(mutex_);
    work_.notify_one();
    done_.wait_for(lock, std::chrono::milliseconds(1));
    lock.unlock();
    rethrowError();
  }
  Held& held = ring_[n % ring_.size()];
  held.state = *frame.state;
  held.frame.state = &held.state;
  held.frame.step_index = frame.step_index;
  held.frame.step_name = frame.step_name;
  held.frame.stage = frame.stage;
  held.frame.frequencies = frame.frequencies;
  held.frame.mode_shapes = frame.mode_shapes;
  held.frame.pending = frame.pending;
  return held;
}

void BackgroundSink::publish() {
  const size_t n = published_.load(std::memory_order_relaxed) + 1;
  published_.store(n, std::memory_order_release);
  if (writer_asleep_.load(std::memory_order_relaxed) &&
      4 * (n - written_.load(std::memory_order_relaxed)) >= 3 * ring_.size())
    wakeWriter();
}

void BackgroundSink::write(const ResultFrame& frame) {
  Held& held = next(frame);
  held.frame.elements = frame.elements;
  held.frame.reactions = frame.reactions;
  held.frame.inputs = frame.inputs;
  publish();
}

void BackgroundSink::take(ResultFrame& frame) {
  Held& held = next(frame);
  held.frame.elements.swap(frame.elements);
  held.frame.reactions.swap(frame.reactions);
  std::swap(held.frame.inputs, frame.inputs);
  publish();
}

void BackgroundSink::flush() {
  rethrowError();
  {
    std::unique_lock<std::mutex> lock(mutex_);
    flush_asked_ = true;
    flushed_ = false;
    work_.notify_one();
    done_.wait(lock, [this] { return flushed_; });
  }
  rethrowError();
}

bool BackgroundSink::writePublished() {
  const size_t published = published_.load(std::memory_order_acquire);
  size_t n = written_.load(std::memory_order_relaxed);
  try {
    for (; n < published; ++n) {
      ResultFrame& frame = ring_[n % ring_.size()].frame;
      completeResults(frame);
      sink_.write(frame);
    }
    written_.store(n, std::memory_order_release);
    return true;
  } catch (...) {
    const std::lock_guard<std::mutex> lock(mutex_);
    error_ = std::current_exception();
    failed_.store(true, std::memory_order_release);
    written_.store(published, std::memory_order_release);  // the frames after it are dropped
    return false;
  }
}

// The writing thread: sleeps until it is woken or its poll interval has passed, then writes what
// is published, then flushes when asked; ends when the sink is destroyed, after the last frames.
void BackgroundSink::work() {
  bool working = true;  // the sink has not failed
  auto sleep = kFirstPoll;
  for (;;) {
    bool flush = false, stop = false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (!flush_asked_ && !stop_) {
        writer_asleep_.store(true, std::memory_order_relaxed);
        work_.wait_for(lock, sleep);
        writer_asleep_.store(false, std::memory_order_relaxed);
      }
      flush = flush_asked_;
      stop = stop_;
    }
    // Frames found: look again soon; none: twice as late, up to kWakeInterval.
    const bool found =
        published_.load(std::memory_order_acquire) != written_.load(std::memory_order_relaxed);
    sleep = found ? kFirstPoll : std::min<std::chrono::milliseconds>(2 * sleep, kWakeInterval);
    if (working) working = writePublished();
    done_.notify_one();
    if (flush) {
      std::exception_ptr error;
      if (working) {
        try {
          sink_.flush();
        } catch (...) {
          error = std::current_exception();
        }
      }
      const std::lock_guard<std::mutex> lock(mutex_);
      if (error) {
        error_ = error;
        failed_.store(true, std::memory_order_release);
        working = false;
      }
      flush_asked_ = false;
      flushed_ = true;
      done_.notify_one();
    }
    if (stop) return;
  }
}

}  // namespace flexmoor::app

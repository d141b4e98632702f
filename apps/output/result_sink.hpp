#pragma once
// Where a run's records go (simulation.hpp): the netCDF writer, an in-memory collector, later a
// host code's callback.
#include "apps/output/result_frame.hpp"

namespace flexmoor::app {

class ResultSink {
 public:
  virtual ~ResultSink() = default;
  // One record; `frame.state` is valid during the call only.
  virtual void write(const ResultFrame& frame) = 0;
  // The same record from a caller that fills `frame` anew for the next one: the sink may keep
  // its element results and reactions and leave in their place those of an earlier record
  // (storage of the same shape to fill, without allocating), instead of copying them.
  virtual void take(ResultFrame& frame) { write(frame); }
  // At the end of every step and of the run: whatever the sink buffers is made to last.
  virtual void flush() {}
  // Whether the frames written must carry element results and reactions (an assembly sweep per
  // record); a streamed record skips them when no sink does.
  virtual bool needsResults() const { return true; }
  // Whether the sink takes frames whose results are pending (ResultFrame::pending) and completes
  // them itself (completeResults), so that the run's thread need not compute them.
  virtual bool completesResults() const { return false; }
};

}  // namespace flexmoor::app

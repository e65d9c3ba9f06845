// Per-pass GPU times from timestamp queries, read back frames later without waiting: a small
// ring of query sets, one per frame in flight. render() only ever asks whether a set is ready;
// Chain::wait_for_timings is the one place that waits.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "pfx/host/timing.hpp"

namespace pfx::host {

class GpuTimer {
 public:
  // Frames whose queries may be in flight at once. A GPU further behind than this loses the
  // oldest frame's times (the report says which frame its times belong to).
  static constexpr size_t kFramesInFlight = 4;

  GpuTimer() = default;
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // Timestamps the start of frame `frame`'s passes.
  void begin_frame(uint64_t frame);
  // Timestamps the end of the pass just run; names it for the report.
  void end_pass(const std::string& effect, const std::string& pass);
  // The frame's passes are all stamped: it joins the frames in flight.
  void end_frame();
  // The frame begun last failed part way: its queries are dropped.
  void abandon_frame();

  // The newest frame in flight before `before_frame` whose queries have all landed, without
  // waiting (GL_QUERY_RESULT_AVAILABLE, then GL_QUERY_RESULT_NO_WAIT). Frees it and every older
  // set. False when none is complete.
  bool poll(uint64_t before_frame, FrameTimes* times);
  // Waits for the newest frame in flight and reads it (GL_QUERY_RESULT); drops every set. False
  // when no frame is in flight.
  bool wait_newest(FrameTimes* times);
  // Drops every set in flight (a change of timing scheme).
  void clear();

 private:
  struct QuerySet {
    uint64_t frame = 0;
    bool in_flight = false;
    std::vector<GLuint> queries;  // start, then one per pass end
    std::vector<PassTime> passes;
    size_t stamped = 0;
  };
  QuerySet& open_set();
  void stamp(QuerySet& set);
  static void read(const QuerySet& set, GLenum pname, FrameTimes* times);

  QuerySet sets_[kFramesInFlight];
  QuerySet* current_ = nullptr;
};

}  // namespace pfx::host

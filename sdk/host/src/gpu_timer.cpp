#include "gpu_timer.hpp"

namespace pfx::host {

GpuTimer::~GpuTimer() {
  for (QuerySet& set : sets_)
    if (!set.queries.empty()) glDeleteQueries(static_cast<GLsizei>(set.queries.size()), set.queries.data());
}

GpuTimer::QuerySet& GpuTimer::open_set() {
  QuerySet* chosen = nullptr;
  for (QuerySet& set : sets_)
    if (!set.in_flight) {
      chosen = &set;
      break;
    }
  if (!chosen) {
    // Every set still in flight: the oldest frame's times are given up.
    chosen = &sets_[0];
    for (QuerySet& set : sets_)
      if (set.frame < chosen->frame) chosen = &set;
  }
  chosen->in_flight = false;
  chosen->passes.clear();
  chosen->stamped = 0;
  return *chosen;
}

void GpuTimer::stamp(QuerySet& set) {
  if (set.stamped == set.queries.size()) {
    GLuint query = 0;
    glGenQueries(1, &query);
    set.queries.push_back(query);
  }
  glQueryCounter(set.queries[set.stamped++], GL_TIMESTAMP);
}

void GpuTimer::begin_frame(uint64_t frame) {
  current_ = &open_set();
  current_->frame = frame;
  stamp(*current_);
}

void GpuTimer::end_pass(const std::string& effect, const std::string& pass) {
  if (!current_) return;
  stamp(*current_);
  current_->passes.push_back({effect, pass, 0.0});
}

void GpuTimer::end_frame() {
  if (current_) current_->in_flight = true;
  current_ = nullptr;
}

void GpuTimer::abandon_frame() {
  if (current_) current_->in_flight = false;
  current_ = nullptr;
}

void GpuTimer::read(const QuerySet& set, GLenum pname, FrameTimes* times) {
  std::vector<GLuint64> stamps(set.stamped, 0);
  for (size_t i = 0; i < set.stamped; ++i) glGetQueryObjectui64v(set.queries[i], pname, &stamps[i]);
  times->frame = set.frame;
  times->passes = set.passes;
  times->total_ms = 0;
  for (size_t i = 0; i < times->passes.size(); ++i) {
    times->passes[i].ms = double(stamps[i + 1] - stamps[i]) * 1e-6;
    times->total_ms += times->passes[i].ms;
  }
}

bool GpuTimer::poll(uint64_t before_frame, FrameTimes* times) {
  // Oldest first: the GPU finishes frames in order, so the first incomplete one ends the search.
  bool found = false;
  for (;;) {
    QuerySet* oldest = nullptr;
    for (QuerySet& set : sets_)
      if (set.in_flight && set.frame < before_frame && (!oldest || set.frame < oldest->frame)) oldest = &set;
    if (!oldest) break;
    bool complete = true;
    for (size_t i = 0; i < oldest->stamped && complete; ++i) {
      GLuint available = GL_FALSE;
      glGetQueryObjectuiv(oldest->queries[i], GL_QUERY_RESULT_AVAILABLE, &available);
      complete = available == GL_TRUE;
    }
    if (!complete) break;
    read(*oldest, GL_QUERY_RESULT_NO_WAIT, times);
    oldest->in_flight = false;
    found = true;
  }
  return found;
}

bool GpuTimer::wait_newest(FrameTimes* times) {
  QuerySet* newest = nullptr;
  for (QuerySet& set : sets_)
    if (set.in_flight && (!newest || set.frame > newest->frame)) newest = &set;
  if (!newest) return false;
  read(*newest, GL_QUERY_RESULT, times);
  clear();
  return true;
}

void GpuTimer::clear() {
  for (QuerySet& set : sets_) set.in_flight = false;
  current_ = nullptr;
}

}  // namespace pfx::host

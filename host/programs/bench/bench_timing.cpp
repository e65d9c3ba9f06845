#include "bench_timing.hpp"

#include <algorithm>
#include <chrono>

#include <glad/gl.h>

namespace pfx::bench {

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double time_copy(gl::CopyPass& copy, uint32_t source, uint32_t target, int w, int h, pfx::host::Timing timing) {
  if (timing == pfx::host::Timing::GPU_QUERIES) {
    GLuint queries[2];
    glGenQueries(2, queries);
    glQueryCounter(queries[0], GL_TIMESTAMP);
    copy.run(source, target, w, h);
    glQueryCounter(queries[1], GL_TIMESTAMP);
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(queries[0], GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(queries[1], GL_QUERY_RESULT, &end);
    glDeleteQueries(2, queries);
    return double(end - start) * 1e-6;
  }
  glFinish();
  auto start = std::chrono::steady_clock::now();
  copy.run(source, target, w, h);
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace pfx::bench

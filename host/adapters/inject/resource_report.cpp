#include "resource_report.hpp"

#include <cstdio>

#include <glad/gl.h>

#include "process_memory.hpp"

namespace pfx::inject {
namespace {

constexpr GLuint kNamesLooked = 8192;

int count(GLboolean (*is)(GLuint)) {
  int live = 0;
  for (GLuint name = 1; name <= kNamesLooked; ++name) live += is(name) ? 1 : 0;
  return live;
}

}  // namespace

ResourceCounts count_resources() {
  ResourceCounts counts;
  counts.resident_kib = resident_kib();
  counts.heap_bytes = heap_bytes_in_use();
  // glad's entries are function pointers of the current context's functions.
  counts.textures = count(glad_glIsTexture);
  counts.buffers = count(glad_glIsBuffer);
  counts.framebuffers = count(glad_glIsFramebuffer);
  counts.renderbuffers = count(glad_glIsRenderbuffer);
  counts.programs = count(glad_glIsProgram);
  counts.shaders = count(glad_glIsShader);
  counts.vertex_arrays = count(glad_glIsVertexArray);
  counts.samplers = count(glad_glIsSampler);
  counts.queries = count(glad_glIsQuery);
  return counts;
}

std::string resource_text(const ResourceCounts& c) {
  char text[512];
  std::snprintf(text, sizeof text,
                "resident memory %llu KiB; heap in use %llu bytes; GL objects: %d textures, %d buffers, %d framebuffers, %d renderbuffers, "
                "%d programs, %d shaders, %d vertex arrays, %d samplers, %d queries",
                static_cast<unsigned long long>(c.resident_kib), static_cast<unsigned long long>(c.heap_bytes), c.textures, c.buffers, c.framebuffers,
                c.renderbuffers, c.programs, c.shaders, c.vertex_arrays, c.samplers, c.queries);
  return text;
}

}  // namespace pfx::inject

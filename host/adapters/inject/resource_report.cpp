#include "resource_report.hpp"

#include <malloc.h>
#include <unistd.h>

#include <cstdio>

#include <glad/gl.h>

namespace pfx::inject {
namespace {

constexpr GLuint kNamesLooked = 8192;

int count(GLboolean (*is)(GLuint)) {
  int live = 0;
  for (GLuint name = 1; name <= kNamesLooked; ++name) live += is(name) ? 1 : 0;
  return live;
}

// The second field of /proc/self/statm: resident pages.
uint64_t resident_kib() {
  std::FILE* file = std::fopen("/proc/self/statm", "r");
  if (!file) return 0;
  unsigned long long size = 0, resident = 0;
  const int read = std::fscanf(file, "%llu %llu", &size, &resident);
  std::fclose(file);
  return read == 2 ? resident * static_cast<uint64_t>(sysconf(_SC_PAGESIZE)) / 1024 : 0;
}

// Bytes the C library's allocator has handed out and not had back, over all its arenas (small
// blocks and the ones it maps on their own). Unlike resident memory this does not move when the
// allocator keeps freed pages, the kernel merges pages or a pool maps a fresh chunk: a block lost
// per frame shows here as itself.
uint64_t heap_bytes_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<uint64_t>(info.uordblks) + static_cast<uint64_t>(info.hblkhd);
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

// --resources-at: what an application holds after a presented frame, to see that a long run with
// the chain does not grow: the process's resident memory, the bytes its C library
// allocator has handed out and not had back, and the live GL objects of the current
// context, counted by kind.
#pragma once

#include <cstdint>
#include <string>

namespace pfx::inject {

struct ResourceCounts {
  uint64_t resident_kib = 0;
  uint64_t heap_bytes = 0;  // malloc'd and not freed (glibc's mallinfo2, all arenas)
  // Names for which glIs* says yes, among the first kNamesLooked of each kind: GL hands out the
  // lowest free names, so a leak of any kind pushes its count up.
  int textures = 0, buffers = 0, framebuffers = 0, renderbuffers = 0, programs = 0, shaders = 0, vertex_arrays = 0,
      samplers = 0, queries = 0;
};

// With the context current (nothing of its state is changed).
ResourceCounts count_resources();
// "resident memory 51234 KiB; heap in use 9876543 bytes; GL objects: 12 textures, 4 buffers, ..."
std::string resource_text(const ResourceCounts& counts);

}  // namespace pfx::inject

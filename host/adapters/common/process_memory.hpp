// What a process holds in memory, read without GL: for --resources-at in the OpenGL library and
// in the Vulkan layer alike.
#pragma once

#include <cstdint>

namespace pfx::inject {

// The second field of /proc/self/statm, in KiB; 0 when it cannot be read.
uint64_t resident_kib();
// Bytes the C library's allocator has handed out and not had back, over all its arenas (small
// blocks and the ones it maps on their own). Unlike resident memory this does not move when the
// allocator keeps freed pages, the kernel merges pages or a pool maps a fresh chunk: a block lost
// per frame shows here as itself.
uint64_t heap_bytes_in_use();

}  // namespace pfx::inject

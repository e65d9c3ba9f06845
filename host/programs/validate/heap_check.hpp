// The "heap growth" check: an effect created, rendered and destroyed over and over must leave the
// process's heap as it found it. A host creates an instance per chain, per preset change, per
// clip; a plugin that keeps a little of each one grows the host without end. Measured with
// glibc's count of the bytes malloc has handed out and not had back (mallinfo2), which sees a
// lost block as itself whatever the allocator keeps or the kernel does with pages.
#pragma once

#include <cstdint>
#include <string>

#include "child_process.hpp"

namespace pfx::validate {

// The cycles the check runs: first to warm up, then measured; and the most the heap may grow
// over the measured ones. Measured on llvmpipe, the shipped effects grow the heap while caches of
// the driver fill, by less each cycle: over cycles 11-70 by 44-77 KB, over 101-200 by 3-32 KB
// (bloom, glare, dof, tiledlights, three runs each; 0-14 KB over 201-400), and never by a
// fixed amount per cycle as a leak does. The FX samplers effect (textures and sampler objects
// of its own) fills them more slowly: 258 KB over cycles 101-200 once, levelling off near 440 KB
// after 1000 cycles, with single blocks of about 100 KB given back and taken again, so one batch
// of 100 may grow by 170 KB where the next gives 99 KB back. The bound, 64 KiB over 100 cycles,
// is twice the most the other effects grew; a batch under it ends the check. It fails when all
// of up to four batches grew by more: a plugin that keeps 656 bytes or more per instance
// (broken_leaks_memory keeps 12,345: 1.24 MB).
struct HeapCycles {
  int warm_up;
  int measured;  // cycles per batch
  int batches;   // at most
  std::int64_t bound_bytes;
};
inline constexpr HeapCycles kHeapCycles{100, 100, 4, 64 * 1024};

// Why this process's heap cannot be counted with mallinfo2, or "" when it can: AddressSanitizer
// (or any allocator put in place of glibc's) hands out blocks glibc never sees.
std::string heap_count_unavailable();

// Reports the first batch's growth as the fact "heap_growth_bytes", and a problem when every
// batch grew the heap by more than the bound; when the heap cannot be counted, says why as the
// fact "skip" instead.
void check_heap_growth(const std::string& path, const std::string& effect_id, CheckReporter& report);

}  // namespace pfx::validate

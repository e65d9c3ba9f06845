// Resident memory of a host process under load, for the tests that run 2,000 frames through an
// adapter: anonymous 4 KiB pages (RssAnon), the heap and the driver's buffers, not the file pages
// the first frames map in. Transparent huge pages would move it in 2 MiB steps nobody took, so the
// test process asks for small pages before it starts a host, which inherits the setting.
#pragma once

#include <sys/types.h>

#include <cstdint>

namespace pfx::test {

// RssAnon of process `pid` in bytes; 0 when it cannot be read.
uint64_t anonymous_bytes(pid_t pid);
// PR_SET_THP_DISABLE for this process and the hosts it starts.
void use_small_pages();

// What a long run may add between frame 200 and frame 2,000: a leak of one small object a frame
// (64 bytes) shows over 1,800 frames; the allocator's and driver's caches settle by frame 200.
constexpr uint64_t kLoadGrowthLimit = 1800 * 64;

}  // namespace pfx::test

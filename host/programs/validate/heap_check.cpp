#include "heap_check.hpp"

#include <dlfcn.h>
#include <malloc.h>

#include <cstdlib>

#include "render_rig.hpp"
#include "synthetic_inputs.hpp"

namespace pfx::validate {
namespace {

// Small blocks and the ones glibc maps on their own, over every arena.
std::int64_t heap_bytes_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<std::int64_t>(info.uordblks + info.hblkhd);
}

}  // namespace

std::string heap_count_unavailable() {
  if (dlsym(RTLD_DEFAULT, "__asan_init"))
    return "AddressSanitizer replaces malloc, so glibc's count of the heap (mallinfo2) sees none of the "
           "plugin's blocks";
  // Any other allocator in glibc's place (a preloaded jemalloc or tcmalloc) hides its blocks the
  // same way: a block glibc would count must show in the count.
  constexpr std::int64_t kProbe = 64 * 1024;
  const std::int64_t before = heap_bytes_in_use();
  void* volatile probe = std::malloc(kProbe);
  const std::int64_t during = heap_bytes_in_use();
  std::free(probe);
  if (during - before < kProbe)
    return "malloc in this process is not glibc's (mallinfo2 did not count a 64 KiB block), so the heap "
           "cannot be counted";
  return "";
}

void check_heap_growth(const std::string& path, const std::string& effect_id, CheckReporter& report) {
  const std::string unavailable = heap_count_unavailable();
  if (!unavailable.empty()) {
    report.fact("skip", unavailable);
    return;
  }
  RenderRig rig(report);
  if (!rig.open(path) || !rig.add_effect(effect_id)) return;
  const pfx::app::Image frame = gradient_image(16, 9);
  // One cycle is what a host does for a chain's life: create, a frame, destroy. A render that
  // fails is reported by the rig; the heap is still counted.
  auto cycle = [&] {
    rig.render(frame, "gradient 16x9 (heap growth cycles)");
    rig.remove_effect();
    return rig.add_effect(effect_id);
  };
  const HeapCycles& cycles = kHeapCycles;
  for (int i = 0; i < cycles.warm_up; ++i)
    if (!cycle()) return;
  const std::int64_t before = heap_bytes_in_use();
  for (int i = 0; i < cycles.measured; ++i)
    if (!cycle()) return;
  const std::int64_t growth = heap_bytes_in_use() - before;
  report.fact("heap_growth_bytes", std::to_string(growth));
  if (growth <= cycles.bound_bytes) return;
  // A leak grows the heap by as much again over the next cycles; the driver's caches (llvmpipe's
  // threads keep per-scene memory in their own arenas, more of it on a loaded machine) do not.
  const std::int64_t again_before = heap_bytes_in_use();
  for (int i = 0; i < cycles.measured; ++i)
    if (!cycle()) return;
  const std::int64_t again = heap_bytes_in_use() - again_before;
  if (again > cycles.bound_bytes)
    report.problem("the heap grew by " + std::to_string(growth) + " bytes over " + std::to_string(cycles.measured) +
                   " cycles of create, a 16x9 frame and destroy (" + std::to_string(growth / cycles.measured) +
                   " bytes per cycle, after " + std::to_string(cycles.warm_up) + " to warm up), and by " +
                   std::to_string(again) + " over as many more: more than the bound of " +
                   std::to_string(cycles.bound_bytes) + " bytes each time; the plugin keeps memory it allocated for "
                   "an instance");
}

}  // namespace pfx::validate

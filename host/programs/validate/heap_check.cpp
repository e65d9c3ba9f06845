#include "heap_check.hpp"

#include <dlfcn.h>
#include <malloc.h>

#include <cstdlib>
#include <vector>

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
  // A leak grows the heap by as much in every batch of cycles; the driver's caches (llvmpipe's
  // threads keep per-scene memory in their own arenas, more of it on a loaded machine) fill, then
  // hand blocks of about 100 KB back and forth. So the check fails only when every batch grew.
  std::vector<std::int64_t> growths;
  for (int batch = 0; batch < cycles.batches; ++batch) {
    const std::int64_t before = heap_bytes_in_use();
    for (int i = 0; i < cycles.measured; ++i)
      if (!cycle()) return;
    growths.push_back(heap_bytes_in_use() - before);
    if (batch == 0) report.fact("heap_growth_bytes", std::to_string(growths.front()));
    if (growths.back() <= cycles.bound_bytes) return;
  }
  std::string later;
  for (std::size_t i = 1; i < growths.size(); ++i)
    later += (i == 1 ? "" : i + 1 == growths.size() ? " and " : ", ") + std::to_string(growths[i]);
  report.problem("the heap grew by " + std::to_string(growths.front()) + " bytes over " +
                 std::to_string(cycles.measured) + " cycles of create, a 16x9 frame and destroy (" +
                 std::to_string(growths.front() / cycles.measured) + " bytes per cycle, after " +
                 std::to_string(cycles.warm_up) + " to warm up), and by " + later + " over as many in each of " +
                 std::to_string(growths.size() - 1) + " batches after them: more than the bound of " +
                 std::to_string(cycles.bound_bytes) + " bytes every time; the plugin keeps memory it allocated "
                 "for an instance");
}

}  // namespace pfx::validate

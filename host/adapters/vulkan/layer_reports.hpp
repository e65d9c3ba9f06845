// What the layer writes for pfx-inject's own tools, as its OpenGL library writes them: the frame
// times --bench reads (PFX_INJECT_STATS) and the pass times --panel's pfx-view shows
// (PFX_INJECT_TIMINGS). Called under state().mutex.
#pragma once

#include <cstdint>

#include <pfx/vulkan_bridge.h>

namespace pfx::vulkan_layer {

// After a present returned.
void report_present();
// After the bridge ran `image` as the process's presented frame `frame`.
void report_run(pfx_vk_bridge* bridge, const pfx_vk_image& image, uint64_t frame);
// Before the application is ended after --quit-after's frame: the frame times, when --bench asked.
void write_bench_stats();

}  // namespace pfx::vulkan_layer

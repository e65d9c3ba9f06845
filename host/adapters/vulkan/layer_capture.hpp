// pfx-inject's --capture and --quit-after for Vulkan applications: for a chosen presented frame
// (counted from 1 over every swapchain of the process) PREFIX.png holds what was presented and
// PREFIX.app.png the application's own frame, as 8-bit RGB; each file appears whole or not at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pfx::vulkan_layer {

// The capture prefixes asked for this frame.
std::vector<std::string> capture_prefixes_for(uint64_t frame);
// Names in the log the captures of this frame that are not written, with the reason: each once
// (all:PREFIX once while the reason lasts). swapchain_index as for write_capture's prefixes.
void say_captures_skipped(uint64_t frame, uint32_t swapchain_index, const std::string& why);
// PREFIX for the first swapchain of a present, PREFIX-2 for the second...
std::string swapchain_suffix(uint32_t swapchain_index);
// Writes PREFIX.app.png and PREFIX.png from RGBA rows, top row first; a file that cannot be
// written is named in the log.
void write_capture(const std::string& prefix, uint32_t width, uint32_t height, const std::vector<uint8_t>& app,
                   const std::vector<uint8_t>& result);
// The frame after which the application is ended (exit(0), its atexit handlers run), or 0.
uint64_t quit_after();

}  // namespace pfx::vulkan_layer

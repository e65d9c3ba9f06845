// Running the video hosts (ffmpeg, melt, gst-launch-1.0) as a user does, with this build's
// adapters found through the hosts' own search paths (FREI0R_PATH, GST_PLUGIN_PATH) and the test
// fixture plugins through PFX_PLUGIN_PATH; and the 8-bit pictures they write.
#pragma once

#include <string>
#include <vector>

#include "image.hpp"
#include "view_process.hpp"

namespace pfx::test {

// VAR=value items for a host program: the adapters' folders, a GStreamer registry of the tests'
// own, headless GL for GStreamer; in a sanitizer build, AddressSanitizer's runtime preloaded
// (the hosts are not built with it) with leak checking left to our own processes. `extra` items
// come last and win.
std::vector<std::string> host_environment(const std::vector<std::string>& extra = {});

// Runs argv under /usr/bin/env with host_environment(extra); stdout and stderr together.
RunResult run_host(const std::vector<std::string>& argv, const std::vector<std::string>& extra = {},
                   double timeout_seconds = 300);
// The same, started and left running (for watching a long run).
std::vector<std::string> host_command(const std::vector<std::string>& argv, const std::vector<std::string>& extra = {});

// A PNG read as RGBA (RGB files get alpha 255); REQUIREs that it reads.
app::DisplayImage read_rgba(const std::string& path);
// pixels as RGB (alpha dropped), for comparing with a file written without alpha.
std::vector<uint8_t> rgb_of(const app::DisplayImage& image);
// How often `what` occurs in `text`.
size_t occurrences(const std::string& text, const std::string& what);
// A file's bytes (empty when it cannot be read).
std::vector<uint8_t> read_bytes(const std::string& path);
// gst-launch-1.0 [-q] with a pipeline written as on its command line, words split at blanks
// (nothing in the tests' pipelines needs quoting); -q hides the element warnings it prints.
RunResult gst_launch(const std::string& pipeline, bool quiet = true, const std::vector<std::string>& extra = {});

}  // namespace pfx::test

#pragma once
// Files of compiled code that an FX runtime keeps between runs (GL program binaries, the Vulkan
// pipeline cache): where they live, how a file proves it is whole, and how it is written so that
// a reader never sees half of one. A folder per kind under $XDG_CACHE_HOME/pfx (else
// ~/.cache/pfx); PFX_FX_CACHE=0 turns every cache off. A file is an 8-byte magic, a 64-bit FNV-1a
// checksum of what follows, and its payload; one whose magic or checksum is wrong is treated as
// absent (the caller builds again and writes it anew). Files are written under a temporary name
// and renamed when complete, so two processes writing the same file leave one whole file.
#include <cstdint>
#include <string>

namespace pfx::fx::cache {

// The folder for caches of `kind` ("fx-programs"), or "" when caching is off or there is no home.
std::string folder_for(const char* kind);

// FNV-1a, 64 bits, from a seed.
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t seed = 0xCBF29CE484222325ull);

// The payload of a whole file with `magic` (8 bytes), or false.
bool read_checked(const std::string& path, const char* magic, std::string& payload);
// Writes the file atomically, creating its folder; false when the disk refuses (a cache is an
// aid: callers go on without it).
bool write_checked(const std::string& path, const char* magic, const std::string& payload);

// Deletes the files of `folder` used longest ago (by modification time; a reader touches what it
// uses) while it holds more than `max_bytes`, down to three quarters of it. Files another process
// deletes first are passed over.
void keep_within(const std::string& folder, std::uintmax_t max_bytes);

}  // namespace pfx::fx::cache

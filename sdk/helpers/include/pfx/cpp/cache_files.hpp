// Header-only C++ helpers for plugin authors: files of compiled code a plugin keeps between runs
// (GL program binaries, a Vulkan pipeline cache): where they live, how a file proves it is whole,
// and how it is written so that a reader never sees half of one. A folder per kind under
// $XDG_CACHE_HOME/pfx (else ~/.cache/pfx). A file is an 8-byte magic, a 64-bit FNV-1a checksum of
// what follows, and its payload; one whose magic or checksum is wrong is treated as absent (the
// caller builds again and writes it anew). Files are written under a temporary name and renamed
// when complete, so two processes writing the same file leave one whole file.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace pfx::cache {

// The folder for caches of `kind` ("fx-programs"), or "" when there is no home or the environment
// variable `off_variable` is "0" (the user's switch for this plugin's caches).
inline std::string folder_for(const char* kind, const char* off_variable) {
  const char* off = std::getenv(off_variable);
  if (off && std::strcmp(off, "0") == 0) return "";
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  if (xdg && *xdg) return std::string(xdg) + "/pfx/" + kind;
  if (home && *home) return std::string(home) + "/.cache/pfx/" + kind;
  return "";
}

// FNV-1a, 64 bits, from a seed.
inline std::uint64_t fnv1a(const std::string& bytes, std::uint64_t seed = 0xCBF29CE484222325ull) {
  std::uint64_t hash = seed;
  for (unsigned char c : bytes) hash = (hash ^ c) * 0x100000001B3ull;
  return hash;
}

// The payload of a whole file with `magic` (8 bytes), or false.
inline bool read_checked(const std::string& path, const char* magic, std::string& payload) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return false;
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (bytes.size() < 16 || std::memcmp(bytes.data(), magic, 8) != 0) return false;
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, bytes.data() + 8, 8);
  payload = bytes.substr(16);
  return fnv1a(payload) == checksum;
}

// Writes the file atomically, creating its folder; false when the disk refuses (a cache is an
// aid: callers go on without it).
inline bool write_checked(const std::string& path, const char* magic, const std::string& payload) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(fs::path(path).parent_path(), ec);
  static std::atomic<unsigned> counter{0};
  const std::string temporary = path + ".tmp." + std::to_string(getpid()) + "." + std::to_string(counter++);
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    const std::uint64_t checksum = fnv1a(payload);
    file.write(magic, 8);
    file.write(reinterpret_cast<const char*>(&checksum), 8);
    file.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    if (!file) {
      file.close();
      fs::remove(temporary, ec);
      return false;
    }
  }
  fs::rename(temporary, path, ec);  // complete files only, whoever reads at the same time
  if (ec) fs::remove(temporary, ec);
  return !ec;
}

// Deletes the .bin files of `folder` used longest ago (by modification time; a reader touches
// what it uses) while it holds more than `max_bytes`, down to three quarters of it. Files another
// process deletes first are passed over.
inline void keep_within(const std::string& folder, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<std::pair<fs::file_time_type, fs::path>> files;
  std::uintmax_t total = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    if (entry.path().extension() != ".bin") continue;
    const std::uintmax_t size = entry.file_size(ec);
    if (ec) continue;
    total += size;
    files.emplace_back(entry.last_write_time(ec), entry.path());
  }
  if (total <= max_bytes) return;
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    if (total <= max_bytes / 4 * 3) break;
    const std::uintmax_t size = fs::file_size(file.second, ec);
    if (!ec && fs::remove(file.second, ec)) total -= size;
  }
}

}  // namespace pfx::cache

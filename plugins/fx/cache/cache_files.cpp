#include "cache_files.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

namespace pfx::fx::cache {

namespace fs = std::filesystem;

std::string folder_for(const char* kind) {
  const char* off = std::getenv("PFX_FX_CACHE");
  if (off && std::strcmp(off, "0") == 0) return "";
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  if (xdg && *xdg) return std::string(xdg) + "/pfx/" + kind;
  if (home && *home) return std::string(home) + "/.cache/pfx/" + kind;
  return "";
}

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t seed) {
  std::uint64_t hash = seed;
  for (unsigned char c : bytes) hash = (hash ^ c) * 0x100000001B3ull;
  return hash;
}

bool read_checked(const std::string& path, const char* magic, std::string& payload) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return false;
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (bytes.size() < 16 || std::memcmp(bytes.data(), magic, 8) != 0) return false;
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, bytes.data() + 8, 8);
  payload = bytes.substr(16);
  return fnv1a(payload) == checksum;
}

bool write_checked(const std::string& path, const char* magic, const std::string& payload) {
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

void keep_within(const std::string& folder, std::uintmax_t max_bytes) {
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

}  // namespace pfx::fx::cache

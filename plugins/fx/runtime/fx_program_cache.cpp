#include "fx_program_cache.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

namespace pfx_fx {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'P', 'F', 'X', 'F', 'X', 'P', 'B', '1'};
constexpr const char* kPluginVersion = "0.1.0";

// FNV-1a, 64 bits, from a seed: two seeds make the 128-bit names of cache files.
std::uint64_t fnv(const std::string& text, std::uint64_t hash) {
  for (unsigned char c : text) hash = (hash ^ c) * 0x100000001B3ull;
  return hash;
}

// The most the folder may hold. Specialised programs (fx_programs.hpp) add one set per distinct
// set of values an effect settles on, so without a bound the folder would only grow; past it the
// programs used longest ago go first, until three quarters of it remain.
constexpr std::uintmax_t kMaxBytes = 256ull << 20;

// Deletes the least recently used programs (a load touches its file) while the folder holds more
// than kMaxBytes. Another process may be doing the same: a file already gone is passed over.
void keep_within_bound(const std::string& folder) {
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
  if (total <= kMaxBytes) return;
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    if (total <= kMaxBytes / 4 * 3) break;
    const std::uintmax_t size = fs::file_size(file.second, ec);
    if (!ec && fs::remove(file.second, ec)) total -= size;
  }
}

std::string gl_string(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

ProgramCache::ProgramCache() {
  const char* off = std::getenv("PFX_FX_CACHE");
  if (off && std::strcmp(off, "0") == 0) return;
  GLint formats = 0;
  glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
  if (formats <= 0) return;
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  if (xdg && *xdg) folder_ = std::string(xdg) + "/pfx/fx-programs";
  else if (home && *home) folder_ = std::string(home) + "/.cache/pfx/fx-programs";
  driver_ = gl_string(GL_VENDOR) + "\n" + gl_string(GL_RENDERER) + "\n" + gl_string(GL_VERSION) + "\n" + kPluginVersion;
}

std::string ProgramCache::key(const std::vector<std::string>& sources) const {
  std::string all = driver_;
  for (const std::string& s : sources) all += "\n--\n" + s;
  char name[40];
  std::snprintf(name, sizeof name, "%016llx%016llx", static_cast<unsigned long long>(fnv(all, 0xCBF29CE484222325ull)),
                static_cast<unsigned long long>(fnv(all, 0x84222325CBF29CE4ull)));
  return name;
}

GLuint ProgramCache::load(const std::string& key) const {
  if (!usable()) return 0;
  std::ifstream file(folder_ + "/" + key + ".bin", std::ios::binary);
  if (!file) return 0;
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::size_t header = sizeof kMagic + 4 + 8;
  if (bytes.size() <= header || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) return 0;
  std::uint32_t format = 0;
  std::uint64_t checksum = 0;
  std::memcpy(&format, bytes.data() + sizeof kMagic, 4);
  std::memcpy(&checksum, bytes.data() + sizeof kMagic + 4, 8);
  std::string binary = bytes.substr(header);
  if (fnv(binary, 0xCBF29CE484222325ull) != checksum) return 0;  // damaged: rebuilt and written again
  GLuint program = glCreateProgram();
  glProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  glProgramBinary(program, format, binary.data(), static_cast<GLsizei>(binary.size()));
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  while (glGetError() != GL_NO_ERROR) {  // a refused binary may raise an error; the pass must not
  }
  if (linked) {
    std::error_code ec;
    fs::last_write_time(folder_ + "/" + key + ".bin", fs::file_time_type::clock::now(), ec);  // used now
    return program;
  }
  glDeleteProgram(program);  // stale (another driver build): rebuilt and written again
  return 0;
}

void ProgramCache::store(const std::string& key, GLuint program) const {
  if (!usable()) return;
  GLint length = 0;
  glGetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &length);
  if (length <= 0) return;
  std::string binary(static_cast<std::size_t>(length), '\0');
  GLenum format = 0;
  GLsizei written = 0;
  glGetProgramBinary(program, length, &written, &format, binary.data());
  while (glGetError() != GL_NO_ERROR) {
  }
  if (written <= 0) return;
  binary.resize(static_cast<std::size_t>(written));
  std::error_code ec;
  fs::create_directories(folder_, ec);
  static std::atomic<unsigned> counter{0};
  const std::string path = folder_ + "/" + key + ".bin";
  const std::string temporary = path + ".tmp." + std::to_string(getpid()) + "." + std::to_string(counter++);
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    std::uint32_t f = format;
    std::uint64_t checksum = fnv(binary, 0xCBF29CE484222325ull);
    file.write(kMagic, sizeof kMagic);
    file.write(reinterpret_cast<const char*>(&f), 4);
    file.write(reinterpret_cast<const char*>(&checksum), 8);
    file.write(binary.data(), static_cast<std::streamsize>(binary.size()));
    if (!file) {
      file.close();
      fs::remove(temporary, ec);
      return;
    }
  }
  fs::rename(temporary, path, ec);  // complete files only, whoever reads at the same time
  if (ec) fs::remove(temporary, ec);
  keep_within_bound(folder_);
}

}  // namespace pfx_fx

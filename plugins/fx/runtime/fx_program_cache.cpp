#include "fx_program_cache.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "cache_files.hpp"

namespace pfx_fx {
namespace {

namespace fs = std::filesystem;
using pfx::fx::cache::fnv1a;

// The payload: the binary's format (4 bytes), then the binary. Version 2 checksums the format too.
constexpr char kMagic[8] = {'P', 'F', 'X', 'F', 'X', 'P', 'B', '2'};
constexpr const char* kPluginVersion = "0.1.0";

// The most the folder may hold. Specialised programs (fx_programs.hpp) add one set per distinct
// set of values an effect settles on, so without a bound the folder would only grow; past it the
// programs used longest ago go first, until three quarters of it remain.
constexpr std::uintmax_t kMaxBytes = 256ull << 20;

std::string gl_string(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

ProgramCache::ProgramCache() {
  folder_ = pfx::fx::cache::folder_for("fx-programs");
  GLint formats = 0;
  glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
  if (formats <= 0) folder_.clear();
  driver_ = gl_string(GL_VENDOR) + "\n" + gl_string(GL_RENDERER) + "\n" + gl_string(GL_VERSION) + "\n" + kPluginVersion;
}

std::string ProgramCache::key(const std::vector<std::string>& sources) const {
  std::string all = driver_;
  for (const std::string& s : sources) all += "\n--\n" + s;
  char name[40];
  // Two seeds make a 128-bit name.
  std::snprintf(name, sizeof name, "%016llx%016llx", static_cast<unsigned long long>(fnv1a(all, 0xCBF29CE484222325ull)),
                static_cast<unsigned long long>(fnv1a(all, 0x84222325CBF29CE4ull)));
  return name;
}

GLuint ProgramCache::load(const std::string& key) const {
  if (!usable()) return 0;
  std::string payload;
  const std::string path = folder_ + "/" + key + ".bin";
  if (!pfx::fx::cache::read_checked(path, kMagic, payload) || payload.size() <= 4) return 0;  // damaged: rebuilt and written again
  std::uint32_t format = 0;
  std::memcpy(&format, payload.data(), 4);
  GLuint program = glCreateProgram();
  glProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  glProgramBinary(program, format, payload.data() + 4, static_cast<GLsizei>(payload.size() - 4));
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  while (glGetError() != GL_NO_ERROR) {  // a refused binary may raise an error; the pass must not
  }
  if (linked) {
    std::error_code ec;
    fs::last_write_time(path, fs::file_time_type::clock::now(), ec);  // used now
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
  std::string payload(4 + static_cast<std::size_t>(length), '\0');
  GLenum format = 0;
  GLsizei written = 0;
  glGetProgramBinary(program, length, &written, &format, payload.data() + 4);
  while (glGetError() != GL_NO_ERROR) {
  }
  if (written <= 0) return;
  payload.resize(4 + static_cast<std::size_t>(written));
  const std::uint32_t f = format;
  std::memcpy(payload.data(), &f, 4);
  if (pfx::fx::cache::write_checked(folder_ + "/" + key + ".bin", kMagic, payload)) pfx::fx::cache::keep_within(folder_, kMaxBytes);
}

}  // namespace pfx_fx

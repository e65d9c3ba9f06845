// Header-only C++ helpers for plugin authors: compiled GL programs kept on disk, so an effect
// starts without the driver compiling its GLSL again. One file per program in the folder of a kind
// (cache_files.hpp: $XDG_CACHE_HOME/pfx/<kind>, else ~/.cache/pfx/<kind>), named by a hash of the
// program's sources, the GL's vendor, renderer and version, and the plugin's version. A file that
// is damaged (its checksum), stale (refused by the GL) or unreadable is ignored and written again.
// The folder holds at most a given number of bytes: past that, the programs used longest ago are
// deleted. Needs <glad/gl.h> as gl_program.hpp does.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <glad/gl.h>
#include <pfx/cpp/cache_files.hpp>
#include <pfx/cpp/gl_program.hpp>

namespace pfx::gl {

class ProgramCache {
 public:
  // With a context current: the GL's identity and the folder of `kind`; usable() is false when
  // the GL offers no binary format, there is no folder, or `off_variable` is "0". `version`
  // changes every key (a plugin's version: its programs may change meaning between versions).
  ProgramCache(const char* kind, const char* off_variable, const std::string& version, std::uintmax_t max_bytes)
      : folder_(pfx::cache::folder_for(kind, off_variable)), max_bytes_(max_bytes) {
    GLint formats = 0;
    glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
    if (formats <= 0) folder_.clear();
    driver_ = gl_string(GL_VENDOR) + "\n" + gl_string(GL_RENDERER) + "\n" + gl_string(GL_VERSION) + "\n" + version;
  }
  bool usable() const { return !folder_.empty(); }

  // The name of the program built from `sources` (its stages' GLSL, in order).
  std::string key(const std::vector<std::string>& sources) const {
    std::string all = driver_;
    for (const std::string& s : sources) all += "\n--\n" + s;
    char name[40];
    // Two seeds make a 128-bit name.
    std::snprintf(name, sizeof name, "%016llx%016llx",
                  static_cast<unsigned long long>(pfx::cache::fnv1a(all, 0xCBF29CE484222325ull)),
                  static_cast<unsigned long long>(pfx::cache::fnv1a(all, 0x84222325CBF29CE4ull)));
    return name;
  }

  // A linked program from the cache, or 0.
  GLuint load(const std::string& key) const {
    if (!usable()) return 0;
    std::string payload;
    const std::string path = folder_ + "/" + key + ".bin";
    if (!pfx::cache::read_checked(path, kMagic, payload) || payload.size() <= 4) return 0;  // damaged: built again
    std::uint32_t format = 0;
    std::memcpy(&format, payload.data(), 4);
    GLuint program = glCreateProgram();
    glProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
    glProgramBinary(program, format, payload.data() + 4, static_cast<GLsizei>(payload.size() - 4));
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    while (glGetError() != GL_NO_ERROR) {  // a refused binary may raise an error; the caller must not see it
    }
    if (linked) {
      std::error_code ec;
      std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), ec);  // used now
      return program;
    }
    glDeleteProgram(program);  // stale (another driver build): built again and written again
    return 0;
  }

  // Stores a program built with its binary retrievable; failures are silent (the cache is an aid).
  void store(const std::string& key, GLuint program) const {
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
    if (pfx::cache::write_checked(folder_ + "/" + key + ".bin", kMagic, payload))
      pfx::cache::keep_within(folder_, max_bytes_);
  }

  // build_program through the cache: the program from the cache when it is there (*from_cache
  // true), else compiled, linked and stored. 0 and the compiler's message in *error on failure.
  GLuint build(const GLenum* stages, const char* const* sources, int count, std::string* error,
               bool* from_cache = nullptr) const {
    std::vector<std::string> texts(sources, sources + count);
    const std::string name = usable() ? key(texts) : std::string();
    GLuint program = usable() ? load(name) : 0;
    if (from_cache) *from_cache = program != 0;
    if (program) return program;
    program = build_program(stages, sources, count, error, usable());
    if (program) store(name, program);
    return program;
  }

 private:
  static std::string gl_string(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "";
  }

  // The payload: the binary's format (4 bytes), then the binary.
  static constexpr char kMagic[8] = {'P', 'F', 'X', 'G', 'L', 'P', 'B', '2'};

  std::string folder_;
  std::string driver_;
  std::uintmax_t max_bytes_;
};

}  // namespace pfx::gl

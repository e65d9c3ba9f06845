#pragma once
// Compiled GL programs of FX passes kept on disk, so an effect starts without the driver compiling
// its GLSL again: one file per program in $XDG_CACHE_HOME/pfx/fx-programs (else
// ~/.cache/pfx/fx-programs), named by a hash of the program's GLSL, the GL's vendor, renderer and
// version, and this plugin's version. Files are written under a temporary name and renamed when
// complete; one that is damaged (its checksum), stale (refused by the GL) or unreadable is ignored
// and written again. The folder holds at most 256 MiB: past that, the programs used longest ago
// are deleted. PFX_FX_CACHE=0 turns the cache off. The GLSL itself is generated at every
// start: it costs a few milliseconds on the CPU.
#include <string>
#include <vector>

#include <glad/gl.h>

namespace pfx_fx {

class ProgramCache {
 public:
  // Reads the GL's identity and the folder; usable() is false when the GL offers no binary format
  // or there is no folder.
  ProgramCache();
  bool usable() const { return !folder_.empty(); }
  std::string key(const std::vector<std::string>& sources) const;
  // A linked program from the cache, or 0.
  GLuint load(const std::string& key) const;
  // Stores a program built with its binary retrievable; failures are silent (the cache is an aid).
  void store(const std::string& key, GLuint program) const;

 private:
  std::string folder_;
  std::string driver_;
};

}  // namespace pfx_fx

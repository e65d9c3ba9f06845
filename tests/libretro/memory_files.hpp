#pragma once
// Files held in memory for the readers of plugins/libretro/formats: each test writes the presets
// and shaders it reads, so every rule is checked on text written for it.
#include <map>
#include <optional>
#include <string>

#include "preset_file.hpp"

namespace pfx::test {

struct MemoryFiles {
  std::map<std::string, std::string> texts;  // path -> text
  int reads = 0;

  libretro::TextReader reader() {
    return [this](const std::string& path, std::string* error) -> std::optional<std::string> {
      ++reads;
      auto it = texts.find(path);
      if (it == texts.end()) return *error = path + ": no such file", std::nullopt;
      return it->second;
    };
  }
};

}  // namespace pfx::test

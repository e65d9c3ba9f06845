#pragma once
// One preset file (.slangp, .glslp) read as RetroArch's configuration files are: `key = value`
// lines, `#` comments, values quoted or up to the first space, the first of two equal keys kept,
// `#include "file"` spliced in (its keys only where the file has none yet) and `#reference "file"`
// collected for the preset (preset.hpp says what a reference means). Two things RetroArch drops
// are read as their writers meant them: `key=value` without spaces, and `/* ... */` notes over
// several lines (RetroArch skips such lines only because they have no '='). No file is opened here
// but through the reader the caller gives, so the rules are tested on text.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pfx::libretro {

// Where a line came from, for messages: "file:line".
struct TextPlace {
  std::string file;
  int line = 0;
  std::string text() const { return file + ":" + std::to_string(line); }
};

struct PresetEntry {
  std::string value;  // quotes removed
  TextPlace place;
};

struct PresetFile {
  std::string path;                            // as given to read_preset_file
  std::map<std::string, PresetEntry> entries;  // the first of equal keys
  std::vector<PresetEntry> references;         // `#reference` paths, in file order, as written
  std::vector<std::string> warnings;           // "file:line: ..." for lines that mean nothing

  const PresetEntry* find(const std::string& key) const {
    auto it = entries.find(key);
    return it == entries.end() ? nullptr : &it->second;
  }
};

// Reads the file at `path` into its text, or returns nothing with the reason in *error.
using TextReader = std::function<std::optional<std::string>(const std::string& path, std::string* error)>;
// The reader of files on disk: at most kMaxPresetFileBytes, so that a huge file is refused, not read.
constexpr std::size_t kMaxPresetFileBytes = 4u << 20;
std::optional<std::string> read_text_file(const std::string& path, std::string* error);

// The path `written` names in the file `from`: a leading "~/" is the home folder, a relative path
// is relative to `from`'s folder; "." and ".." are taken out.
std::string resolve_preset_path(const std::string& written, const std::string& from);

// Parses `path` (read with `read`), splicing its `#include`s (at most kMaxIncludeDepth deep and
// kMaxIncludes in all, so that files including one another twice over end). False with
// "file:line: why" in *error for a file that cannot be read.
constexpr int kMaxIncludeDepth = 16;
constexpr int kMaxIncludes = 256;
bool read_preset_file(const std::string& path, const TextReader& read, PresetFile* out, std::string* error);

}  // namespace pfx::libretro

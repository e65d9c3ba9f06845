#include "preset_file.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pfx::libretro {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::size_t skip_spaces(const std::string& line, std::size_t at) {
  while (at < line.size() && is_space(line[at])) ++at;
  return at;
}

// A value as RetroArch reads one: inside the quotes when it starts with one (to the end of the line
// when the closing quote is missing), else up to the first space or `#`.
std::string read_value(const std::string& line, std::size_t at) {
  if (at < line.size() && line[at] == '"') {
    const std::size_t end = line.find('"', at + 1);
    return line.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
  }
  std::size_t end = at;
  while (end < line.size() && !is_space(line[end]) && line[end] != '#') ++end;
  return line.substr(at, end - at);
}

// `#include` and `#reference` count only at the start of a line, in lower case, followed by a space.
bool directive(const std::string& line, const char* name, std::string* argument) {
  const std::string tag = std::string("#") + name + " ";
  if (line.compare(0, tag.size(), tag) != 0) return false;
  *argument = read_value(line, skip_spaces(line, tag.size()));
  return true;
}

struct Reader {
  const TextReader& read;
  PresetFile& out;
  std::string& error;
  int includes = 0;

  // `from`: the #include line that names the file (null for the preset itself).
  bool file(const std::string& path, int depth, const TextPlace* from) {
    std::optional<std::string> text = read(path, &error);
    if (!text) return error = (from ? from->text() + ": " : std::string()) + error, false;
    std::istringstream lines(*text);
    std::string line;
    bool in_block_comment = false;
    for (int number = 1; std::getline(lines, line); ++number) {
      const TextPlace place{path, number};
      std::string argument;
      if (directive(line, "include", &argument)) {
        if (++includes > kMaxIncludes)
          return error = place.text() + ": more than " + std::to_string(kMaxIncludes) + " includes in one preset file",
                 false;
        if (depth >= kMaxIncludeDepth)
          return error = place.text() + ": includes nest more than " + std::to_string(kMaxIncludeDepth) +
                         " deep (does a file include itself?)",
                 false;
        if (!file(resolve_preset_path(argument, path), depth + 1, &place)) return false;
        continue;
      }
      if (directive(line, "reference", &argument)) {
        out.references.push_back({argument, place});
        continue;
      }
      if (!line.empty() && line[0] == '#') continue;  // a comment
      std::size_t at = skip_spaces(line, 0);
      // A block comment (/* ... */) from the line it opens on to the line it closes on, as the
      // collections write notes in presets; RetroArch ignores those lines for their missing '='.
      if (in_block_comment || line.compare(at, 2, "/*") == 0) {
        in_block_comment = line.find("*/", in_block_comment ? 0 : at + 2) == std::string::npos;
        continue;
      }
      if (at == line.size() || line[at] == '#' || line.compare(at, 2, "//") == 0) continue;
      const std::size_t key_start = at;
      while (at < line.size() && !is_space(line[at]) && line[at] != '=' && line[at] != '#') ++at;
      const std::string key = line.substr(key_start, at - key_start);
      at = skip_spaces(line, at);
      if (at == line.size() || line[at] != '=') {
        out.warnings.push_back(place.text() + ": '" + key + "' has no '= value': the line is ignored");
        continue;
      }
      // The first of two equal keys counts, as in RetroArch (an include's only where the file had none).
      out.entries.emplace(key, PresetEntry{read_value(line, skip_spaces(line, at + 1)), place});
    }
    return true;
  }
};

}  // namespace

std::optional<std::string> read_text_file(const std::string& path, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return *error = path + ": cannot be opened", std::nullopt;
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxPresetFileBytes)
      return *error = path + ": larger than " + std::to_string(kMaxPresetFileBytes >> 20) +
                      " MiB, not a preset or shader",
             std::nullopt;
  }
  if (in.bad()) return *error = path + ": cannot be read", std::nullopt;
  return text;
}

std::string resolve_preset_path(const std::string& written, const std::string& from) {
  std::string path;
  if (written.size() >= 2 && written[0] == '~' && written[1] == '/' && std::getenv("HOME") && *std::getenv("HOME")) {
    path = std::getenv("HOME") + written.substr(1);
  } else if (!written.empty() && written[0] == '/') {
    path = written;
  } else {
    const std::size_t slash = from.rfind('/');
    path = slash == std::string::npos ? written : from.substr(0, slash + 1) + written;
  }
  // "a/../b" as "b": one name for a file however it is reached (files are read once by name).
  return std::filesystem::path(path).lexically_normal().string();
}

bool read_preset_file(const std::string& path, const TextReader& read, PresetFile* out, std::string* error) {
  *out = PresetFile{};
  out->path = path;
  Reader reader{read, *out, *error};
  return reader.file(path, 0, nullptr);
}

}  // namespace pfx::libretro

#include "glsl_source.hpp"

#include <algorithm>
#include <sstream>

namespace pfx::libretro {
namespace {

// The line without the spaces and tabs it starts with.
std::string trimmed_start(const std::string& line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : line.substr(first);
}

// "#version 130" -> 130; 0 when the directive carries no number.
int version_number(const std::string& directive) {
  std::istringstream words(directive.substr(8));
  int number = 0;
  return words >> number ? number : 0;
}

}  // namespace

bool read_glsl(const std::string& path, const TextReader& read, SlangSource* out, std::string* error) {
  *out = SlangSource{};
  out->path = path;
  out->files.push_back(path);
  std::optional<std::string> text = read(path, error);
  if (!text) return false;
  if (text->size() > kMaxSlangSourceBytes)
    return *error = path + ": more than " + std::to_string(kMaxSlangSourceBytes >> 20) + " MiB of code", false;
  std::istringstream lines(*text);
  std::string line, body, version;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string directive = trimmed_start(line);
    if (version.empty() && directive.compare(0, 9, "#version ") == 0) {
      version = directive;
      body += "\n";  // moved ahead of the defines; the line's place kept
      continue;
    }
    if (directive.compare(0, 18, "#pragma parameter ") == 0) {
      SlangParameter parameter;
      parameter.place = TextPlace{path, number};
      const std::size_t start = directive.find_first_not_of(" \t", 18);
      const std::string why = parse_parameter(start == std::string::npos ? "" : directive.substr(start), &parameter);
      if (!why.empty()) return *error = parameter.place.text() + ": " + why, false;
      // Declared twice (a shader pasted from two): the first one counts, as in RetroArch.
      if (std::none_of(out->parameters.begin(), out->parameters.end(),
                       [&](const SlangParameter& p) { return p.id == parameter.id; }))
        out->parameters.push_back(parameter);
      body += "\n";
      continue;
    }
    body += line + "\n";
  }
  if (version.empty() || version_number(version) < 140)
    version = "#version " + std::to_string(kGlslCoreVersion) + " core";
  // C-style initialisers (`float w[3] = {...}`), which compatibility contexts accept at every
  // version and some of the collection's shaders use, need GLSL 4.20 or this extension in core.
  const std::string head = version + "\n#extension GL_ARB_shading_language_420pack : enable\n";
  const std::string tail = "#define PARAMETER_UNIFORM\n#line 1\n" + body;
  out->vertex = head + "#define VERTEX\n" + tail;
  out->fragment = head + "#define FRAGMENT\n" + tail;
  return true;
}

}  // namespace pfx::libretro

#include "slang_source.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace pfx::libretro {
namespace {

constexpr const char* kFormats[] = {"R8_UNORM",
                                    "R8_UINT",
                                    "R8_SINT",
                                    "R8G8_UNORM",
                                    "R8G8_UINT",
                                    "R8G8_SINT",
                                    "R8G8B8A8_UNORM",
                                    "R8G8B8A8_UINT",
                                    "R8G8B8A8_SINT",
                                    "R8G8B8A8_SRGB",
                                    "A2B10G10R10_UNORM_PACK32",
                                    "A2B10G10R10_UINT_PACK32",
                                    "R16_UINT",
                                    "R16_SINT",
                                    "R16_SFLOAT",
                                    "R16G16_UINT",
                                    "R16G16_SINT",
                                    "R16G16_SFLOAT",
                                    "R16G16B16A16_UINT",
                                    "R16G16B16A16_SINT",
                                    "R16G16B16A16_SFLOAT",
                                    "R32_UINT",
                                    "R32_SINT",
                                    "R32_SFLOAT",
                                    "R32G32_UINT",
                                    "R32G32_SINT",
                                    "R32G32_SFLOAT",
                                    "R32G32B32A32_UINT",
                                    "R32G32B32A32_SINT",
                                    "R32G32B32A32_SFLOAT"};

bool starts_with(const std::string& text, const std::string& start) {
  return text.compare(0, start.size(), start) == 0;
}

// The word after `#pragma NAME` and the rest of the line, spaces around removed.
std::string rest_after(const std::string& line, std::size_t at) {
  const std::size_t first = line.find_first_not_of(" \t", at);
  if (first == std::string::npos) return "";
  return line.substr(first, line.find_last_not_of(" \t") - first + 1);
}

// The text between the first pair of quotes, as RetroArch takes an include's file.
bool quoted(const std::string& text, std::string* inside) {
  const std::size_t open = text.find('"');
  const std::size_t close = open == std::string::npos ? open : text.find('"', open + 1);
  if (close == std::string::npos) return false;
  *inside = text.substr(open + 1, close - open - 1);
  return true;
}

}  // namespace

std::string parse_parameter(const std::string& text, SlangParameter* out) {
  std::istringstream words(text);
  if (!(words >> out->id)) return "a parameter needs an id";
  const std::size_t label_at = text.find('"');
  const std::size_t label_end = label_at == std::string::npos ? label_at : text.find('"', label_at + 1);
  if (label_end == std::string::npos) return "parameter '" + out->id + "' needs its label in quotes";
  out->label = text.substr(label_at + 1, label_end - label_at - 1);
  std::vector<double> values;
  const char* at = text.data() + label_end + 1;
  const char* const end = text.data() + text.size();
  while (values.size() < 4) {
    while (at < end && (*at == ' ' || *at == '\t')) ++at;
    double value = 0;
    const auto [next, status] = std::from_chars(at + (at < end && *at == '+' ? 1 : 0), end, value);
    if (status != std::errc() || !std::isfinite(value)) break;
    values.push_back(value);
    at = next;
  }
  if (values.size() < 3)
    return "parameter '" + out->id + "' needs an initial value, a minimum and a maximum (and may give a step)";
  out->initial = values[0], out->minimum = values[1], out->maximum = values[2];
  out->step = values.size() == 4 ? values[3] : 0.1 * (values[2] - values[1]);
  return "";
}

namespace {

enum class Stage { kBoth, kVertex, kFragment };

class Expander {
 public:
  Expander(const TextReader& read, SlangSource& out, std::string& error) : read_(read), out_(out), error_(error) {}

  bool root(const std::string& path) {
    std::optional<std::string> text = read_(path, &error_);
    if (!text) return false;
    std::istringstream lines(*text);
    std::string first;
    std::getline(lines, first);
    if (!first.empty() && first.back() == '\r') first.pop_back();
    if (!starts_with(first, "#version "))
      return error_ = path + ":1: a slang shader starts with its #version line", false;
    emit(first + "\n#extension GL_GOOGLE_cpp_style_line_directive : require\n");
    note(path);
    return body(path, lines, 2, 0);
  }
  bool has_both_stages() const { return seen_vertex_ && seen_fragment_; }

 private:
  void emit(const std::string& text) {
    if (stage_ != Stage::kFragment) out_.vertex += text;
    if (stage_ != Stage::kVertex) out_.fragment += text;
  }
  void mark(const std::string& file, int line) { emit("#line " + std::to_string(line) + " \"" + file + "\"\n"); }
  void note(const std::string& file) {
    if (std::find(out_.files.begin(), out_.files.end(), file) == out_.files.end()) out_.files.push_back(file);
  }
  bool fail(const TextPlace& place, const std::string& why) { return error_ = place.text() + ": " + why, false; }

  bool include(const TextPlace& place, const std::string& file, bool optional, int depth) {
    if (++includes_ > kMaxSlangIncludes)
      return fail(place, "more than " + std::to_string(kMaxSlangIncludes) + " includes in one shader");
    if (depth >= kMaxSlangIncludeDepth)
      return fail(place, "includes nest more than " + std::to_string(kMaxSlangIncludeDepth) +
                             " deep (does a file include itself?)");
    const std::string path = resolve_preset_path(file, place.file);
    std::string why;
    std::optional<std::string> text = read_(path, &why);
    if (!text) return optional ? true : fail(place, "#include: " + why);
    note(path);
    std::istringstream lines(*text);
    if (!body(path, lines, 1, depth + 1)) return false;
    mark(place.file, place.line + 1);
    return true;
  }

  bool pragma(const TextPlace& place, const std::string& line, int depth, bool* handled) {
    *handled = true;
    std::string argument;
    if (starts_with(line, "#pragma stage ")) {
      const std::string stage = rest_after(line, 14);
      if (stage == "vertex")
        stage_ = Stage::kVertex, seen_vertex_ = true;
      else if (stage == "fragment")
        stage_ = Stage::kFragment, seen_fragment_ = true;
      else
        return fail(place, "'" + stage + "' is not a stage (vertex, fragment)");
      mark(place.file, place.line + 1);
      return true;
    }
    if (starts_with(line, "#pragma name ")) {
      if (!out_.name.empty()) return fail(place, "a second #pragma name");
      out_.name = rest_after(line, 13);
      if (out_.name.empty()) return fail(place, "#pragma name needs a name");
    } else if (starts_with(line, "#pragma format ")) {
      if (!out_.format.empty()) return fail(place, "a second #pragma format");
      out_.format = rest_after(line, 15);
      if (!is_slang_format(out_.format))
        return fail(place, "'" + out_.format + "' is not a format #pragma format knows");
    } else if (starts_with(line, "#pragma parameter ")) {
      SlangParameter parameter;
      parameter.place = place;
      const std::string why = parse_parameter(rest_after(line, 18), &parameter);
      if (!why.empty()) return fail(place, why);
      const auto same = std::find_if(out_.parameters.begin(), out_.parameters.end(),
                                     [&](const SlangParameter& p) { return p.id == parameter.id; });
      if (same == out_.parameters.end())
        out_.parameters.push_back(parameter);
      else if (same->label != parameter.label || same->initial != parameter.initial ||
               same->minimum != parameter.minimum || same->maximum != parameter.maximum || same->step != parameter.step)
        return fail(place, "parameter '" + parameter.id + "' was declared differently at " + same->place.text());
    } else if (starts_with(line, "#pragma include_optional ") && quoted(line, &argument)) {
      return include(place, argument, true, depth);
    } else {
      *handled = false;
      return true;
    }
    emit("\n");  // the line's place kept, its text out of the code
    return true;
  }

  bool body(const std::string& path, std::istringstream& lines, int first_line, int depth) {
    mark(path, first_line);
    std::string line;
    for (int number = first_line; std::getline(lines, line); ++number) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const TextPlace place{path, number};
      std::string file;
      if (starts_with(line, "#include ")) {
        if (!quoted(line, &file)) return fail(place, "#include needs a file in quotes");
        if (!include(place, file, false, depth)) return false;
        continue;
      }
      bool handled = false;
      if (starts_with(line, "#pragma ") && !pragma(place, line, depth, &handled)) return false;
      if (!handled) emit(line + "\n");
      if (out_.vertex.size() + out_.fragment.size() > 2 * kMaxSlangSourceBytes)
        return fail(place, "the shader grows past " + std::to_string(kMaxSlangSourceBytes >> 20) +
                               " MiB of code with its includes");
    }
    return true;
  }

  const TextReader& read_;
  SlangSource& out_;
  std::string& error_;
  Stage stage_ = Stage::kBoth;
  int includes_ = 0;
  bool seen_vertex_ = false, seen_fragment_ = false;
};

}  // namespace

bool is_slang_format(const std::string& name) {
  return std::find(std::begin(kFormats), std::end(kFormats), name) != std::end(kFormats);
}

bool read_slang(const std::string& path, const TextReader& read, SlangSource* out, std::string* error) {
  *out = SlangSource{};
  out->path = path;
  Expander expander(read, *out, *error);
  if (!expander.root(path)) return false;
  if (!expander.has_both_stages())
    return *error = path + ": needs both '#pragma stage vertex' and '#pragma stage fragment'", false;
  return true;
}

}  // namespace pfx::libretro

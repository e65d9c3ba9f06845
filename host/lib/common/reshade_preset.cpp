#include "reshade_preset.hpp"

#include <map>
#include <sstream>

#include <pfx/cpp/identifier.hpp>

namespace pfx::app {
namespace {

std::string trimmed(const std::string& text) {
  std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator))
    if (!trimmed(part).empty()) parts.push_back(trimmed(part));
  return parts;
}

struct Technique {
  std::string name, file;  // file "" in presets older than ReShade 4 ("Techniques=A,B")
};

Technique technique_of(const std::string& entry) {
  std::size_t at = entry.find('@');
  if (at == std::string::npos) return {entry, ""};
  return {entry.substr(0, at), entry.substr(at + 1)};
}

std::string file_name_of(const std::string& path) {
  std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string stem_of(const std::string& file_name) { return file_name.substr(0, file_name.rfind('.')); }

// ReShade and Windows editors may start a UTF-8 file with a byte-order mark.
std::string without_byte_order_mark(const std::string& text) {
  static const std::string mark = "\xEF\xBB\xBF";
  return text.rfind(mark, 0) == 0 ? text.substr(mark.size()) : text;
}

// A ReShade .ini file's keys: those before the first section, and each section's by file name.
struct IniFile {
  std::map<std::string, std::string> globals;
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> sections;
};

// Read the way ReShade reads its .ini files: a UTF-8 byte-order mark and blanks around each line
// are dropped (so are CRLF ends), lines starting with ';', '#' or '/' are comments, a section name
// ends at its first ']', and a line without '=' is a key without a value. A key given twice keeps
// its first value in a section (ReShade appends the second one after the values it reads) and adds
// to the list in the global part (two Techniques= lines enable both lists).
IniFile read_ini(const std::string& text) {
  IniFile ini;
  std::string section;
  std::istringstream in(without_byte_order_mark(text));
  std::string line;
  while (std::getline(in, line)) {
    line = trimmed(line);
    if (line.empty() || line[0] == ';' || line[0] == '#' || line[0] == '/') continue;
    if (line.front() == '[') {
      const std::size_t close = line.find(']');
      section = file_name_of(trimmed(line.substr(1, close == std::string::npos ? std::string::npos : close - 1)));
      ini.sections[section];
      continue;
    }
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos) continue;
    const std::string key = trimmed(line.substr(0, equals)), value = trimmed(line.substr(equals + 1));
    if (section.empty()) {
      std::string& list = ini.globals[key];
      list += (list.empty() || value.empty() ? "" : ",") + value;
      continue;
    }
    auto& values = ini.sections[section];
    bool seen = false;
    for (const auto& earlier : values) seen = seen || earlier.first == key;
    if (!seen) values.emplace_back(key, value);
  }
  return ini;
}

}  // namespace

bool looks_like_reshade_preset(const std::string& text) {
  std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || text[first] == '{') return false;
  std::istringstream in(without_byte_order_mark(text));
  std::string line;
  while (std::getline(in, line)) {
    line = trimmed(line);
    if (line.rfind("Techniques", 0) == 0 || line.rfind("TechniqueSorting", 0) == 0 || line.rfind("PreprocessorDefinitions", 0) == 0 ||
        (line.size() > 2 && line.front() == '['))
      return true;
  }
  return false;
}

void parse_reshade_preset(const std::string& text, Preset* out) {
  IniFile ini = read_ini(text);
  std::map<std::string, std::string>& globals = ini.globals;
  const auto& sections = ini.sections;
  std::vector<Technique> enabled;
  for (const std::string& entry : split(globals["Techniques"], ',')) enabled.push_back(technique_of(entry));
  std::vector<Technique> order;
  for (const std::string& entry : split(globals["TechniqueSorting"], ',')) order.push_back(technique_of(entry));
  auto is_enabled = [&](const Technique& t) {
    for (const Technique& e : enabled)
      if (e.name == t.name && (e.file.empty() || t.file.empty() || e.file == t.file)) return true;
    return false;
  };
  std::vector<Technique> chain;
  for (const Technique& t : order)
    if (is_enabled(t)) chain.push_back(t);
  for (const Technique& t : enabled) {  // enabled ones TechniqueSorting does not name run last
    bool placed = false;
    for (const Technique& c : chain) placed = placed || (c.name == t.name && c.file == t.file);
    if (!placed) chain.push_back(t);
  }
  out->from_reshade = true;
  out->chain = std::vector<PresetEffect>{};
  for (const Technique& t : chain) {
    std::string effect = "fx_" + pfx::identifier_from(t.name);
    out->chain->push_back({effect, true});
    // The values of the technique's file. An old preset names techniques without their file
    // (Techniques=LumaSharpen,Vibrance): then the section of the file named like the technique
    // (SweetFX's LumaSharpen in LumaSharpen.fx), else every section.
    std::string file_of_technique = t.file.empty() ? "" : file_name_of(t.file);
    if (file_of_technique.empty())
      for (const auto& section_entry : sections)
        if (pfx::identifier_from(stem_of(section_entry.first)) == pfx::identifier_from(t.name)) file_of_technique = section_entry.first;
    for (const auto& [file, values] : sections) {
      if (!file_of_technique.empty() && file != file_of_technique) continue;
      for (const auto& [name, value] : values) {
        std::string id = effect + "." + pfx::identifier_from(name);
        std::vector<std::string> parts = split(value, ',');
        if (parts.size() == 4) {
          out->assignments.push_back({id + "=" + parts[0] + "," + parts[1] + "," + parts[2]});
          out->assignments.push_back({id + "_alpha=" + parts[3], id + "_w=" + parts[3]});
        } else {
          out->assignments.push_back({id + "=" + value});
        }
      }
    }
  }
  out->source_definitions = globals["PreprocessorDefinitions"];  // trimmed; checked when applied
}

}  // namespace pfx::app

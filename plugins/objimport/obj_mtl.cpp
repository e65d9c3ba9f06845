#include "obj_mtl.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unordered_map>

#include "obj_stages.hpp"
#include "obj_text.hpp"

namespace pfx_obj {

namespace {

class MtlParser {
 public:
  MtlParser(std::string_view text, const std::string& file_name, const std::string& directory,
            std::vector<Material>* materials, std::vector<std::string>* warnings)
      : cursor_{text.data(), text.data() + text.size()}, file_name_(file_name), directory_(directory),
        materials_(materials), warnings_(warnings) {}

  void run() {
    if (std::string_view(cursor_.p, 3) == "\xEF\xBB\xBF") cursor_.p += 3;  // (the copy holds 3 bytes)
    while (cursor_.p < cursor_.end) {
      line_ = cursor_.line_ends + 1;
      statement();
      cursor_.skip_statement();
    }
  }

 private:
  void warn(const std::string& text) { warnings_->push_back(file_name_ + ":" + std::to_string(line_) + ": " + text); }

  // The material's path that a map statement sets; null for every other statement.
  static std::string* map_field(Material* m, std::string_view keyword) {
    if (keyword == "map_Kd") return &m->diffuse_map;
    if (keyword == "map_Ke") return &m->emissive_map;
    if (keyword == "map_d") return &m->alpha_map;
    if (keyword == "bump" || keyword == "map_Bump" || keyword == "map_bump") return &m->bump_map;
    if (keyword == "norm") return &m->normal_map;
    return nullptr;
  }

  std::string_view rest() const { return {cursor_.p, static_cast<size_t>(cursor_.end - cursor_.p)}; }

  Material* current(std::string_view keyword) {
    if (current_) return &materials_->back();
    warn(std::string(keyword) + " before any newmtl: ignored");
    return nullptr;
  }

  void statement() {
    cursor_.skip_blanks();
    if (cursor_.at_statement_end()) return;
    std::string_view keyword = cursor_.token();
    if (std::any_of(keyword.begin(), keyword.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; })) {
      warn("binary data: not a material library; the rest of the file is ignored");
      cursor_.p = cursor_.end;
      return;
    }
    if (keyword == "newmtl") {
      cursor_.skip_blanks();
      std::string name = cursor_.rest_of_line();
      const bool again = std::any_of(materials_->begin(), materials_->end(), [&](const Material& m) { return m.name == name; });
      if (name.empty()) warn("newmtl: needs a name");
      else if (again) warn("material '" + name + "' defined again: the first definition is kept");
      else materials_->push_back(Material{name});
      current_ = !name.empty() && !again;
    } else if (keyword == "Kd" || keyword == "Ks" || keyword == "Ke") {
      float rgb[3];
      if (!color(keyword, rgb)) return;
      if (Material* m = current(keyword))
        std::copy(rgb, rgb + 3, keyword == "Kd" ? m->diffuse : keyword == "Ks" ? m->specular : m->emissive);
    } else if (keyword == "Ns" || keyword == "d" || keyword == "Tr") {
      cursor_.skip_blanks();
      if (keyword == "d" && rest().substr(0, 5) == "-halo") {
        cursor_.token();
        cursor_.skip_blanks();
      }
      float value;
      if (!number(keyword, &value)) return;
      if (Material* m = current(keyword))
        (keyword == "Ns" ? m->shininess : m->opacity) = keyword == "Tr" ? 1.0f - value : value;
    } else if (Material probe; map_field(&probe, keyword)) {
      const std::string path = map_path(keyword);
      if (Material* m = path.empty() ? nullptr : current(keyword)) *map_field(m, keyword) = resolve_path(directory_, path);
    }
    // Everything else (Ka, Ni, illum, map_Ks, ...) is valid MTL that pfx does not use.
  }

  bool number(std::string_view keyword, float* out) {
    cursor_.skip_blanks();
    std::string_view token = cursor_.token();
    float value;
    if (!parse_float(token, &value) || !std::isfinite(value)) {
      warn(std::string(keyword) + ": '" + printable(token) + "' is not a finite number: ignored");
      return false;
    }
    *out = value;
    return true;
  }

  // "Kd r g b" or "Kd v" (grey); spectral and xyz forms are not supported.
  bool color(std::string_view keyword, float rgb[3]) {
    cursor_.skip_blanks();
    for (std::string_view form : {"spectral", "xyz"})
      if (rest().substr(0, form.size()) == form) {
        warn(std::string(keyword) + " " + std::string(form) + ": not supported, ignored");
        return false;
      }
    int count = 0;
    for (; count < 3; ++count) {
      cursor_.skip_blanks();
      if (cursor_.at_statement_end()) break;
      if (!number(keyword, &rgb[count])) return false;
    }
    cursor_.skip_blanks();
    if (count == 1) rgb[1] = rgb[2] = rgb[0];
    else if (count != 3 || !cursor_.at_statement_end()) {
      warn(std::string(keyword) + ": expected r g b: ignored");
      return false;
    }
    return true;
  }

  // The file name of a map statement after its options (-s 1 1 1, -bm 0.5, -clamp on, ...).
  std::string map_path(std::string_view keyword) {
    for (cursor_.skip_blanks(); *cursor_.p == '-'; cursor_.skip_blanks()) {
      std::string_view option = cursor_.token();
      int max_args = 1, min_args = 1;
      if (option == "-o" || option == "-s" || option == "-t") max_args = 3;
      else if (option == "-mm") min_args = max_args = 2;
      for (int i = 0; i < max_args; ++i) {
        cursor_.skip_blanks();
        const char* save = cursor_.p;
        std::string_view arg = cursor_.token();
        float unused;
        bool numeric = parse_float(arg, &unused);
        if (arg.empty() || (i >= min_args && !numeric)) {
          cursor_.p = save;
          break;
        }
      }
    }
    std::string path = cursor_.rest_of_line();
    if (path.empty()) warn(std::string(keyword) + ": needs a file name");
    return path;
  }

  LineCursor cursor_;
  const std::string& file_name_;
  const std::string& directory_;
  std::vector<Material>* materials_;
  std::vector<std::string>* warnings_;
  bool current_ = false;
  uint64_t line_ = 0;
};

}  // namespace

void parse_mtl(std::string_view text, const std::string& file_name, const std::string& directory,
               std::vector<Material>* materials, std::vector<std::string>* warnings) {
  // Read from a copy that ends with a line end, and one more byte (LineCursor).
  const std::string copy = std::string(text) + "\n\n";
  MtlParser({copy.data(), copy.size() - 1}, file_name, directory, materials, warnings).run();
}

std::string resolve_path(const std::string& directory, std::string path) {
  for (char& c : path)
    if (c == '\\') c = '/';
  std::filesystem::path p(path);
  if (p.is_absolute() || directory.empty()) return p.lexically_normal().string();
  return (std::filesystem::path(directory) / p).lexically_normal().string();
}

namespace {

// Cuts "a.mtl b.mtl" into files; a name with blanks ("my materials.mtl") is taken whole when a
// file of that whole name exists.
std::vector<std::string> material_library_names(const std::string& directory, const std::string& text) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(resolve_path(directory, text), ec)) return {text};
  std::vector<std::string> names;
  for (size_t start = text.find_first_not_of(" \t"); start != std::string::npos;) {
    const size_t end = std::min(text.find_first_of(" \t", start), text.size());
    names.push_back(text.substr(start, end - start));
    start = text.find_first_not_of(" \t", end);
  }
  return names;
}

// The materials of one mtllib line's libraries appended to table->materials.
void read_libraries(const LocalMessage& library, const std::string& directory, MaterialTable* table) {
  if (directory.empty()) {
    table->warnings.push_back(
        {library.line, "mtllib " + library.text + ": not read (the model was given as bytes without a file name)"});
    return;
  }
  for (const std::string& name : material_library_names(directory, library.text)) {
    const std::string path = resolve_path(directory, name);
    FileBytes file;
    std::string problem;
    if (!file.open(path, &problem)) {
      table->warnings.push_back({library.line, "mtllib: " + problem + " (materials keep their defaults)"});
      continue;
    }
    std::vector<std::string> warnings;
    parse_mtl(file.bytes(), path, std::filesystem::path(path).parent_path().string(), &table->materials, &warnings);
    for (std::string& warning : warnings) table->warnings.push_back({library.line, std::move(warning)});
  }
}

}  // namespace

// Stage 4 of an import (obj_stages.hpp).
MaterialTable load_materials(const FileStatements& statements, const std::string& directory) {
  MaterialTable table;
  // Every library first, in file order: a usemtl may come before its mtllib.
  for (const LocalMessage& library : statements.material_libraries) read_libraries(library, directory, &table);
  // Each usemtl name's material; an unknown name gets a default material of that name.
  std::unordered_map<std::string, uint32_t> by_name;
  for (uint32_t i = 0; i < table.materials.size(); ++i) by_name.emplace(table.materials[i].name, i);
  for (const LocalMessage& name : statements.material_names) {
    const auto [it, fresh] = by_name.emplace(name.text, static_cast<uint32_t>(table.materials.size()));
    if (fresh) {
      table.materials.push_back(Material{name.text});
      table.warnings.push_back(
          {name.line, "usemtl " + name.text + ": no material of that name in the material libraries (defaults used)"});
    }
    table.of_name.push_back(it->second);
  }
  return table;
}

}  // namespace pfx_obj

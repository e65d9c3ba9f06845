// The serial plan between the parallel parse and the parallel stages after it (obj_importer.hpp).
#include <filesystem>

#include "obj_file.hpp"
#include "obj_importer.hpp"

namespace pfx_obj {

namespace {

// Cuts "a.mtl b.mtl" into files; a name with blanks ("my materials.mtl") is taken whole when a
// file of that whole name exists.
std::vector<std::string> material_library_names(const std::string& directory, const std::string& text) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(resolve_path(directory, text), ec)) return {text};
  std::vector<std::string> names;
  std::string current;
  for (char c : text) {
    if (c == ' ' || c == '\t') {
      if (!current.empty()) names.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) names.push_back(current);
  return names;
}

}  // namespace

bool Importer::plan(std::string* error) {
  plans_.assign(chunks_.size(), ChunkPlan{});
  uint64_t line = 1, positions = 0, texcoords = 0, normals = 0, faces = 0;
  uint32_t material = kNoIndex, smoothing = kDefaultSmoothing;
  // The first error in file order; then every material library (in file order, before any
  // usemtl is looked up, as a usemtl may come before its mtllib).
  for (const ChunkData& chunk : chunks_) {
    if (chunk.failed) {
      *error = at(name_, line + chunk.error.line, chunk.error.text);
      return false;
    }
    line += chunk.line_ends;
  }
  line = 1;
  for (const ChunkData& chunk : chunks_) {
    for (const auto& library : chunk.material_libraries) load_material_library(line + library.line, library.text);
    line += chunk.line_ends;
  }
  line = 1;
  for (size_t c = 0; c < chunks_.size(); ++c) {
    const ChunkData& chunk = chunks_[c];
    ChunkPlan& plan = plans_[c];
    plan.first_line = line;
    plan.position_base = static_cast<uint32_t>(positions);
    plan.texcoord_base = static_cast<uint32_t>(texcoords);
    plan.normal_base = static_cast<uint32_t>(normals);
    plan.face_base = faces;
    plan.start_material = material;
    plan.start_smoothing = smoothing;
    for (size_t i = 0; i < chunk.material_names.size(); ++i)
      plan.material_slots.push_back(material_slot(chunk.material_names[i], line + chunk.material_name_lines[i]));
    for (const StateChange& change : chunk.changes) {
      if (change.kind == StateChange::kMaterial) material = plan.material_slots[change.value];
      else smoothing = change.value;
    }
    for (const LocalMessage& w : chunk.warnings) warn(line + w.line, w.text);
    extra_warnings_ += chunk.warning_total - chunk.warnings.size();
    for (const auto& [keyword, ignored] : chunk.ignored) {
      auto& total = ignored_[keyword];
      if (total.count == 0) {
        total.first_line = line + ignored.first_line;
        total.valid_obj = ignored.valid_obj;
      }
      total.count += ignored.count;
    }
    out_->lines_skipped += chunk.lines_skipped;
    out_->points_skipped += chunk.points_skipped;
    line += chunk.line_ends;
    positions += chunk.position_count();
    texcoords += chunk.texcoords.size() / 2;
    normals += chunk.normals.size() / 3;
    faces += chunk.face_count;
    any_colors_ |= !chunk.colors.empty();
    const uint64_t limit = static_cast<uint64_t>(kMaxWrittenIndex);
    if (positions > limit || texcoords > limit || normals > limit || faces > limit) {
      *error = name_ + ": more than 2^31 - 1 elements of one kind (v, vt, vn or f): too large";
      return false;
    }
  }
  totals_[0] = static_cast<uint32_t>(positions);
  totals_[1] = static_cast<uint32_t>(texcoords);
  totals_[2] = static_cast<uint32_t>(normals);
  out_->faces = faces;
  for (const auto& [keyword, ignored] : ignored_)
    warn(ignored.first_line, (ignored.valid_obj ? "'" + keyword + "' statements are not supported: "
                                                : "unknown statement '" + keyword + "': ") +
                                 std::to_string(ignored.count) + " ignored");
  if (faces == 0) warn(line > 1 ? line - 1 : 1, "no faces: the mesh is empty");
  return true;
}

void Importer::load_material_library(uint64_t line, const std::string& text) {
  if (directory_.empty()) {
    warn(line, "mtllib " + text + ": not read (the model was given as bytes without a file name)");
    return;
  }
  for (const std::string& file : material_library_names(directory_, text)) {
    const std::string path = resolve_path(directory_, file);
    std::string bytes, problem;
    if (!read_small_file(path, &bytes, &problem)) {
      warn(line, "mtllib: " + problem + " (materials keep their defaults)");
      continue;
    }
    std::vector<std::string> mtl_warnings;
    parse_mtl(bytes, path, std::filesystem::path(path).parent_path().string(), &out_->materials, &mtl_warnings);
    for (auto& w : mtl_warnings) warn(line, std::move(w));
  }
}

// The material a usemtl names; an unknown name gets a default material of that name.
uint32_t Importer::material_slot(const std::string& name, uint64_t line) {
  auto& materials = out_->materials;
  if (material_index_.size() < materials.size())  // the libraries' materials, indexed once
    for (size_t i = material_index_.size(); i < materials.size(); ++i)
      material_index_.emplace(materials[i].name, static_cast<uint32_t>(i));
  if (auto it = material_index_.find(name); it != material_index_.end()) return it->second;
  material_index_.emplace(name, static_cast<uint32_t>(materials.size()));
  materials.push_back(Material{});
  materials.back().name = name;
  warn(line, "usemtl " + name + ": no material of that name in the material libraries (defaults used)");
  return static_cast<uint32_t>(materials.size() - 1);
}

}  // namespace pfx_obj

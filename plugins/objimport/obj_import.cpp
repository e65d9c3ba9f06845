// The import pipeline: parse chunks in parallel, then merge them in file order.
//
//   1. parse      chunks in parallel (obj_chunk.cpp)
//   2. plan       serial: the first error, where each chunk's lines, elements, faces and corners
//                 start, the material libraries, the material and smoothing group in force at
//                 each chunk's start
//   3. resolve    chunks in parallel: indices to 0-based (relative ones too), range checks, each
//                 face's material and normal group, triangle counts per material
//   4. gather     vertex data of all chunks into single arrays
//   5. dedup      one vertex per distinct corner (obj_dedup.cpp)
//   6. triangles  chunks in parallel, each writing its triangles at precomputed offsets
//   7. normals    generated where the file gave none (obj_normals.cpp); bounds
//
// Nothing in the output depends on how the text was cut: vertices are numbered by first use,
// sub-meshes follow the first use of their material, triangles keep file order within one.
#include "obj_import.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include "obj_chunk.hpp"
#include "obj_dedup.hpp"
#include "obj_face_states.hpp"
#include "obj_file.hpp"
#include "obj_normals.hpp"
#include "obj_parallel.hpp"
#include "obj_split.hpp"
#include "obj_triangulate.hpp"

namespace pfx_obj {

namespace {

struct Located {
  uint64_t line;  // 1-based, in the OBJ file
  std::string text;
};

// What the serial plan knows of one chunk before the parallel stages use it.
struct ChunkPlan {
  uint64_t first_line = 1;
  uint32_t position_base = 0, texcoord_base = 0, normal_base = 0;
  uint64_t face_base = 0, corner_base = 0;
  uint32_t start_material = kNoIndex;  // material slot in force at the chunk's start
  uint32_t start_smoothing = kDefaultSmoothing;
  std::vector<uint32_t> material_slots;  // chunk material name index -> material slot
  uint32_t start_slot = 0;  // start_material, or the no-material slot (set by the resolve stage)
};

// What the resolve stage makes of one chunk.
struct ChunkFaces {
  std::vector<uint64_t> triangle_counts;  // per material slot
  std::vector<uint64_t> first_use;        // per material slot: the file ordinal of its first face
  bool failed = false;
  Located error;
  std::vector<Located> warnings;
  uint64_t warning_total = 0;
};

std::string at(const std::string& name, uint64_t line, const std::string& text) {
  return name + ":" + std::to_string(line) + ": " + text;
}

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

class Importer {
 public:
  Importer(const std::string& name, const std::string& directory, const ImportOptions& options)
      : name_(name), directory_(directory), options_(options) {
    threads_ = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  }

  bool run(std::string_view text, ObjMesh* out, std::string* error) {
    out_ = out;
    *out = ObjMesh{};
    StageClock clock(&out->stages);
    report(0.0f);
    clock.time("parse", true, [&] { parse(text); });
    bool ok = true;
    clock.time("plan", false, [&] { ok = plan(error); });
    if (!ok) return false;
    clock.time("resolve", true, [&] { resolve_all(); });
    if (!first_resolve_error(error)) return false;
    clock.time("gather", true, [&] { gather(); });
    report(0.7f);
    deduplicate_corners(&clock);
    report(0.85f);
    clock.time("triangles", true, [&] { build_triangles(); });
    clock.time("vertices", true, [&] { fill_vertices(); });
    clock.time("normals", true, [&] { generate_normals(keys_, out_->positions, out_->indices, threads_, &out_->normals); });
    clock.time("bounds, warnings", false, [&] { finish(); });
    report(1.0f);
    return true;
  }

 private:
  void report(float fraction) {
    if (options_.progress) options_.progress(fraction);
  }

  void parse(std::string_view text) {
    size_t chunk_bytes = options_.chunk_bytes;
    if (chunk_bytes == 0) chunk_bytes = std::clamp<size_t>(text.size() / (size_t{threads_} * 8), 1 << 20, 32 << 20);
    texts_ = split_at_line_ends(text, std::max<size_t>(1, (text.size() + chunk_bytes - 1) / chunk_bytes));
    chunks_.assign(texts_.size(), ChunkData{});
    std::atomic<size_t> bytes_done{0};
    const double total = std::max<size_t>(1, text.size());
    run_parallel(
        threads_, texts_.size(),
        [&](size_t c, unsigned) {
          parse_chunk(texts_[c], c == 0, options_.plain_lines, &chunks_[c]);
          bytes_done += texts_[c].size();
        },
        [&] { report(static_cast<float>(0.6 * bytes_done.load() / total)); });
  }

  void warn(uint64_t line, std::string text) { warnings_.push_back({line, std::move(text)}); }

  bool plan(std::string* error) {
    plans_.assign(chunks_.size(), ChunkPlan{});
    uint64_t line = 1, positions = 0, texcoords = 0, normals = 0, faces = 0, corners = 0;
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
      plan.corner_base = corners;
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
      faces += chunk.faces.size();
      corners += chunk.corners.size() / 3;
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

  void load_material_library(uint64_t line, const std::string& text) {
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
  uint32_t material_slot(const std::string& name, uint64_t line) {
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

  void resolve_all() {
    faces_.assign(chunks_.size(), ChunkFaces{});
    const size_t slots = out_->materials.size() + 1;  // the last slot: no material
    run_parallel(threads_, chunks_.size(), [&](size_t c, unsigned) { resolve(c, slots); });
  }

  void resolve(size_t c, size_t slots) {
    ChunkData& chunk = chunks_[c];
    ChunkPlan& plan = plans_[c];
    ChunkFaces& result = faces_[c];
    plan.start_slot = plan.start_material == kNoIndex ? static_cast<uint32_t>(slots - 1) : plan.start_material;
    result.triangle_counts.assign(slots, 0);
    result.first_use.assign(slots, ~uint64_t{0});
    for (size_t m = 0; m < chunk.triangles_by_material.size(); ++m) {
      if (chunk.first_face_by_material[m] == ChunkData::kNoFace) continue;
      const uint32_t slot = m == 0 ? plan.start_slot : plan.material_slots[m - 1];
      result.triangle_counts[slot] += chunk.triangles_by_material[m];
      result.first_use[slot] = std::min(result.first_use[slot], plan.face_base + chunk.first_face_by_material[m]);
    }
    // Positive indices are stored final: only relative ones, or an index past the file's last
    // element (an error), need a walk over the corners.
    if (chunk.relative_fields.empty() && chunk.max_index[0] <= totals_[0] && chunk.max_index[1] <= totals_[1] &&
        chunk.max_index[2] <= totals_[2])
      return;
    const char* kinds[3] = {"v", "vt", "vn"};
    const uint32_t bases[3] = {plan.position_base, plan.texcoord_base, plan.normal_base};
    uint64_t field = 0;
    for (size_t f = 0; f < chunk.faces.size(); ++f) {
      const Face& face = chunk.faces[f];
      for (uint32_t k = 0; k < face.corner_count; ++k) {
        for (int j = 0; j < 3; ++j, ++field) {
          uint32_t& value = chunk.corners[field];
          // A relative index may be stored as kNoIndex (-1: it reaches two elements back before
          // the chunk): only a field not marked relative can mean "absent".
          const bool relative = field / 64 < chunk.relative_fields.size() &&
                                (chunk.relative_fields[field / 64] >> (field % 64) & 1);
          if (!relative && value == kNoIndex) continue;
          const int64_t one_based = relative ? int64_t{bases[j]} + static_cast<int32_t>(value) : int64_t{value} + 1;
          if (relative && one_based < 1) {
            result.failed = true;
            result.error = {plan.first_line + face.line,
                            std::string("f: relative ") + kinds[j] + " index reaches before the first " + kinds[j]};
            return;
          }
          if (one_based > totals_[j]) {
            result.failed = true;
            result.error = {plan.first_line + face.line,
                            totals_[j] == 0 ? std::string("f: ") + kinds[j] + " index " + std::to_string(one_based) +
                                                  " but the file has no " + kinds[j]
                                            : std::string("f: ") + kinds[j] + " index " + std::to_string(one_based) +
                                                  " is out of range (the file has " + std::to_string(totals_[j]) +
                                                  " " + kinds[j] + ")"};
            return;
          }
          value = static_cast<uint32_t>(one_based - 1);
        }
      }
    }
    chunk.relative_fields = {};
  }

  // The material slot and normal group of chunk c's faces, walked in order.
  FaceStates face_states(size_t c) const {
    const ChunkPlan& plan = plans_[c];
    return FaceStates(&chunks_[c].changes, &plan.material_slots, plan.start_slot, plan.start_smoothing, plan.face_base);
  }

  bool first_resolve_error(std::string* error) {
    for (const ChunkFaces& f : faces_)
      if (f.failed) {
        *error = at(name_, f.error.line, f.error.text);
        return false;
      }
    return true;
  }

  // One array per kind of vertex data, chunk arrays copied in at their bases in parallel, each
  // chunk's freed as soon as it is copied.
  void gather() {
    uint64_t position_total = totals_[0];
    all_positions_.resize(3 * position_total);
    all_texcoords_.resize(2 * size_t{totals_[1]});
    all_normals_.resize(3 * size_t{totals_[2]});
    if (any_colors_) all_colors_.resize(3 * position_total);
    run_parallel(threads_, chunks_.size(), [&](size_t c, unsigned) {
      ChunkData& chunk = chunks_[c];
      const ChunkPlan& plan = plans_[c];
      auto copy = [](BigVector<float>& from, BigVector<float>& to, size_t at) {
        if (!from.empty()) std::memcpy(&to[at], from.data(), from.size() * sizeof(float));
        from = {};
      };
      if (any_colors_) {
        if (chunk.colors.empty()) std::fill_n(&all_colors_[3 * size_t{plan.position_base}], chunk.positions.size(), 1.0f);
        copy(chunk.colors, all_colors_, 3 * size_t{plan.position_base});
      }
      copy(chunk.positions, all_positions_, 3 * size_t{plan.position_base});
      copy(chunk.texcoords, all_texcoords_, 2 * size_t{plan.texcoord_base});
      copy(chunk.normals, all_normals_, 3 * size_t{plan.normal_base});
    });
  }

  void deduplicate_corners(StageClock* clock) {
    std::vector<DedupChunk> inputs(chunks_.size());
    for (size_t c = 0; c < chunks_.size(); ++c) {
      inputs[c].corners = chunks_[c].corners.data();
      inputs[c].corner_count = chunks_[c].corners.size() / 3;
      inputs[c].faces = chunks_[c].faces.data();
      inputs[c].face_count = chunks_[c].faces.size();
      inputs[c].states = face_states(c);
    }
    deduplicate(inputs, totals_[0], threads_, &keys_, &corner_vertex_, clock);
  }

  void build_triangles();
  void fill_vertices();
  void finish();

  const std::string& name_;
  const std::string& directory_;
  const ImportOptions& options_;
  unsigned threads_ = 1;
  ObjMesh* out_ = nullptr;
  std::vector<std::string_view> texts_;
  std::vector<ChunkData> chunks_;
  std::vector<ChunkPlan> plans_;
  std::vector<ChunkFaces> faces_;
  uint32_t totals_[3] = {0, 0, 0};
  bool any_colors_ = false;
  std::vector<Located> warnings_;
  uint64_t extra_warnings_ = 0;  // warnings the chunks counted but did not keep
  std::map<std::string, IgnoredKeyword> ignored_;
  std::unordered_map<std::string, uint32_t> material_index_;  // material name -> index in out_->materials
  BigVector<float> all_positions_, all_texcoords_, all_normals_, all_colors_;
  BigVector<VertexKey> keys_;
  std::vector<BigVector<uint32_t>> corner_vertex_;
};

void Importer::build_triangles() {
  const size_t slots = out_->materials.size() + 1;
  // Sub-meshes in order of their material's first face.
  std::vector<uint64_t> triangles(slots, 0), first_use(slots, ~uint64_t{0});
  for (const ChunkFaces& f : faces_)
    for (size_t s = 0; s < slots; ++s) {
      triangles[s] += f.triangle_counts[s];
      first_use[s] = std::min(first_use[s], f.first_use[s]);
    }
  std::vector<uint32_t> order;
  for (uint32_t s = 0; s < slots; ++s)
    if (triangles[s] > 0) order.push_back(s);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return first_use[a] < first_use[b]; });
  std::vector<uint64_t> start(slots, 0);
  uint64_t index_total = 0;
  for (uint32_t s : order) {
    start[s] = index_total;
    index_total += 3 * triangles[s];
  }
  if (index_total > 0xFFFFFFFFull) throw std::length_error(name_ + ": more than 2^32 - 1 triangle indices");
  for (uint32_t s : order)
    out_->submeshes.push_back({static_cast<uint32_t>(start[s]), static_cast<uint32_t>(3 * triangles[s]),
                               s == slots - 1 ? kNoIndex : s});
  std::vector<std::vector<uint64_t>> write_at(chunks_.size());
  for (size_t c = 0; c < chunks_.size(); ++c) {
    write_at[c] = start;
    for (size_t s = 0; s < slots; ++s) start[s] += 3 * faces_[c].triangle_counts[s];
  }
  out_->indices.resize(index_total);

  run_parallel(threads_, chunks_.size(), [&](size_t c, unsigned) {
    const ChunkData& chunk = chunks_[c];
    ChunkFaces& result = faces_[c];
    const uint32_t* vertex = corner_vertex_[c].data();
    uint32_t* indices = out_->indices.data();
    std::vector<uint64_t>& at = write_at[c];
    TriangulationScratch scratch;
    std::vector<const float*> corner_positions;
    std::vector<uint32_t> polygon;
    FaceStates states = face_states(c);
    uint64_t corner = 0;
    for (size_t f = 0; f < chunk.faces.size(); ++f) {
      const uint32_t n = chunk.faces[f].corner_count;
      states.at_face(f);
      uint64_t& cursor = at[states.slot()];
      if (n == 3) {
        indices[cursor] = vertex[corner];
        indices[cursor + 1] = vertex[corner + 1];
        indices[cursor + 2] = vertex[corner + 2];
        cursor += 3;
        corner += 3;
        continue;
      }
      corner_positions.resize(n);
      for (uint32_t k = 0; k < n; ++k)
        corner_positions[k] = &all_positions_[3 * size_t{chunk.corners[3 * (corner + k)]}];
      polygon.clear();
      Triangulation how = triangulate_polygon(corner_positions.data(), n, &polygon, &scratch);
      for (uint32_t k : polygon) indices[cursor++] = vertex[corner + k];
      corner += n;
      if (how != Triangulation::kEarClipped) {
        const char* why = how == Triangulation::kFanDegenerate      ? "has no area"
                          : how == Triangulation::kFanTooLarge      ? "is too large for ear clipping (over 4096 corners)"
                                                                    : "is self-intersecting";
        ++result.warning_total;
        if (result.warnings.size() < kMaxWarnings)
          result.warnings.push_back({plans_[c].first_line + chunk.faces[f].line,
                                     "f: polygon of " + std::to_string(n) + " corners " + why +
                                         ": triangulated as a fan"});
      }
    }
  });
  for (ChunkFaces& f : faces_) {
    for (Located& w : f.warnings) warnings_.push_back(std::move(w));
    extra_warnings_ += f.warning_total - f.warnings.size();
  }
  chunks_ = {};
  corner_vertex_ = {};
  faces_ = {};
}

void Importer::fill_vertices() {
  const size_t count = keys_.size();
  const bool any_texcoords = std::any_of(keys_.begin(), keys_.end(), [](const VertexKey& k) { return k.vt != kNoIndex; });
  out_->positions.resize(3 * count);
  out_->normals.resize(3 * count);
  if (any_texcoords) out_->texcoords.resize(2 * count);
  if (any_colors_) out_->colors.resize(3 * count);
  run_parallel(threads_, threads_, [&](size_t w, unsigned) {
    const size_t lo = count * w / threads_, hi = count * (w + 1) / threads_;
    for (size_t i = lo; i < hi; ++i) {
      const VertexKey& key = keys_[i];
      std::memcpy(&out_->positions[3 * i], &all_positions_[3 * size_t{key.v}], 3 * sizeof(float));
      if (any_colors_) std::memcpy(&out_->colors[3 * i], &all_colors_[3 * size_t{key.v}], 3 * sizeof(float));
      if (any_texcoords) {
        if (key.vt != kNoIndex) std::memcpy(&out_->texcoords[2 * i], &all_texcoords_[2 * size_t{key.vt}], 2 * sizeof(float));
        else out_->texcoords[2 * i] = out_->texcoords[2 * i + 1] = 0.0f;
      }
      if (key.vn != kNoIndex) std::memcpy(&out_->normals[3 * i], &all_normals_[3 * size_t{key.vn}], 3 * sizeof(float));
    }
  });
  all_positions_ = {};
  all_texcoords_ = {};
  all_normals_ = {};
  all_colors_ = {};
}

void Importer::finish() {
  keys_ = {};
  const size_t count = out_->vertex_count();
  if (count > 0) {
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
    for (size_t i = 0; i < count; ++i)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], out_->positions[3 * i + k]);
        hi[k] = std::max(hi[k], out_->positions[3 * i + k]);
      }
    std::copy(lo, lo + 3, out_->bounds_min);
    std::copy(hi, hi + 3, out_->bounds_max);
  }

  std::stable_sort(warnings_.begin(), warnings_.end(), [](const Located& a, const Located& b) { return a.line < b.line; });
  out_->warning_total = warnings_.size() + extra_warnings_;
  for (size_t i = 0; i < warnings_.size() && i < kMaxWarnings; ++i)
    out_->warnings.push_back(at(name_, warnings_[i].line, warnings_[i].text));
}

}  // namespace

bool import_obj_text(std::string_view text, const std::string& name, const std::string& directory,
                     const ImportOptions& options, ObjMesh* out, std::string* error) {
  try {
    return Importer(name, directory, options).run(text, out, error);
  } catch (const std::bad_alloc&) {
    *error = name + ": out of memory";
  } catch (const std::exception& e) {
    *error = std::string(e.what()).rfind(name, 0) == 0 ? e.what() : name + ": " + e.what();
  }
  *out = ObjMesh{};
  return false;
}

bool import_obj_file(const std::string& path, const ImportOptions& options, ObjMesh* out, std::string* error) {
  FileBytes file;
  if (!file.open(path, error)) return false;
  const std::string directory = std::filesystem::path(path).parent_path().string();
  return import_obj_text(file.bytes(), path, directory.empty() ? "." : directory, options, out, error);
}

}  // namespace pfx_obj

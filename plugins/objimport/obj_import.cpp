// The OBJ importer, top to bottom. An import runs these stages in order (Importer::run):
//
//   1. cut      the text into chunks at line ends (split_at_line_ends, obj_reader.cpp)
//   2. read     each chunk on any worker (obj_reader.cpp: the grammar, into obj_chunk.hpp's data),
//      number  and, in file order as soon as it and every chunk before it are read, its vertex
//               data appended to the file's and its faces written as triangles of vertex numbers:
//               each corner numbered against one vertex numbering for the whole file
//               (obj_dedup.hpp), relative indices made final, polygons ear-clipped
//               (obj_triangulate.cpp). The workers read later chunks while one numbers
//               (obj_parallel.hpp), so the numbers never depend on the thread count.
//   3. check    indices against the file's totals; polygons that reached past the positions read
//               so far clipped; material libraries read (obj_mtl.cpp)
//   4. index    sub-meshes in order of their material's first use, each chunk's triangles copied
//               to their material's place
//   5. vertices the vertex arrays from the numbered keys, and the bounds
//   6. normals  where the file gives none (obj_normals.hpp)
//   7. warnings in line order
//
// The file comes mapped (obj_file.hpp); large arrays are obj_buffer.hpp's. Parallel stages run on
// the host's thread pool (obj_parallel.hpp); without one, on the calling thread.
#include "obj_import.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include "obj_chunk.hpp"
#include "obj_dedup.hpp"
#include "obj_file.hpp"
#include "obj_normals.hpp"
#include "obj_parallel.hpp"
#include "obj_triangulate.hpp"

namespace pfx_obj {

namespace {

// Cuts "a.mtl b.mtl" into files; a name with blanks ("my materials.mtl") is taken whole when a
// file of that whole name exists.
std::vector<std::string> material_library_names(const std::string& directory, const std::string& text) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(resolve_path(directory, text), ec)) return {text};
  std::vector<std::string> names;
  size_t start = 0;
  while ((start = text.find_first_not_of(" \t", start)) != std::string::npos) {
    const size_t end = std::min(text.find_first_of(" \t", start), text.size());
    names.push_back(text.substr(start, end - start));
    start = end;
  }
  return names;
}

// Room for `most` elements when that is at most an eighth of the machine's memory (address space
// only, never copied: the kernel refuses mappings much larger than memory), else none: the array
// then doubles as it grows.
uint64_t room_for(uint64_t most, size_t element_bytes) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 && most * element_bytes <= uint64_t(pages) * uint64_t(page) / 8 ? most : 0;
}

class Importer {
 public:
  static constexpr size_t kBlock = size_t{1} << 15;  // vertices per parallel task

  // file: where the text is a file's mapping, whose pages each chunk drops once read.
  Importer(const std::string& name, const std::string& directory, const ImportOptions& options,
           const FileBytes* file, ObjMesh* out)
      : name_(name), directory_(directory), options_(options), threads_(worker_count(options.pool, options.threads)),
        file_(file), out_(out) {}

  bool run(std::string_view text, std::string* error) {
    report(0.0f);
    if (!read_and_number(text, error) || !check_indices(error)) return false;
    clip_deferred_polygons();
    load_materials();
    report(0.7f);
    write_index_array();
    free_array(&chunks_);
    report(0.85f);
    fill_vertices();
    generate_normals(numbering_.keys(), out_->positions, out_->indices, options_.pool, threads_, &out_->normals);
    free_array(&numbering_.keys());
    finish_warnings();
    report(1.0f);
    return true;
  }

 private:
  // What the file before a chunk set up for it, found when the chunk is numbered.
  struct ChunkStart {
    uint64_t line = 1;
    uint32_t bases[3] = {0, 0, 0};  // v, vt and vn before the chunk
    uint64_t face = 0;              // the file ordinal of its first face
    uint64_t triangle = 0;          // where its triangles start in triangles_
    uint32_t material = kNoIndex;   // the usemtl name in force (index into names_), or none
    uint32_t smoothing = kDefaultSmoothing;
    bool suspect = false;           // it may hold an index the file cannot satisfy
  };

  void report(float fraction) { if (options_.progress) options_.progress(fraction); }
  void warn(uint64_t line, std::string text) { warnings_.push_back({line, std::move(text)}); }
  std::string at(uint64_t line, const std::string& text) const { return name_ + ":" + std::to_string(line) + ": " + text; }

  size_t chunk_count(size_t bytes) const {
    if (options_.chunk_bytes > 0) return std::max<size_t>(1, (bytes + options_.chunk_bytes - 1) / options_.chunk_bytes);
    // About eight chunks per thread of 1 to 4 MB, their count a multiple of the thread count so the
    // threads finish together.
    const size_t chunk_bytes = std::clamp<size_t>(bytes / (size_t{threads_} * 8), 1 << 20, 4 << 20);
    size_t chunks = (bytes + chunk_bytes - 1) / chunk_bytes;
    if (chunks > 1) chunks = (chunks + threads_ - 1) / threads_ * threads_;
    return std::max<size_t>(1, chunks);
  }

  // Stage 2. A chunk's vertex data, corners and faces are read into the arrays of one of a few
  // slots and go back to it once numbered, so later chunks reuse pages already written instead of
  // fresh ones.
  bool read_and_number(std::string_view text, std::string* error) {
    // Room, in address space only (obj_buffer.hpp), for the most the text can hold ("v 0 0 0",
    // "vt 0", "vn 0 0 0") and for what files hold: a vertex per position, a triangle index per byte
    // (a quad "f 1 2 3 4" holds 0.6). Past that (vertices split by seams, polygons of many short
    // corners) an array grows by copying.
    const size_t bytes = text.size();
    positions_.reserve(room_for(3 * (bytes / 8 + 1), sizeof(float)));
    texcoords_.reserve(room_for(2 * (bytes / 5 + 1), sizeof(float)));
    normals_.reserve(room_for(3 * (bytes / 9 + 1), sizeof(float)));
    triangles_.reserve(room_for(bytes + 3, sizeof(uint32_t)));
    numbering_.reserve(room_for(bytes / 8 + 1, sizeof(VertexKey) + 4), room_for(bytes / 8 + 1, 4));
    texts_ = split_at_line_ends(text, chunk_count(bytes));
    const size_t count = texts_.size();
    chunks_.resize(count);
    starts_.resize(count + 1);
    size_t largest = 0;
    for (std::string_view chunk : texts_) largest = std::max(largest, chunk.size());
    const size_t window = threads_;  // chunks between reading and numbering: one per worker
    std::vector<ChunkData> slots(window);  // only their arrays are used
    const std::thread::id caller = std::this_thread::get_id();
    uint64_t bytes_numbered = 0;  // (one in-order job at a time)
    auto read = [&](size_t c, unsigned) {
      swap_arrays(&chunks_[c], &slots[c % window]);
      parse_chunk(texts_[c], c == 0, &chunks_[c], largest);
      if (file_) file_->drop_pages(texts_[c]);
    };
    auto number = [&](size_t c) {
      if (!number_chunk(c, text.size(), error)) return false;
      swap_arrays(&chunks_[c], &slots[c % window]);
      bytes_numbered += texts_[c].size();
      if (std::this_thread::get_id() == caller) report(static_cast<float>(0.6 * double(bytes_numbered) / double(bytes)));
      return true;
    };
    run_ordered_jobs(options_.pool, threads_, count, window, read, number);
    numbering_.finish();
    return error->empty();
  }

  // A chunk's large arrays swapped with a slot's.
  static void swap_arrays(ChunkData* a, ChunkData* b) {
    a->positions.swap(b->positions);
    a->texcoords.swap(b->texcoords);
    a->normals.swap(b->normals);
    a->corners.swap(b->corners);
    a->faces.swap(b->faces);
  }

  // Chunk c's vertex data appended to the file's (colours: white for a v without one, once any v
  // has one).
  void append_vertex_data(size_t c) {
    const ChunkData& chunk = chunks_[c];
    positions_.insert(positions_.end(), chunk.positions.begin(), chunk.positions.end());
    texcoords_.insert(texcoords_.end(), chunk.texcoords.begin(), chunk.texcoords.end());
    normals_.insert(normals_.end(), chunk.normals.begin(), chunk.normals.end());
    if (!chunk.colors.empty() && colors_.empty()) colors_.assign(3 * size_t{starts_[c].bases[0]}, 1.0f);
    if (chunk.colors.empty() && !colors_.empty()) colors_.resize(positions_.size(), 1.0f);
    colors_.insert(colors_.end(), chunk.colors.begin(), chunk.colors.end());
  }

  // Chunk c, read, after every chunk before it: its faces numbered into triangles_, and
  // starts_[c + 1] set from starts_[c]. False with *error at the first chunk that failed to read.
  bool number_chunk(size_t c, uint64_t text_bytes, std::string* error) {
    ChunkData& chunk = chunks_[c];
    ChunkStart& start = starts_[c];
    if (!chunk.error.text.empty()) {
      *error = at(start.line + chunk.error.line, chunk.error.text);
      return false;
    }
    ChunkStart& next = starts_[c + 1];
    const uint64_t totals[4] = {start.bases[0] + chunk.positions.size() / 3, start.bases[1] + chunk.texcoords.size() / 2,
                                start.bases[2] + chunk.normals.size() / 3, start.face + chunk.faces.size()};
    if (*std::max_element(totals, totals + 4) > uint64_t(kMaxWrittenIndex)) {
      *error = name_ + ": more than 2^31 - 1 elements of one kind (v, vt, vn or f): too large";
      return false;
    }
    std::copy(totals, totals + 3, next.bases);
    next.line = start.line + chunk.line_ends;
    next.face = start.face + chunk.faces.size();
    next.triangle = start.triangle + chunk.triangles;
    if (3 * next.triangle > kNoIndex) throw std::length_error(name_ + ": more than 2^32 - 1 triangle indices");
    collect_statements(c);
    append_vertex_data(c);

    // An index past what the rest of the text could still define cannot be satisfied: from the
    // chunk that may hold one, none is numbered and check_indices finds it. (A position index
    // sizes an array here.)
    const uint64_t bytes_left = text_bytes - static_cast<uint64_t>(texts_[c].data() + texts_[c].size() - texts_[0].data());
    start.suspect |= chunk.max_index[0] > next.bases[0] + bytes_left / 8 + 1;
    any_suspect_ |= start.suspect;
    if (!any_suspect_) {
      triangles_.resize(3 * next.triangle);
      numbering_.cover(std::max(next.bases[0], chunk.max_index[0]));
      any_suspect_ = start.suspect = !number_faces(c, triangles_.data() + 3 * start.triangle);
    }
    free_array(&chunk.relative_fields);
    return true;
  }

  // Chunk c's faces as triangles of vertex numbers, into `out`. Each corner is numbered in order,
  // its relative indices made final first (false when one reaches before the first element); a
  // corner without a normal is keyed by its face's normal group: its smoothing group, or the face
  // itself when smoothing is off. A polygon is ear-clipped, or, when a corner's position comes
  // later in the file, cut as a fan for now and clipped once every chunk is read.
  bool number_faces(size_t c, uint32_t* out) {
    const ChunkData& chunk = chunks_[c];
    const ChunkStart& start = starts_[c];
    const uint32_t* bases = start.bases;
    const uint32_t positions_read = starts_[c + 1].bases[0];
    const bool any_relative = !chunk.relative_fields.empty();
    uint32_t smoothing = start.smoothing;
    uint64_t field = 0;
    size_t change = 0;
    for (size_t f = 0; f < chunk.faces.size(); ++f) {
      for (; change < chunk.changes.size() && chunk.changes[change].first_face == f; ++change)
        if (chunk.changes[change].kind == StateChange::kSmoothing) smoothing = chunk.changes[change].value;
      const uint32_t group = smoothing == 0 ? kFlatFaceBit | static_cast<uint32_t>(start.face + f) : smoothing;
      const uint32_t n = chunk.faces[f].corner_count;
      if (n > 3) polygon_.resize(n), corners_.resize(n);
      uint32_t* ids = n == 3 ? out : polygon_.data();
      bool all_read = true;
      for (uint32_t k = 0; k < n; ++k) {
        uint32_t index[3];
        for (int kind = 0; kind < 3; ++kind, ++field) {
          index[kind] = chunk.corners[field];
          if (!any_relative || !chunk.is_relative(field)) continue;
          const int64_t one_based = int64_t{bases[kind]} + static_cast<int32_t>(index[kind]);
          if (one_based < 1) return false;
          index[kind] = static_cast<uint32_t>(one_based - 1);
        }
        ids[k] = numbering_.find_or_insert({index[0], index[1], index[2], index[2] == kNoIndex ? group : 0});
        if (n > 3 && (all_read &= index[0] < positions_read)) corners_[k] = &positions_[3 * size_t{index[0]}];
      }
      if (n == 3) {
        out += 3;
      } else if (all_read) {
        out = clip(ids, corners_.data(), n, start.line + chunk.faces[f].line, out);
      } else {
        deferred_.push_back({static_cast<uint64_t>(out - triangles_.data()), n, start.line + chunk.faces[f].line});
        for (uint32_t k = 1; k + 1 < n; ++k) *out++ = ids[0], *out++ = ids[k], *out++ = ids[k + 1];
      }
    }
    return true;
  }

  // Polygon `ids` (n vertex numbers, their positions at `corners`) as n - 2 triangles from `out` on,
  // with a warning at `line` when it had to be cut as a fan. Returns the end of what it wrote.
  uint32_t* clip(const uint32_t* ids, const float* const* corners, uint32_t n, uint64_t line, uint32_t* out) {
    clipped_.clear();
    const Triangulation how = triangulate_polygon(corners, n, &clipped_, &scratch_);
    for (uint32_t k : clipped_) *out++ = ids[k];
    if (how != Triangulation::kEarClipped)
      warn(line, "f: polygon of " + std::to_string(n) + " corners " +
                     (how == Triangulation::kFanDegenerate  ? "has no area"
                      : how == Triangulation::kFanTooLarge ? "is too large for ear clipping (over 4096 corners)"
                                                           : "is self-intersecting") +
                     ": triangulated as a fan");
    return out;
  }

  // The polygons cut as fans while a corner's position was still to come, clipped now. A fan
  // (0 1 2) (0 2 3) ... holds the polygon's corners 0 and 1, then one in each triangle's third place.
  void clip_deferred_polygons() {
    for (const DeferredPolygon& polygon : deferred_) {
      uint32_t* fan = triangles_.data() + polygon.at;
      polygon_.assign({fan[0], fan[1]});
      for (uint32_t k = 0; k + 2 < polygon.corners; ++k) polygon_.push_back(fan[3 * k + 2]);
      corners_.resize(polygon.corners);
      for (uint32_t k = 0; k < polygon.corners; ++k) corners_[k] = &positions_[3 * size_t{numbering_.keys()[polygon_[k]].v}];
      clip(polygon_.data(), corners_.data(), polygon.corners, polygon.line, fan);
    }
  }

  // Chunk c's other statements: the state in force after it, its usemtl names (each change's value
  // made an index into names_), material libraries and skipped statements.
  void collect_statements(size_t c) {
    ChunkData& chunk = chunks_[c];
    ChunkStart& start = starts_[c];
    ChunkStart& next = starts_[c + 1];
    std::vector<uint32_t> file_names;  // per chunk-local name
    for (const LocalMessage& name : chunk.material_names) {
      auto [it, fresh] = name_index_.emplace(name.text, static_cast<uint32_t>(names_.size()));
      if (fresh) names_.push_back({start.line + name.line, name.text});
      file_names.push_back(it->second);
    }
    next.material = start.material;
    next.smoothing = start.smoothing;
    for (StateChange& change : chunk.changes) {
      if (change.kind == StateChange::kMaterial) next.material = change.value = file_names[change.value];
      else next.smoothing = change.value;
    }
    for (const LocalMessage& library : chunk.material_libraries)
      libraries_.push_back({start.line + library.line, library.text});
    for (const auto& [keyword, ignored] : chunk.ignored) {
      IgnoredKeyword& total = ignored_[keyword];
      if (total.count == 0) total = {start.line + ignored.first_line, 0, ignored.valid_obj};
      total.count += ignored.count;
    }
    out_->lines_skipped += chunk.lines_skipped;
    out_->points_skipped += chunk.points_skipped;
  }

  // Stage 3. Every index within the file's totals; the first that is not, in file order, is the
  // error. Chunks that may hold one are read again here (an error path only).
  bool check_indices(std::string* error) {
    const size_t count = chunks_.size();
    const uint32_t* totals = starts_[count].bases;
    for (size_t c = 0; c < count; ++c) {
      for (int k = 0; k < 3; ++k) starts_[c].suspect |= chunks_[c].max_index[k] > totals[k];
      if (!starts_[c].suspect) continue;
      ChunkData chunk;
      parse_chunk(texts_[c], c == 0, &chunk);
      uint64_t field = 0;
      for (const Face& face : chunk.faces)
        for (uint32_t j = 0; j < 3 * face.corner_count; ++j, ++field) {
          const int kind = static_cast<int>(field % 3);
          const bool relative = chunk.is_relative(field);
          if (!relative && chunk.corners[field] == kNoIndex) continue;
          const int64_t one_based = relative ? int64_t{starts_[c].bases[kind]} + static_cast<int32_t>(chunk.corners[field])
                                             : int64_t{chunk.corners[field]} + 1;
          if (one_based >= 1 && one_based <= totals[kind]) continue;
          const std::string k = kind == 0 ? "v" : kind == 1 ? "vt" : "vn", n = std::to_string(one_based);
          const std::string why = one_based < 1 ? "relative " + k + " index reaches before the first " + k
                                  : totals[kind] == 0 ? k + " index " + n + " but the file has no " + k
                                  : k + " index " + n + " is out of range (the file has " + std::to_string(totals[kind]) + " " + k + ")";
          *error = at(starts_[c].line + face.line, "f: " + why);
          return false;
        }
    }
    return true;
  }

  void load_materials() {
    // Every library first, in file order: a usemtl may come before its mtllib.
    for (const LocalMessage& library : libraries_) {
      if (directory_.empty()) {
        warn(library.line, "mtllib " + library.text + ": not read (the model was given as bytes without a file name)");
        continue;
      }
      for (const std::string& name : material_library_names(directory_, library.text)) {
        const std::string path = resolve_path(directory_, name);
        FileBytes file;
        std::string problem;
        if (!file.open(path, &problem)) {
          warn(library.line, "mtllib: " + problem + " (materials keep their defaults)");
          continue;
        }
        std::vector<std::string> mtl_warnings;
        parse_mtl(file.bytes(), path, std::filesystem::path(path).parent_path().string(), &out_->materials, &mtl_warnings);
        for (auto& w : mtl_warnings) warn(library.line, std::move(w));
      }
    }
    // Each usemtl name's material; an unknown name gets a default material of that name.
    std::unordered_map<std::string, uint32_t> by_name;
    for (size_t i = 0; i < out_->materials.size(); ++i)
      by_name.emplace(out_->materials[i].name, static_cast<uint32_t>(i));
    for (const LocalMessage& name : names_) {
      auto [it, fresh] = by_name.emplace(name.text, static_cast<uint32_t>(out_->materials.size()));
      if (fresh) {
        out_->materials.push_back(Material{name.text});
        warn(name.line, "usemtl " + name.text + ": no material of that name in the material libraries (defaults used)");
      }
      name_slots_.push_back(it->second);
    }
  }

  // The slot of a usemtl name (index into names_): its material's index, or the last slot for none.
  uint32_t slot_of(uint32_t name) const {
    return name == kNoIndex ? static_cast<uint32_t>(out_->materials.size()) : name_slots_[name];
  }

  // run(slot, first, end) for each run of chunk c's triangles of one material, in order: the
  // triangles [first, end) of triangles_.
  template <typename Run>
  void for_each_run(size_t c, Run run) const {
    const uint64_t base = starts_[c].triangle;
    uint32_t slot = slot_of(starts_[c].material);
    uint64_t first = base;
    for (const StateChange& change : chunks_[c].changes) {
      if (change.kind != StateChange::kMaterial) continue;
      if (base + change.first_triangle > first) run(slot, first, base + change.first_triangle);
      slot = slot_of(change.value);
      first = base + change.first_triangle;
    }
    if (starts_[c + 1].triangle > first) run(slot, first, starts_[c + 1].triangle);
  }

  // Stage 4. Sub-meshes in order of their material's first triangle, each run of triangles copied
  // to its material's place.
  void write_index_array() {
    const size_t slots = out_->materials.size() + 1, count = chunks_.size();
    std::vector<uint64_t> triangles(slots, 0), first_use(slots, ~uint64_t{0});
    for (size_t c = 0; c < count; ++c)
      for_each_run(c, [&](uint32_t s, uint64_t first, uint64_t end) {
        triangles[s] += end - first;
        first_use[s] = std::min(first_use[s], first);
      });
    std::vector<uint32_t> order;
    for (uint32_t s = 0; s < slots; ++s)
      if (triangles[s] > 0) order.push_back(s);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return first_use[a] < first_use[b]; });
    std::vector<uint64_t> place(slots, 0);
    uint64_t total = 0;
    for (uint32_t s : order) {
      place[s] = total;
      total += 3 * triangles[s];
      out_->submeshes.push_back({static_cast<uint32_t>(place[s]), static_cast<uint32_t>(3 * triangles[s]),
                                 s == slots - 1 ? kNoIndex : s});
    }
    out_->faces = starts_[count].face;
    if (order.size() <= 1) {  // one material: the triangles as they are
      out_->indices.swap(triangles_);
      return;
    }
    out_->indices.resize(total);
    for (size_t c = 0; c < count; ++c)
      for_each_run(c, [&](uint32_t s, uint64_t first, uint64_t end) {
        std::memcpy(&out_->indices[place[s]], &triangles_[3 * first], 3 * (end - first) * sizeof(uint32_t));
        place[s] += 3 * (end - first);
      });
    free_array(&triangles_);
  }

  // Stage 5: each kind of vertex data gathered by the numbered keys, one kind at a time, the
  // file's array of that kind freed once gathered; then the bounds.
  void fill_vertices() {
    const BigVector<VertexKey>& keys = numbering_.keys();
    gather<3>(&positions_, &VertexKey::v, &out_->positions);
    if (!colors_.empty()) gather<3>(&colors_, &VertexKey::v, &out_->colors);
    if (std::any_of(keys.begin(), keys.end(), [](const VertexKey& k) { return k.vt != kNoIndex; }))
      gather<2>(&texcoords_, &VertexKey::vt, &out_->texcoords);
    gather<3>(&normals_, &VertexKey::vn, &out_->normals);  // those without are generated later
    for (BigVector<float>* data : {&positions_, &texcoords_, &normals_, &colors_}) free_array(data);
    if (keys.empty()) return;  // the bounds stay zero
    std::fill_n(out_->bounds_min, 3, HUGE_VALF);
    std::fill_n(out_->bounds_max, 3, -HUGE_VALF);
    for (size_t i = 0; i < out_->positions.size(); ++i) {
      out_->bounds_min[i % 3] = std::min(out_->bounds_min[i % 3], out_->positions[i]);
      out_->bounds_max[i % 3] = std::max(out_->bounds_max[i % 3], out_->positions[i]);
    }
  }

  // Each vertex's kWidth floats of `source` at the element its key's `field` names (zeros for
  // none), in blocks on every worker; `source` freed after.
  template <int kWidth>
  void gather(BigVector<float>* source, uint32_t VertexKey::*field, BigVector<float>* out) {
    const BigVector<VertexKey>& keys = numbering_.keys();
    const size_t count = keys.size();
    out->resize(kWidth * count);
    run_parallel(options_.pool, threads_, (count + kBlock - 1) / kBlock, [&](size_t b, unsigned) {
      for (size_t i = b * kBlock; i < std::min(count, (b + 1) * kBlock); ++i) {
        const uint32_t element = keys[i].*field;
        for (int k = 0; k < kWidth; ++k)
          (*out)[kWidth * i + k] = element == kNoIndex ? 0.0f : (*source)[kWidth * size_t{element} + k];
      }
    });
    free_array(source);
  }

  // Stage 7: skipped statements and an empty mesh said once, then every warning in line order.
  void finish_warnings() {
    for (const auto& [keyword, ignored] : ignored_)
      warn(ignored.first_line, (ignored.valid_obj ? "'" + keyword + "' statements are not supported: "
                                                  : "unknown statement '" + keyword + "': ") +
                                   std::to_string(ignored.count) + " ignored");
    if (out_->faces == 0) warn(std::max<uint64_t>(starts_.back().line - 1, 1), "no faces: the mesh is empty");
    std::stable_sort(warnings_.begin(), warnings_.end(), [](const LocalMessage& a, const LocalMessage& b) { return a.line < b.line; });
    out_->warning_total = warnings_.size();
    for (size_t i = 0; i < warnings_.size() && i < kMaxWarnings; ++i) out_->warnings.push_back(at(warnings_[i].line, warnings_[i].text));
  }

  const std::string& name_;
  const std::string& directory_;
  const ImportOptions& options_;
  const unsigned threads_;
  const FileBytes* file_;
  ObjMesh* out_;
  std::vector<std::string_view> texts_;
  std::vector<ChunkData> chunks_;
  std::vector<ChunkStart> starts_;  // per chunk, and one past the last: the file's totals
  bool any_suspect_ = false;
  VertexNumbering numbering_;
  BigVector<uint32_t> triangles_;  // three vertex numbers per triangle, in file order
  struct DeferredPolygon {
    uint64_t at;  // its first triangle's place in triangles_
    uint32_t corners;
    uint64_t line;
  };
  std::vector<DeferredPolygon> deferred_;
  std::vector<uint32_t> polygon_, clipped_;  // a polygon's vertex numbers; its triangles as corner numbers
  std::vector<const float*> corners_;        // a polygon's positions
  TriangulationScratch scratch_;
  std::vector<LocalMessage> names_;   // usemtl names in order of first use, at that line
  std::unordered_map<std::string, uint32_t> name_index_;
  std::vector<uint32_t> name_slots_;  // per name: its material's index
  std::vector<LocalMessage> libraries_;    // mtllib lines
  std::map<std::string, IgnoredKeyword> ignored_;
  std::vector<LocalMessage> warnings_;
  BigVector<float> positions_, texcoords_, normals_, colors_;  // the file's vertex data, as written
};

bool import_text(std::string_view text, const std::string& name, const std::string& directory,
                 const ImportOptions& options, const FileBytes* file, ObjMesh* out, std::string* error) {
  *out = ObjMesh{};
  error->clear();
  try {
    if (Importer(name, directory, options, file, out).run(text, error)) return true;
  } catch (const std::bad_alloc&) {
    *error = name + ": out of memory";
  } catch (const std::exception& e) {
    *error = std::string(e.what()).rfind(name, 0) == 0 ? e.what() : name + ": " + e.what();
  }
  *out = ObjMesh{};
  return false;
}

}  // namespace

bool import_obj_text(std::string_view text, const std::string& name, const std::string& directory,
                     const ImportOptions& options, ObjMesh* out, std::string* error) {
  return import_text(text, name, directory, options, nullptr, out, error);
}

bool import_obj_file(const std::string& path, const ImportOptions& options, ObjMesh* out, std::string* error) {
  FileBytes file;
  if (!file.open(path, error)) return false;
  const std::string directory = std::filesystem::path(path).parent_path().string();
  return import_text(file.bytes(), path, directory.empty() ? "." : directory, options, &file, out, error);
}

}  // namespace pfx_obj

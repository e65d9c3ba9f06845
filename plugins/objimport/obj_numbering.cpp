// Stages 2 and 3 of an import (obj_stages.hpp): the chunks read in parallel and numbered in file
// order, the indices checked, the polygons whose positions came late clipped.
#include <unistd.h>

#include <algorithm>
#include <thread>
#include <unordered_map>

#include "obj_parallel.hpp"
#include "obj_stages.hpp"
#include "obj_triangulate.hpp"

namespace pfx_obj {

namespace {

// Room for `most` elements when that is at most an eighth of the machine's memory (address space
// only, never copied: the kernel refuses mappings much larger than memory), else none: the array
// then doubles as it grows.
uint64_t room_for(uint64_t most, size_t element_bytes) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 && most * element_bytes <= uint64_t(pages) * uint64_t(page) / 8 ? most : 0;
}

// A polygon to cut into triangles by ear clipping (obj_triangulate.hpp): its corners' vertex
// numbers and positions; the memory is reused from one polygon to the next.
class Polygon {
 public:
  std::vector<uint32_t> ids;
  std::vector<const float*> corners;
  // Its n - 2 triangles, as vertex numbers, from `out` on, with a warning at `line` when it had to
  // be cut as a fan. Returns the end of what it wrote.
  uint32_t* cut(uint64_t line, uint32_t* out, std::vector<LocalMessage>* warnings) {
    const uint32_t n = static_cast<uint32_t>(ids.size());
    clipped_.clear();
    const Triangulation how = triangulate_polygon(corners.data(), n, &clipped_, &scratch_);
    for (uint32_t k : clipped_) *out++ = ids[k];
    if (how == Triangulation::kEarClipped) return out;
    const char* why = how == Triangulation::kFanDegenerate ? "has no area"
                      : how == Triangulation::kFanTooLarge ? "is too large for ear clipping (over 4096 corners)"
                                                           : "is self-intersecting";
    warnings->push_back({line, "f: polygon of " + std::to_string(n) + " corners " + why + ": triangulated as a fan"});
    return out;
  }

 private:
  std::vector<uint32_t> clipped_;  // its triangles as corner numbers
  TriangulationScratch scratch_;
};

// A chunk's large arrays swapped with another's.
void swap_arrays(ChunkData* a, ChunkData* b) {
  a->positions.swap(b->positions);
  a->texcoords.swap(b->texcoords);
  a->normals.swap(b->normals);
  a->corners.swap(b->corners);
  a->faces.swap(b->faces);
}

// Stage 2. A chunk is read into the arrays of one of a few slots, one per worker, and gives them
// back once numbered, so later chunks reuse pages already written instead of fresh ones.
class ChunkNumberer {
 public:
  ChunkNumberer(const std::vector<std::string_view>& texts, const ImportContext& context,
                const std::function<void(double)>& numbered)
      : texts_(texts), context_(context), numbered_(numbered),
        text_bytes_(texts.back().data() + texts.back().size() - texts.front().data()) {
    // Room, in address space only (obj_buffer.hpp), for the most the text can hold ("v 0 0 0",
    // "vt 0", "vn 0 0 0") and for what files hold: a vertex per position, a triangle index per
    // byte (a quad "f 1 2 3 4" holds 0.6). Past that (vertices split by seams, polygons of many
    // short corners) an array grows by copying.
    FileVertices& vertices = out_.vertices;
    vertices.positions.reserve(room_for(3 * (text_bytes_ / 8 + 1), sizeof(float)));
    vertices.texcoords.reserve(room_for(2 * (text_bytes_ / 5 + 1), sizeof(float)));
    vertices.normals.reserve(room_for(3 * (text_bytes_ / 9 + 1), sizeof(float)));
    out_.triangles.reserve(room_for(text_bytes_ + 3, sizeof(uint32_t)));
    numbering_.reserve(room_for(text_bytes_ / 8 + 1, sizeof(VertexKey) + 4), room_for(text_bytes_ / 8 + 1, 4));
  }

  NumberedFile run() {
    const size_t count = texts_.size();
    read_.resize(count);
    out_.chunks.resize(count);
    size_t largest = 0;
    for (std::string_view text : texts_) largest = std::max(largest, text.size());
    const size_t window = context_.threads;  // chunks between reading and numbering: one per worker
    std::vector<ChunkData> slots(window);  // only their arrays are used
    const std::thread::id caller = std::this_thread::get_id();
    uint64_t bytes_numbered = 0;  // (one in-order job at a time)
    auto read = [&](size_t c, unsigned) {
      swap_arrays(&read_[c], &slots[c % window]);
      parse_chunk(texts_[c], c == 0, &read_[c], largest);
      if (context_.file) context_.file->drop_pages(texts_[c]);
    };
    auto number = [&](size_t c) {
      number_chunk(c);
      swap_arrays(&read_[c], &slots[c % window]);
      read_[c] = ChunkData{};
      bytes_numbered += texts_[c].size();
      if (numbered_ && text_bytes_ > 0 && std::this_thread::get_id() == caller)
        numbered_(double(bytes_numbered) / double(text_bytes_));
    };
    run_ordered_jobs(context_.pool, context_.threads, count, window, read, number);
    out_.keys = numbering_.take_keys();
    return std::move(out_);
  }

 private:
  // Chunk c, read, after every chunk before it: its statements and vertex data added to the
  // file's, and its faces numbered into triangles. Throws at a chunk that failed to read.
  void number_chunk(size_t c) {
    const ChunkData& chunk = read_[c];
    NumberedChunk& numbered = out_.chunks[c];
    if (c > 0) numbered.start = out_.chunks[c - 1].end;
    const FileSoFar& start = numbered.start;
    if (!chunk.error.text.empty())
      throw ImportError(at_line(context_.name, start.line + chunk.error.line, chunk.error.text));
    numbered.end = end_of(chunk, start);
    std::copy(chunk.max_index, chunk.max_index + 3, numbered.max_index);
    collect_statements(&read_[c], &numbered);
    append_vertex_data(chunk, start);

    // An index past what the rest of the text could still define cannot be satisfied: from the
    // chunk that may hold one, none is numbered and check_indices finds it. (A position index
    // sizes an array here.)
    const uint64_t bytes_left = text_bytes_ - uint64_t(texts_[c].data() + texts_[c].size() - texts_[0].data());
    numbered.suspect = chunk.max_index[0] > numbered.end.bases[0] + bytes_left / 8 + 1;
    any_suspect_ = any_suspect_ || numbered.suspect;
    if (any_suspect_) return;
    out_.triangles.resize(3 * numbered.end.triangles);
    numbering_.cover(std::max(numbered.end.bases[0], chunk.max_index[0]));
    numbered.suspect = !number_faces(chunk, numbered, out_.triangles.data() + 3 * start.triangles);
    any_suspect_ = numbered.suspect;
  }

  // Where the chunk ends: its start and what it holds (the state in force: as at its start, until
  // collect_statements). Throws past the limits on elements and triangles.
  FileSoFar end_of(const ChunkData& chunk, const FileSoFar& start) const {
    FileSoFar end = start;
    const uint64_t totals[4] = {start.bases[0] + chunk.positions.size() / 3,  // v
                                start.bases[1] + chunk.texcoords.size() / 2,  // vt
                                start.bases[2] + chunk.normals.size() / 3,    // vn
                                start.faces + chunk.faces.size()};
    if (*std::max_element(totals, totals + 4) > uint64_t(kMaxWrittenIndex))
      throw ImportError(context_.name + ": more than 2^31 - 1 elements of one kind (v, vt, vn or f): too large");
    std::copy(totals, totals + 3, end.bases);
    end.line = start.line + chunk.line_ends;
    end.faces = totals[3];
    end.triangles = start.triangles + chunk.triangles;
    if (3 * end.triangles > kNoIndex) throw ImportError(context_.name + ": more than 2^32 - 1 triangle indices");
    return end;
  }

  // The chunk's statements that make no geometry: the state in force after it, its usemtl names
  // (each change's value made an index into the file's), material libraries and skipped statements.
  void collect_statements(ChunkData* chunk, NumberedChunk* numbered) {
    FileStatements& file = out_.statements;
    const uint64_t first_line = numbered->start.line;
    std::vector<uint32_t> file_names;  // per chunk-local name
    for (const LocalMessage& name : chunk->material_names) {
      const auto [it, fresh] = name_index_.emplace(name.text, static_cast<uint32_t>(file.material_names.size()));
      if (fresh) file.material_names.push_back({first_line + name.line, name.text});
      file_names.push_back(it->second);
    }
    numbered->changes = std::move(chunk->changes);
    for (StateChange& change : numbered->changes) {
      if (change.kind == StateChange::kMaterial) {
        change.value = file_names[change.value];
        numbered->end.material = change.value;
      } else {
        numbered->end.smoothing = change.value;
      }
    }
    for (const LocalMessage& library : chunk->material_libraries)
      file.material_libraries.push_back({first_line + library.line, library.text});
    for (const auto& [keyword, ignored] : chunk->ignored) {
      IgnoredKeyword& total = file.ignored[keyword];
      if (total.count == 0) total = {first_line + ignored.first_line, 0, ignored.valid_obj};
      total.count += ignored.count;
    }
    file.lines_skipped += chunk->lines_skipped;
    file.points_skipped += chunk->points_skipped;
  }

  // The chunk's vertex data appended to the file's (colours: white for a v without one, once any v
  // has one).
  void append_vertex_data(const ChunkData& chunk, const FileSoFar& start) {
    FileVertices& file = out_.vertices;
    file.positions.insert(file.positions.end(), chunk.positions.begin(), chunk.positions.end());
    file.texcoords.insert(file.texcoords.end(), chunk.texcoords.begin(), chunk.texcoords.end());
    file.normals.insert(file.normals.end(), chunk.normals.begin(), chunk.normals.end());
    if (!chunk.colors.empty() && file.colors.empty()) file.colors.assign(3 * size_t{start.bases[0]}, 1.0f);
    if (chunk.colors.empty() && !file.colors.empty()) file.colors.resize(file.positions.size(), 1.0f);
    file.colors.insert(file.colors.end(), chunk.colors.begin(), chunk.colors.end());
  }

  // The chunk's faces as triangles of vertex numbers, into `out`. A triangle's corners are
  // numbered straight into `out`; a polygon is ear-clipped, or, when a corner's position comes
  // later in the file, cut as a fan for now and clipped once every chunk is read. False when a
  // relative index reaches before the first element.
  bool number_faces(const ChunkData& chunk, const NumberedChunk& numbered, uint32_t* out) {
    const FileSoFar& start = numbered.start;
    const bool any_relative = !chunk.relative_fields.empty();
    const uint32_t positions_read = numbered.end.bases[0];
    uint64_t field = 0;
    // A face's n corners from `field` on, relative indices made final, each numbered into ids. For
    // a polygon, polygon_.corners gets their positions while each is read so far (*all_read: all were).
    auto number_corners = [&](uint32_t n, uint32_t group, uint32_t* ids, bool* all_read) {
      for (uint32_t k = 0; k < n; ++k) {
        uint32_t index[3];
        for (int kind = 0; kind < 3; ++kind, ++field) {
          index[kind] = chunk.corners[field];
          if (!any_relative || !chunk.is_relative(field)) continue;
          const int64_t one_based = int64_t{start.bases[kind]} + static_cast<int32_t>(index[kind]);
          if (one_based < 1) return false;
          index[kind] = static_cast<uint32_t>(one_based - 1);
        }
        ids[k] = numbering_.find_or_insert({index[0], index[1], index[2], index[2] == kNoIndex ? group : 0});
        if (n == 3) continue;
        *all_read = *all_read && index[0] < positions_read;
        if (*all_read) polygon_.corners[k] = &out_.vertices.positions[3 * size_t{index[0]}];
      }
      return true;
    };
    uint32_t smoothing = start.smoothing;
    size_t change = 0;
    for (size_t f = 0; f < chunk.faces.size(); ++f) {
      for (; change < numbered.changes.size() && numbered.changes[change].first_face == f; ++change)
        if (numbered.changes[change].kind == StateChange::kSmoothing) smoothing = numbered.changes[change].value;
      // A corner without a normal is keyed by its face's normal group: its smoothing group, or the
      // face itself when smoothing is off.
      const uint32_t group = smoothing == 0 ? kFlatFaceBit | static_cast<uint32_t>(start.faces + f) : smoothing;
      const uint32_t n = chunk.faces[f].corner_count;
      bool all_read = true;
      if (n == 3) {
        if (!number_corners(3, group, out, &all_read)) return false;
        out += 3;
        continue;
      }
      polygon_.ids.resize(n);
      polygon_.corners.resize(n);
      if (!number_corners(n, group, polygon_.ids.data(), &all_read)) return false;
      const uint64_t line = start.line + chunk.faces[f].line;
      if (all_read) {
        out = polygon_.cut(line, out, &out_.warnings);
        continue;
      }
      out_.deferred.push_back({static_cast<uint64_t>(out - out_.triangles.data()), n, line});
      for (uint32_t k = 1; k + 1 < n; ++k)  // a fan from the first corner
        for (uint32_t corner : {0u, k, k + 1}) *out++ = polygon_.ids[corner];
    }
    return true;
  }

  const std::vector<std::string_view>& texts_;
  const ImportContext& context_;
  const std::function<void(double)>& numbered_;
  const uint64_t text_bytes_;
  std::vector<ChunkData> read_;  // per chunk: as read, until numbered
  NumberedFile out_;
  VertexNumbering numbering_;
  std::unordered_map<std::string, uint32_t> name_index_;  // usemtl name -> index into material_names
  bool any_suspect_ = false;     // a chunk so far may hold a bad index: none after it is numbered
  Polygon polygon_;
};

// The message for a corner's index that is outside the file's `total` of its kind.
std::string bad_index_reason(int kind, int64_t one_based, uint32_t total) {
  const std::string k = kind == 0 ? "v" : kind == 1 ? "vt" : "vn", n = std::to_string(one_based);
  if (one_based < 1) return "f: relative " + k + " index reaches before the first " + k;
  if (total == 0) return "f: " + k + " index " + n + " but the file has no " + k;
  return "f: " + k + " index " + n + " is out of range (the file has " + std::to_string(total) + " " + k + ")";
}

}  // namespace

NumberedFile number_chunks(const std::vector<std::string_view>& texts, const ImportContext& context,
                           const std::function<void(double)>& numbered) {
  return ChunkNumberer(texts, context, numbered).run();
}

void check_indices(const std::vector<std::string_view>& texts, const NumberedFile& file, const ImportContext& context) {
  const uint32_t* totals = file.totals().bases;
  for (size_t c = 0; c < file.chunks.size(); ++c) {
    const NumberedChunk& numbered = file.chunks[c];
    bool suspect = numbered.suspect;
    for (int k = 0; k < 3; ++k) suspect = suspect || numbered.max_index[k] > totals[k];
    if (!suspect) continue;
    ChunkData chunk;
    parse_chunk(texts[c], c == 0, &chunk);
    uint64_t field = 0;
    for (const Face& face : chunk.faces)
      for (uint32_t j = 0; j < 3 * face.corner_count; ++j, ++field) {
        const int kind = static_cast<int>(field % 3);
        const bool relative = chunk.is_relative(field);
        const uint32_t written = chunk.corners[field];
        if (!relative && written == kNoIndex) continue;
        const int64_t one_based =
            relative ? int64_t{numbered.start.bases[kind]} + static_cast<int32_t>(written) : int64_t{written} + 1;
        if (one_based >= 1 && one_based <= totals[kind]) continue;
        const uint64_t line = numbered.start.line + face.line;
        throw ImportError(at_line(context.name, line, bad_index_reason(kind, one_based, totals[kind])));
      }
  }
}

// A fan (0 1 2) (0 2 3) ... holds the polygon's corners 0 and 1, then one in each triangle's third.
void clip_deferred_polygons(NumberedFile* file) {
  Polygon polygon;
  for (const DeferredPolygon& deferred : file->deferred) {
    uint32_t* fan = file->triangles.data() + deferred.at;
    polygon.ids.assign({fan[0], fan[1]});
    for (uint32_t k = 0; k + 2 < deferred.corners; ++k) polygon.ids.push_back(fan[3 * k + 2]);
    polygon.corners.clear();
    for (uint32_t id : polygon.ids) polygon.corners.push_back(&file->vertices.positions[3 * size_t{file->keys[id].v}]);
    polygon.cut(deferred.line, fan, &file->warnings);
  }
}

}  // namespace pfx_obj

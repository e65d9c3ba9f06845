// From resolved chunks to the mesh (obj_importer.hpp): vertex data gathered, the index array laid
// out per chunk and material, corners numbered (obj_dedup.hpp) and written straight there as
// triangles (polygons ear-clipped), the vertex arrays filled, bounds and warnings.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "obj_importer.hpp"
#include "obj_parallel.hpp"
#include "obj_triangulate.hpp"

namespace pfx_obj {

// One array per kind of vertex data, chunk arrays copied in at their bases in parallel, each
// chunk's freed as soon as it is copied.
// The chunks' vertex arrays move out of the chunks (freed with the triangles' inputs) and are
// read where they lie: copying them into one array per kind cost a pass and as much fresh memory.
void Importer::gather() {
  static const float kWhite[3] = {1.0f, 1.0f, 1.0f};
  all_colors_ = ChunkedElements(3, kWhite);
  for (size_t c = 0; c < chunks_.size(); ++c) {
    ChunkData& chunk = chunks_[c];
    const ChunkPlan& plan = plans_[c];
    all_positions_.add(plan.position_base, chunk.position_count(), chunk.positions.data());
    all_texcoords_.add(plan.texcoord_base, static_cast<uint32_t>(chunk.texcoords.size() / 2), chunk.texcoords.data());
    all_normals_.add(plan.normal_base, static_cast<uint32_t>(chunk.normals.size() / 3), chunk.normals.data());
    all_colors_.add(plan.position_base, chunk.position_count(), chunk.colors.empty() ? nullptr : chunk.colors.data());
    vertex_data_.push_back(std::move(chunk.positions));
    vertex_data_.push_back(std::move(chunk.texcoords));
    vertex_data_.push_back(std::move(chunk.normals));
    vertex_data_.push_back(std::move(chunk.colors));
  }
}

// Sub-meshes in order of their material's first face, and where each chunk's triangles of each
// material go in the index array: the walk below writes them there directly.
void Importer::layout_triangles() {
  const size_t slots = out_->materials.size() + 1;
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
  index_total_ = index_total;
  for (uint32_t s : order)
    out_->submeshes.push_back({static_cast<uint32_t>(start[s]), static_cast<uint32_t>(3 * triangles[s]),
                               s == slots - 1 ? kNoIndex : s});
  write_at_.assign(chunks_.size(), {});
  for (size_t c = 0; c < chunks_.size(); ++c) {
    write_at_[c] = start;
    for (size_t s = 0; s < slots; ++s) start[s] += 3 * faces_[c].triangle_counts[s];
  }
}

// Chunk c's faces in order: each corner numbered by `numbering`, each face's triangles written at
// its material's place (polygons ear-clipped).
void Importer::triangulate_chunk(size_t c, VertexNumbering* numbering) {
  ChunkData& chunk = chunks_[c];
  std::vector<uint64_t> at = write_at_[c];
  uint32_t* indices = out_->indices.data();
  const uint32_t* fields = chunk.corners.data();
  PolygonScratch scratch;
  std::vector<const float*> corner_positions;
  std::vector<uint32_t> corner_ids;
  ChunkedElements::Reader positions(all_positions_);
  FaceStates states = face_states(c);
  for (size_t f = 0; f < chunk.faces.size(); ++f) {
    const uint32_t n = chunk.faces[f].corner_count;
    states.at_face(f);
    const uint32_t group = states.normal_group();
    auto vertex = [&](const uint32_t* corner) {
      return numbering->find_or_insert(VertexKey{corner[0], corner[1], corner[2], corner[2] == kNoIndex ? group : 0});
    };
    uint64_t& cursor = at[states.slot()];
    if (n == 3) {
      indices[cursor] = vertex(fields);
      indices[cursor + 1] = vertex(fields + 3);
      indices[cursor + 2] = vertex(fields + 6);
      cursor += 3;
      fields += 9;
      continue;
    }
    corner_ids.resize(n);
    corner_positions.resize(n);
    for (uint32_t k = 0; k < n; ++k, fields += 3) {
      corner_ids[k] = vertex(fields);
      corner_positions[k] = positions.at(fields[0]);
    }
    write_polygon(c, f, n, corner_ids.data(), corner_positions.data(), &cursor, &scratch);
  }
}

// Face f of chunk c, a polygon of n corners (their vertex numbers and positions), ear-clipped into
// the index array at *cursor; a warning when it had to be a fan.
void Importer::write_polygon(size_t c, size_t f, uint32_t n, const uint32_t* corner_ids,
                             const float* const* corner_positions, uint64_t* cursor, PolygonScratch* scratch) {
  uint32_t* indices = out_->indices.data();
  scratch->polygon.clear();
  Triangulation how = triangulate_polygon(corner_positions, n, &scratch->polygon, &scratch->triangulation);
  for (uint32_t k : scratch->polygon) indices[(*cursor)++] = corner_ids[k];
  if (how != Triangulation::kEarClipped) {
    const char* why = how == Triangulation::kFanDegenerate ? "has no area"
                      : how == Triangulation::kFanTooLarge ? "is too large for ear clipping (over 4096 corners)"
                                                           : "is self-intersecting";
    ChunkFaces& result = faces_[c];
    ++result.warning_total;
    if (result.warnings.size() < kMaxWarnings)
      result.warnings.push_back({plans_[c].first_line + chunks_[c].faces[f].line,
                                 "f: polygon of " + std::to_string(n) + " corners " + why + ": triangulated as a fan"});
  }
}

// A chunk's corners and faces once walked, their pages kept for the arrays made next (the vertex
// arrays; with threads, the merge's too). Freed by the calling thread only while no other thread
// runs: unmapping memory while another thread of the process runs interrupts that thread's core to
// flush its address translations, which in a virtual machine costs far more than the unmapping.
void Importer::free_corners(size_t c) {
  keep_for_reuse(&chunks_[c].corners);
  keep_for_reuse(&chunks_[c].faces);
}

void Importer::number_and_triangulate(StageClock* clock) {
  uint64_t total_corners = 0, largest_chunk = 0;
  for (const ChunkData& chunk : chunks_) {
    total_corners += chunk.corners.size() / 3;
    largest_chunk = std::max<uint64_t>(largest_chunk, chunk.corners.size() / 3);
  }
  if (total_corners > kNoIndex) throw std::length_error(name_ + ": more than 2^32 - 1 face corners");
  out_->indices.resize(index_total_);

  if (threads_ <= 1 || chunks_.size() == 1) {
    // Every corner, in file order, against one numbering: its numbers are final.
    clock->time("dedup, triangles", false, [&] {
      VertexNumbering numbering(totals_[0], total_corners);
      for (size_t c = 0; c < chunks_.size(); ++c) {
        triangulate_chunk(c, &numbering);
        free_corners(c);
      }
      keys_.swap(numbering.keys());
      numbering.keep_pages_for_reuse();
    });
  } else {
    // Each chunk numbered on its own (each worker reuses one numbering), then the chunks' keys
    // merged in file order, then each chunk's triangles renumbered where they lie.
    std::vector<BigVector<VertexKey>> chunk_keys(chunks_.size());
    clock->time("dedup chunks, triangles", true, [&] {
      std::vector<std::unique_ptr<VertexNumbering>> worker_numbering(threads_);
      run_parallel(options_.pool, threads_, chunks_.size(), [&](size_t c, unsigned worker) {
        if (!worker_numbering[worker]) worker_numbering[worker] = std::make_unique<VertexNumbering>(totals_[0], largest_chunk);
        VertexNumbering& numbering = *worker_numbering[worker];
        triangulate_chunk(c, &numbering);
        chunk_keys[c] = numbering.keys();
        numbering.clear();
      });
    });
    for (size_t c = 0; c < chunks_.size(); ++c) free_corners(c);
    std::vector<BigVector<uint32_t>> to_file;
    clock->time("dedup merge", false, [&] { merge_chunk_keys(&chunk_keys, totals_[0], &keys_, &to_file); });
    clock->time("dedup renumber", true, [&] {
      run_parallel(options_.pool, threads_, chunks_.size(), [&](size_t c, unsigned) {
        uint32_t* indices = out_->indices.data();
        const uint32_t* map = to_file[c].data();
        for (size_t s = 0; s < write_at_[c].size(); ++s) {
          const uint64_t begin = write_at_[c][s], end = begin + 3 * faces_[c].triangle_counts[s];
          for (uint64_t i = begin; i < end; ++i) indices[i] = map[indices[i]];
        }
      });
    });
  }
  end_chunks();
}

// Once the index array is written: the walks' warnings kept, the chunks' remaining arrays freed.
void Importer::end_chunks() {
  for (ChunkFaces& f : faces_) {
    for (Located& w : f.warnings) warnings_.push_back(std::move(w));
    extra_warnings_ += f.warning_total - f.warnings.size();
  }
  free_array(&chunks_);
  free_array(&faces_);
  free_array(&write_at_);
}

void Importer::fill_vertices() {
  const size_t count = keys_.size();
  const bool any_texcoords = std::any_of(keys_.begin(), keys_.end(), [](const VertexKey& k) { return k.vt != kNoIndex; });
  out_->positions.resize(3 * count);
  out_->normals.resize(3 * count);
  if (any_texcoords) out_->texcoords.resize(2 * count);
  if (any_colors_) out_->colors.resize(3 * count);
  // In blocks handed out in turn rather than one range per thread: the arrays' first pages may be
  // reused ones (obj_spare_mappings.hpp) and the rest fresh, which made one half twice the work.
  // Each block's bounds too, combined below (min and max do not depend on the order).
  constexpr size_t kBlock = size_t{1} << 15;
  const size_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<std::array<float, 6>> block_bounds(blocks);
  run_parallel(options_.pool, threads_, blocks, [&](size_t b, unsigned) {
    const size_t lo = b * kBlock, hi = std::min(count, lo + kBlock);
    ChunkedElements::Reader positions(all_positions_), colors(all_colors_), texcoords(all_texcoords_),
        normals(all_normals_);
    float low[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, high[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
    for (size_t i = lo; i < hi; ++i) {
      const VertexKey& key = keys_[i];
      const float* p = positions.at(key.v);
      std::memcpy(&out_->positions[3 * i], p, 3 * sizeof(float));
      for (int k = 0; k < 3; ++k) {  // as std::min and std::max: a NaN coordinate is passed over
        low[k] = std::min(low[k], p[k]);
        high[k] = std::max(high[k], p[k]);
      }
      if (any_colors_) std::memcpy(&out_->colors[3 * i], colors.at(key.v), 3 * sizeof(float));
      if (any_texcoords) {
        if (key.vt != kNoIndex) std::memcpy(&out_->texcoords[2 * i], texcoords.at(key.vt), 2 * sizeof(float));
        else out_->texcoords[2 * i] = out_->texcoords[2 * i + 1] = 0.0f;
      }
      if (key.vn != kNoIndex) std::memcpy(&out_->normals[3 * i], normals.at(key.vn), 3 * sizeof(float));
    }
    block_bounds[b] = {low[0], low[1], low[2], high[0], high[1], high[2]};
  });
  if (count > 0) {
    std::copy(block_bounds[0].begin(), block_bounds[0].begin() + 3, out_->bounds_min);
    std::copy(block_bounds[0].begin() + 3, block_bounds[0].end(), out_->bounds_max);
    for (const std::array<float, 6>& bounds : block_bounds)
      for (int k = 0; k < 3; ++k) {
        out_->bounds_min[k] = std::min(out_->bounds_min[k], bounds[k]);
        out_->bounds_max[k] = std::max(out_->bounds_max[k], bounds[3 + k]);
      }
  }
  all_positions_ = ChunkedElements(3);
  all_texcoords_ = ChunkedElements(2);
  all_normals_ = ChunkedElements(3);
  // Freed on this thread: two threads unmapping these arrays (one per chunk and kind of data, 472
  // at 487 MB) mostly wait for each other's hold on the address space, and took 7.7 ms against
  // 6.2 ms on one (medians of 5). Dropping their pages on two threads first (as the plugin does for
  // the result, obj_parallel_free.hpp) took 6.1-7.4 ms: a call per array, each of which likely
  // interrupts the other thread to flush its TLB, against about ten calls for the result.
  free_array(&vertex_data_);
}

void Importer::finish() {
  free_array(&keys_);
  std::stable_sort(warnings_.begin(), warnings_.end(), [](const Located& a, const Located& b) { return a.line < b.line; });
  out_->warning_total = warnings_.size() + extra_warnings_;
  for (size_t i = 0; i < warnings_.size() && i < kMaxWarnings; ++i)
    out_->warnings.push_back(at(name_, warnings_[i].line, warnings_[i].text));
}

}  // namespace pfx_obj

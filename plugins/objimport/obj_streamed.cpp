// Chunk by chunk (obj_importer.hpp). Each chunk is parsed, and as soon as it and every chunk
// before it are, its corners are numbered against one numbering for the whole file (the corners
// come in file order, so the numbers are final) into one array of vertex numbers in file order —
// which, for a file of triangles in one material, is the index array itself. On several threads
// the numbering runs on one thread at a time while the others parse the chunks after it
// (obj_ordered_jobs.hpp). A chunk's corners (12 bytes each) therefore live only until numbered,
// and a later chunk is parsed into the same pages, as are its faces when nothing later needs
// them: a few chunks' worth instead of the whole file's, and pages already written instead of
// fresh ones, for which the kernel charges as much as for parsing (docs/importers/obj.md). The
// staged pipeline keeps every chunk's corners until all are parsed and numbers each chunk on its
// own, then merges the chunks' keys.
//
// The output is the staged pipeline's, byte for byte (the tests compare). What a chunk cannot
// settle with the file read so far up to its end — a position index past the positions read so
// far, a relative index reaching before the first element, an index the whole file does not reach
// — sends the import to the staged pipeline, from the start: all but the first are errors, which
// it reports with their line.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <stdexcept>

#include "obj_importer.hpp"
#include "obj_ordered_jobs.hpp"
#include "obj_split.hpp"

namespace pfx_obj {

namespace {

// How much of an array to make room for, from what the text read so far needed of it: the same
// per byte for the rest of the text, and an eighth more (growing an array copies it).
uint64_t room_for(uint64_t so_far, uint64_t bytes_read, uint64_t bytes_total) {
  const double per_byte = bytes_read > 0 ? static_cast<double>(so_far) / static_cast<double>(bytes_read) : 0.0;
  return static_cast<uint64_t>(per_byte * static_cast<double>(bytes_total) * 1.125) + 1024;
}

// Room for an array that grows as chunks are numbered: for the most elements the text could
// still make (`most`) — address space only, never copied — unless that would be more than an
// eighth of the machine's memory (the kernel refuses a mapping much larger than memory): then an
// estimate from the text read so far, the array doubling when it falls short. Growing by copying
// costs fresh pages as well as the copy: estimates from the text read so far fall short in files
// that list every vertex before the faces.
uint64_t room_at_most(uint64_t most, uint64_t element_bytes, uint64_t so_far, uint64_t bytes_read,
                      uint64_t text_bytes) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  const uint64_t memory = pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : 0;
  return most * element_bytes <= memory / 8 ? most : room_for(so_far, bytes_read, text_bytes);
}

}  // namespace

Importer::Outcome Importer::run_streamed(std::string_view text, ObjMesh* out, std::string* error) {
  out_ = out;
  *out = ObjMesh{};
  StageClock clock(&out->stages);
  report(0.0f);
  texts_ = split_at_line_ends(text, chunk_count(text.size()));
  const size_t chunk_total = texts_.size();
  chunks_.assign(chunk_total, ChunkData{});
  id_begin_.assign(chunk_total + 1, 0);
  faces_kept_.assign(chunk_total, false);
  // Every chunk's arrays sized for the largest, so that each fits in the pages of any before it.
  size_t largest = 0;
  for (std::string_view chunk : texts_) largest = std::max(largest, chunk.size());

  // The corner and face pages of the chunks between parse and numbering (run_ordered_jobs): a
  // chunk is parsed into its slot's pages, which go back to the slot once it is numbered.
  struct ChunkPages {
    BigVector<uint32_t> corners;
    BigVector<Face> faces;
  };
  // One chunk per thread, and one more: parsed while the chunk before it waits for the numbering
  // — each more slot is a chunk's worth of fresh corner pages (two threads, 4 slots against 3:
  // 51.6 against 50.9 ms at 99 MB, 6.6 against 6.3 ms at 10 MB, medians of 21 and 31).
  const size_t window = threads_ == 1 ? 1 : size_t{threads_} + 1;
  std::vector<ChunkPages> pages(window);

  VertexNumbering numbering(0, 0);
  StreamedSoFar so_far;
  std::atomic<uint64_t> bytes_numbered{0};
  bool use_stages = false;

  auto parse_job = [&](size_t c, unsigned) {
    ChunkData& chunk = chunks_[c];
    ChunkPages& slot = pages[c % window];
    chunk.corners.swap(slot.corners);
    chunk.faces.swap(slot.faces);
    parse_one(c, largest);
  };
  // In file order: chunk c numbered, its pages handed back to its slot. false stops the import.
  auto number_job = [&](size_t c) {
    const Taken taken = take_streamed_chunk(c, text.size(), &so_far, &numbering);
    use_stages = taken == Taken::kUseStages;
    if (taken != Taken::kNumbered) return false;
    ChunkPages& slot = pages[c % window];
    slot.corners.swap(chunks_[c].corners);
    if (!faces_kept_[c]) slot.faces.swap(chunks_[c].faces);
    bytes_numbered = so_far.bytes;
    return true;
  };
  // One stage: the numbering runs in file order on one thread at a time, beside the parse of
  // later chunks on the others.
  clock.time("parse and numbering", true, [&] {
    run_ordered_jobs(options_.pool, threads_, chunk_total, window, parse_job, number_job, [&] {
      report(static_cast<float>(0.7 * static_cast<double>(bytes_numbered.load()) / std::max<double>(1.0, text.size())));
    });
  });
  if (use_stages) return Outcome::kUseStages;
  // The last corners and faces handed on, for the arrays made next (obj_spare_mappings.hpp).
  for (ChunkPages& slot : pages) {
    keep_for_reuse(&slot.corners);
    keep_for_reuse(&slot.faces);
  }

  bool ok = true;
  clock.time("plan", false, [&] { ok = plan(error); });
  if (!ok) return Outcome::kFailed;
  for (const ChunkData& chunk : chunks_)
    for (int k = 0; k < 3; ++k)
      if (chunk.max_index[k] > totals_[k]) return Outcome::kUseStages;  // an error, reported with its line there
  // Each chunk's triangles per material: no walk over corners here (relative indices were made
  // final as numbered, indices out of range went to the stages), so no thread is worth starting.
  clock.time("resolve", false, [&] { resolve_all(1); });
  clock.time("gather", false, [&] { gather(); });
  clock.time("layout", false, [&] { layout_triangles(); });
  keys_.swap(numbering.keys());
  numbering.keep_pages_for_reuse();
  clock.time("triangles", false, [&] { write_streamed_triangles(); });
  end_chunks();
  assemble(&clock);
  return Outcome::kDone;
}

// Chunk c, parsed, after every chunk before it: its corners numbered into the vertex numbers, and
// *so_far moved past it. kStop: it failed to parse (the plan reports it, as the first error in
// file order); kUseStages: it needs what only the staged pipeline does.
Importer::Taken Importer::take_streamed_chunk(size_t c, uint64_t text_bytes, StreamedSoFar* so_far,
                                              VertexNumbering* numbering) {
  ChunkData& chunk = chunks_[c];
  if (chunk.failed) return Taken::kStop;
  StreamedSoFar& at = *so_far;
  at.bytes += texts_[c].size();
  const uint64_t chunk_corners = chunk.corners.size() / 3;
  const uint64_t positions_now = at.positions + chunk.position_count();
  if (chunk.max_index[0] > positions_now || positions_now > kMaxWrittenIndex) return Taken::kUseStages;
  if (at.corners + chunk_corners > kNoIndex) throw std::length_error(name_ + ": more than 2^32 - 1 face corners");
  // The most the rest of the text could add: a corner per two bytes ("1 "), a v per eight.
  const uint64_t bytes_left = text_bytes - at.bytes;
  const uint64_t corners_now = at.corners + chunk_corners, keys_now = numbering->keys().size() + chunk_corners;
  if (corners_now > streamed_ids_.capacity())
    streamed_ids_.reserve(std::max({corners_now,
                                    room_at_most(corners_now + bytes_left / 2 + 1, sizeof(uint32_t), corners_now,
                                                 at.bytes, text_bytes),
                                    2 * uint64_t{streamed_ids_.capacity()}}));
  streamed_ids_.resize(corners_now);
  numbering->grow(static_cast<uint32_t>(positions_now),
                  room_at_most(positions_now + bytes_left / 8 + 1, sizeof(uint32_t), positions_now, at.bytes, text_bytes),
                  keys_now,
                  room_at_most(keys_now + bytes_left / 2 + 1, sizeof(VertexKey) + sizeof(uint32_t), keys_now, at.bytes,
                               text_bytes));
  const uint32_t bases[3] = {static_cast<uint32_t>(at.positions), static_cast<uint32_t>(at.texcoords),
                             static_cast<uint32_t>(at.normals)};
  if (!number_streamed_chunk(c, bases, at.smoothing, at.faces, numbering, streamed_ids_.data() + at.corners))
    return Taken::kUseStages;
  // Its faces are needed again only to place polygons' triangles or to follow usemtl.
  uint64_t triangles = 0;
  for (uint64_t t : chunk.triangles_by_material) triangles += t;
  faces_kept_[c] = 3 * triangles != chunk_corners ||
                   std::any_of(chunk.changes.begin(), chunk.changes.end(),
                               [](const StateChange& s) { return s.kind == StateChange::kMaterial; });
  for (const StateChange& change : chunk.changes)
    if (change.kind == StateChange::kSmoothing) at.smoothing = change.value;
  at.positions = positions_now;
  at.texcoords += chunk.texcoords.size() / 2;
  at.normals += chunk.normals.size() / 3;
  at.faces += chunk.face_count;
  at.corners += chunk_corners;
  id_begin_[c + 1] = at.corners;
  return Taken::kNumbered;
}

// Chunk c's corners, in order, numbered into ids: relative indices made final (false when one
// reaches before the first element: an error the staged pipeline reports), each corner without a
// normal keyed by the normal group of its face.
bool Importer::number_streamed_chunk(size_t c, const uint32_t bases[3], uint32_t start_smoothing, uint64_t face_base,
                                     VertexNumbering* numbering, uint32_t* ids) {
  ChunkData& chunk = chunks_[c];
  // Only the normal group is wanted here: materials are placed later, once the plan knows them.
  const std::vector<uint32_t> no_slots(chunk.material_names.size(), 0);
  FaceStates states(&chunk.changes, &no_slots, 0, start_smoothing, face_base);
  uint32_t* fields = chunk.corners.data();
  const bool any_relative = !chunk.relative_fields.empty();
  uint64_t field = 0;
  for (size_t f = 0; f < chunk.faces.size(); ++f) {
    states.at_face(f);
    const uint32_t group = states.normal_group();
    for (uint32_t k = 0; k < chunk.faces[f].corner_count; ++k, fields += 3, field += 3) {
      if (any_relative)
        for (uint64_t j = 0; j < 3; ++j) {
          if (!chunk.is_relative(field + j)) continue;
          const int64_t one_based = int64_t{bases[j]} + static_cast<int32_t>(fields[j]);
          if (one_based < 1) return false;
          fields[j] = static_cast<uint32_t>(one_based - 1);
        }
      *ids++ = numbering->find_or_insert(VertexKey{fields[0], fields[1], fields[2], fields[2] == kNoIndex ? group : 0});
    }
  }
  free_array(&chunk.relative_fields);
  return true;
}

// The index array from the vertex numbers: the numbers themselves when every face is a triangle
// of one material; otherwise each chunk's numbers copied to its material's place, and its
// polygons ear-clipped there.
void Importer::write_streamed_triangles() {
  if (out_->submeshes.size() <= 1 && index_total_ == streamed_ids_.size()) {
    out_->indices.swap(streamed_ids_);
    return;
  }
  out_->indices.resize(index_total_);
  uint32_t* indices = out_->indices.data();
  ChunkedElements::Reader positions(all_positions_);
  PolygonScratch scratch;
  std::vector<const float*> corner_positions;
  for (size_t c = 0; c < chunks_.size(); ++c) {
    std::vector<uint64_t>& at = write_at_[c];
    const uint32_t* ids = streamed_ids_.data() + id_begin_[c];
    if (!faces_kept_[c]) {  // triangles only, all of the material in force at its start
      const uint64_t count = id_begin_[c + 1] - id_begin_[c];
      if (count > 0) std::memcpy(indices + at[plans_[c].start_slot], ids, count * sizeof(uint32_t));
      continue;
    }
    const ChunkData& chunk = chunks_[c];
    FaceStates states = face_states(c);
    for (size_t f = 0; f < chunk.faces.size(); ++f) {
      const uint32_t n = chunk.faces[f].corner_count;
      states.at_face(f);
      uint64_t& cursor = at[states.slot()];
      if (n == 3) {
        std::memcpy(indices + cursor, ids, 3 * sizeof(uint32_t));
        cursor += 3;
      } else {
        corner_positions.resize(n);
        for (uint32_t k = 0; k < n; ++k) corner_positions[k] = positions.at(keys_[ids[k]].v);
        write_polygon(c, f, n, ids, corner_positions.data(), &cursor, &scratch);
      }
      ids += n;
    }
  }
  free_array(&streamed_ids_);
}

}  // namespace pfx_obj

// One vertex per distinct face corner. A corner is keyed by its full 32-bit indices — position,
// texture coordinate, normal — plus, for a corner without a normal, the smoothing group its
// normal will be generated for (obj_normals.cpp). Nothing is packed, so nothing collides: the
// seed's 21-bit packing merged distinct corners past 2^21 elements.
//
// Vertices are numbered in the order of their first corner in the file, whatever the thread
// count, so the output never depends on it. Chunk by chunk (obj_streamed.cpp) and in the staged
// pipeline on one thread, one VertexNumbering sees every corner in file order and its numbers are
// final. In the staged pipeline on several threads, each chunk is numbered on its own in
// parallel, the chunks' distinct keys are then merged in file order (merge_chunk_keys) and their
// numbers mapped to the file's — a chunk lists its keys in the order of their first corner in the
// chunk, so the merge numbers them exactly as one pass over the file would.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "obj_buffer.hpp"
#include "obj_chunk.hpp"

namespace pfx_obj {

struct VertexKey {
  uint32_t v;      // 0-based position index
  uint32_t vt;     // 0-based texture coordinate index, or kNoIndex
  uint32_t vn;     // 0-based normal index, or kNoIndex
  uint32_t group;  // 0 when vn is given; otherwise which generated normal (see obj_face_states.hpp)
  bool operator==(const VertexKey& o) const { return v == o.v && vt == o.vt && vn == o.vn && group == o.group; }
};

class VertexTable;

// Distinct keys numbered in order of first insertion. Variants of one position (different vt, vn
// or normal group) are chained from a table indexed by the position itself, so a lookup reads one
// slot of a dense array and one key — in files that list vertices in the order faces use them,
// both are already in cache. A position with more than kMaxChain variants (a pathological file)
// sends the rest to a hash table, so no lookup walks far.
class VertexNumbering {
 public:
  // position_count: every key's v is below it. max_keys: room reserved for that many keys up
  // front — address space only (BigVector maps without touching), so the arrays never move.
  VertexNumbering(uint32_t position_count, uint64_t max_keys);
  ~VertexNumbering();

  uint32_t find_or_insert(const VertexKey& key) {
    uint32_t last = kNoIndex, length = 0;
    for (uint32_t id = head_[key.v]; id != kNoIndex; id = next_[id]) {
      if (keys_[id] == key) return id;
      last = id;
      ++length;
    }
    if (length >= kMaxChain) return find_or_insert_overflow(key);
    const uint32_t id = add(key);
    (last == kNoIndex ? head_[key.v] : next_[last]) = id;
    return id;
  }

  // For a numbering that meets the positions as the file is read (obj_streamed.cpp): keys with v
  // below position_count may be numbered from now on, and key_count keys in all. An array that
  // must grow for that grows to the room given, or at least twice its size, so that it is seldom
  // copied.
  void grow(uint32_t position_count, uint64_t position_room, uint64_t key_count, uint64_t key_room);

  // The distinct keys, in order of first insertion.
  BigVector<VertexKey>& keys() { return keys_; }

  // Empties the numbering for the next chunk, resetting only the heads its keys used.
  void clear();

  // Frees what is left once the keys are taken, keeping the written pages for the arrays the
  // import makes next (obj_spare_mappings.hpp): the result's vertex arrays.
  void keep_pages_for_reuse();

 private:
  static constexpr uint32_t kMaxChain = 8;
  uint32_t add(const VertexKey& key);
  uint32_t find_or_insert_overflow(const VertexKey& key);

  BigVector<uint32_t> head_;   // per position: its first variant, or kNoIndex
  BigVector<uint32_t> next_;   // per vertex: the next variant of its position
  BigVector<VertexKey> keys_;  // in order of first insertion
  std::unique_ptr<VertexTable> overflow_;
};

// The chunks' distinct keys (each chunk's in order of first use), in file order, numbered as one:
// to_file[c][i] is the file's number of chunk c's key i, and *file_keys the file's distinct keys in
// order of first use. Each chunk's keys are freed once merged.
void merge_chunk_keys(std::vector<BigVector<VertexKey>>* chunk_keys, uint32_t position_count,
                      BigVector<VertexKey>* file_keys, std::vector<BigVector<uint32_t>>* to_file);

}  // namespace pfx_obj

#include "obj_dedup.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "obj_parallel.hpp"
#include "obj_vertex_table.hpp"

namespace pfx_obj {

namespace {

// Variants of one position (different vt, vn or normal group) are chained from a table indexed
// by the position itself, so a lookup reads one slot of a dense array and one key — in files that
// list vertices in the order faces use them, both are already in cache. A position with more than
// kMaxChain variants (a pathological file) sends the rest to a hash table, so no lookup walks far.
constexpr uint32_t kMaxChain = 8;

// Distinct keys numbered in order of first insertion.
class VariantIndex {
 public:
  // max_keys: room reserved for that many keys up front — address space only (BigVector maps
  // without touching), so the arrays never move and copy while growing.
  VariantIndex(uint32_t position_count, uint64_t max_keys) : head_(position_count, kNoIndex) {
    keys_.reserve(max_keys);
    next_.reserve(max_keys);
  }

  uint32_t find_or_insert(const VertexKey& key) {
    uint32_t last = kNoIndex, length = 0;
    for (uint32_t id = head_[key.v]; id != kNoIndex; id = next_[id]) {
      if (keys_[id] == key) return id;
      last = id;
      ++length;
    }
    if (length < kMaxChain) {
      const uint32_t id = add(key);  // may move next_: link it afterwards
      (last == kNoIndex ? head_[key.v] : next_[last]) = id;
      return id;
    }
    if (!overflow_) overflow_ = std::make_unique<VertexTable>(1024);
    bool inserted;
    const uint32_t id = overflow_->find_or_insert(key, hash_key(key), static_cast<uint32_t>(keys_.size()), &inserted);
    if (inserted) add(key);
    return id;
  }

  BigVector<VertexKey>& keys() { return keys_; }

  // Empties the index for the next chunk, resetting only the heads its keys used.
  void clear() {
    for (const VertexKey& key : keys_) head_[key.v] = kNoIndex;
    keys_.clear();
    next_.clear();
    overflow_.reset();
  }

 private:
  uint32_t add(const VertexKey& key) {
    if (keys_.size() >= kNoIndex) throw std::length_error("more than 2^32 - 1 distinct vertices");
    keys_.push_back(key);
    next_.push_back(kNoIndex);
    return static_cast<uint32_t>(keys_.size() - 1);
  }

  BigVector<uint32_t> head_;   // per position: its first variant, or kNoIndex
  BigVector<uint32_t> next_;   // per vertex: the next variant of its position
  BigVector<VertexKey> keys_;  // in order of first insertion
  std::unique_ptr<VertexTable> overflow_;
};

// Calls visit(corner, key) for every corner of the chunk, in order.
template <typename Visit>
void for_each_corner(const DedupChunk& chunk, Visit&& visit) {
  uint64_t corner = 0;
  FaceStates states = chunk.states;
  for (uint64_t f = 0; f < chunk.face_count; ++f) {
    states.at_face(f);
    const uint32_t group = states.normal_group();
    for (uint32_t k = 0; k < chunk.faces[f].corner_count; ++k, ++corner) {
      const uint32_t* fields = chunk.corners + 3 * corner;
      visit(corner, VertexKey{fields[0], fields[1], fields[2], fields[2] == kNoIndex ? group : 0});
    }
  }
}

}  // namespace

void deduplicate(const std::vector<DedupChunk>& chunks, uint32_t position_count, unsigned threads,
                 BigVector<VertexKey>* vertices, std::vector<BigVector<uint32_t>>* corner_vertex, StageClock* clock) {
  uint64_t total_corners = 0;
  corner_vertex->assign(chunks.size(), {});
  for (size_t c = 0; c < chunks.size(); ++c) {
    total_corners += chunks[c].corner_count;
    (*corner_vertex)[c].resize(chunks[c].corner_count);
  }
  if (total_corners > kNoIndex) throw std::length_error("more than 2^32 - 1 face corners");

  if (threads <= 1 || chunks.size() == 1) {
    // Sequential: every corner straight into one index; its ids are the final vertex numbers.
    clock->time("dedup", false, [&] {
      VariantIndex index(position_count, total_corners);
      for (size_t c = 0; c < chunks.size(); ++c) {
        BigVector<uint32_t>& ids = (*corner_vertex)[c];
        for_each_corner(chunks[c], [&](uint64_t corner, const VertexKey& key) { ids[corner] = index.find_or_insert(key); });
      }
      vertices->swap(index.keys());
    });
    return;
  }

  // In parallel, each chunk's corners against an index of that chunk alone (each worker reuses
  // one); then, in file order, each chunk's distinct keys against the whole file's index; then
  // the chunks' corners renumbered in parallel. A key's number is the order of its first corner
  // in the file, exactly as in the sequential case, since each chunk lists its keys in the order
  // of their first corner in the chunk.
  std::vector<BigVector<VertexKey>> chunk_keys(chunks.size());
  std::vector<std::unique_ptr<VariantIndex>> worker_index(threads);
  uint64_t largest_chunk = 0;
  for (const DedupChunk& chunk : chunks) largest_chunk = std::max(largest_chunk, chunk.corner_count);
  clock->time("dedup chunks", true, [&] {
    run_parallel(threads, chunks.size(), [&](size_t c, unsigned worker) {
      if (!worker_index[worker]) worker_index[worker] = std::make_unique<VariantIndex>(position_count, largest_chunk);
      VariantIndex& index = *worker_index[worker];
      BigVector<uint32_t>& ids = (*corner_vertex)[c];
      for_each_corner(chunks[c], [&](uint64_t corner, const VertexKey& key) { ids[corner] = index.find_or_insert(key); });
      chunk_keys[c] = index.keys();
      index.clear();
    });
    worker_index.clear();
  });

  std::vector<BigVector<uint32_t>> to_file(chunks.size());
  clock->time("dedup merge", false, [&] {
    uint64_t chunk_key_total = 0;
    for (const auto& keys : chunk_keys) chunk_key_total += keys.size();
    VariantIndex file_index(position_count, chunk_key_total);
    for (size_t c = 0; c < chunks.size(); ++c) {
      to_file[c].resize(chunk_keys[c].size());
      for (size_t i = 0; i < chunk_keys[c].size(); ++i) to_file[c][i] = file_index.find_or_insert(chunk_keys[c][i]);
      chunk_keys[c] = {};
    }
    vertices->swap(file_index.keys());
  });
  clock->time("dedup renumber", true, [&] {
    run_parallel(threads, chunks.size(), [&](size_t c, unsigned) {
      for (uint32_t& id : (*corner_vertex)[c]) id = to_file[c][id];
    });
  });
}

}  // namespace pfx_obj

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

// The vertices of positions [first_position, first_position + count): one shard.
class Shard {
 public:
  Shard(uint32_t first_position, uint32_t count) : first_(first_position), head_(count, kNoIndex) {}

  bool owns(uint32_t v) const { return v - first_ < head_.size(); }

  uint32_t find_or_insert(const VertexKey& key, uint64_t corner) {
    const uint32_t slot = key.v - first_;
    uint32_t last = kNoIndex, length = 0;
    for (uint32_t id = head_[slot]; id != kNoIndex; id = next_[id]) {
      if (keys_[id] == key) return id;
      last = id;
      ++length;
    }
    if (length < kMaxChain) {
      const uint32_t id = add(key, corner);  // may move next_: link it afterwards
      (last == kNoIndex ? head_[slot] : next_[last]) = id;
      return id;
    }
    if (!overflow_) overflow_ = std::make_unique<VertexTable>(1024);
    bool inserted;
    const uint32_t id = overflow_->find_or_insert(key, hash_key(key), static_cast<uint32_t>(keys_.size()), &inserted);
    if (inserted) add(key, corner);
    return id;
  }

  const BigVector<VertexKey>& keys() const { return keys_; }
  const BigVector<uint64_t>& first_corners() const { return first_corners_; }

 private:
  uint32_t add(const VertexKey& key, uint64_t corner) {
    if (keys_.size() >= kNoIndex) throw std::length_error("more than 2^32 - 1 distinct vertices");
    keys_.push_back(key);
    next_.push_back(kNoIndex);
    first_corners_.push_back(corner);
    return static_cast<uint32_t>(keys_.size() - 1);
  }

  uint32_t first_;
  BigVector<uint32_t> head_;          // per position: its first variant, or kNoIndex
  BigVector<uint32_t> next_;          // per vertex: the next variant of its position
  BigVector<VertexKey> keys_;         // in order of first use within the shard
  BigVector<uint64_t> first_corners_; // the file ordinal of each key's first corner
  std::unique_ptr<VertexTable> overflow_;
};

// Calls visit(chunk, corner, key) for every corner of every chunk, in file order.
template <typename Visit>
void for_each_corner(const std::vector<DedupChunk>& chunks, Visit&& visit) {
  for (size_t c = 0; c < chunks.size(); ++c) {
    const DedupChunk& chunk = chunks[c];
    uint64_t corner = 0;
    for (uint64_t f = 0; f < chunk.face_count; ++f) {
      const uint32_t group = chunk.face_groups[f];
      for (uint32_t k = 0; k < chunk.faces[f].corner_count; ++k, ++corner) {
        const uint32_t* fields = chunk.corners + 3 * corner;
        VertexKey key{fields[0], fields[1], fields[2], fields[2] == kNoIndex ? group : 0};
        visit(c, corner, key);
      }
    }
  }
}

}  // namespace

void deduplicate(const std::vector<DedupChunk>& chunks, uint32_t position_count, unsigned threads,
                 BigVector<VertexKey>* vertices, std::vector<BigVector<uint32_t>>* corner_vertex) {
  uint64_t total_corners = 0;
  corner_vertex->assign(chunks.size(), {});
  for (size_t c = 0; c < chunks.size(); ++c) {
    total_corners += chunks[c].corner_count;
    (*corner_vertex)[c].resize(chunks[c].corner_count);
  }
  if (total_corners > kNoIndex) throw std::length_error("more than 2^32 - 1 face corners");
  const unsigned shards = std::max(1u, std::min(threads, std::max(1u, position_count / 4096)));

  if (shards == 1) {
    // The sequential case: vertex ids are final as they are handed out.
    Shard shard(0, position_count);
    for_each_corner(chunks, [&](size_t c, uint64_t corner, const VertexKey& key) {
      (*corner_vertex)[c][corner] = shard.find_or_insert(key, chunks[c].first_corner + corner);
    });
    *vertices = shard.keys();
    return;
  }

  // Each shard owns a range of positions, numbers the vertices of its corners and writes their ids
  // to its own stream (threads writing interleaved corners of one array would fight over cache
  // lines), counting how many corners of each chunk it took.
  std::vector<std::unique_ptr<Shard>> shard_data(shards);
  std::vector<BigVector<uint32_t>> streams(shards);
  std::vector<std::vector<uint64_t>> taken(shards, std::vector<uint64_t>(chunks.size(), 0));
  run_on_each_worker(shards, [&](unsigned s) {
    const uint32_t lo = static_cast<uint32_t>(uint64_t{position_count} * s / shards);
    const uint32_t hi = static_cast<uint32_t>(uint64_t{position_count} * (s + 1) / shards);
    shard_data[s] = std::make_unique<Shard>(lo, hi - lo);
    Shard& shard = *shard_data[s];
    streams[s].reserve(total_corners / shards + 1024);
    for_each_corner(chunks, [&](size_t c, uint64_t corner, const VertexKey& key) {
      if (!shard.owns(key.v)) return;
      streams[s].push_back(shard.find_or_insert(key, chunks[c].first_corner + corner));
      ++taken[s][c];
    });
  });

  // Global ids in order of first use: merge the shards' lists, each already in that order.
  uint64_t total = 0;
  for (const auto& shard : shard_data) total += shard->keys().size();
  vertices->resize(total);
  std::vector<std::vector<uint32_t>> global_id(shards);
  std::vector<size_t> head(shards, 0);
  for (unsigned s = 0; s < shards; ++s) global_id[s].resize(shard_data[s]->keys().size());
  for (uint64_t g = 0; g < total; ++g) {
    unsigned best = 0;
    uint64_t best_corner = ~uint64_t{0};
    for (unsigned s = 0; s < shards; ++s) {
      const auto& firsts = shard_data[s]->first_corners();
      if (head[s] < firsts.size() && firsts[head[s]] < best_corner) {
        best = s;
        best_corner = firsts[head[s]];
      }
    }
    global_id[best][head[best]] = static_cast<uint32_t>(g);
    (*vertices)[g] = shard_data[best]->keys()[head[best]];
    ++head[best];
  }

  // Renumber each chunk's corners, reading each shard's stream from where that chunk starts in it.
  std::vector<std::vector<uint64_t>> stream_start(chunks.size(), std::vector<uint64_t>(shards, 0));
  for (size_t c = 1; c < chunks.size(); ++c)
    for (unsigned s = 0; s < shards; ++s) stream_start[c][s] = stream_start[c - 1][s] + taken[s][c - 1];
  std::vector<uint32_t> bounds(shards + 1);
  for (unsigned s = 0; s <= shards; ++s) bounds[s] = static_cast<uint32_t>(uint64_t{position_count} * s / shards);
  run_parallel(threads, chunks.size(), [&](size_t c, unsigned) {
    BigVector<uint32_t>& ids = (*corner_vertex)[c];
    std::vector<uint64_t> at = stream_start[c];
    const uint32_t* fields = chunks[c].corners;
    for (size_t k = 0; k < ids.size(); ++k) {
      const uint32_t v = fields[3 * k];
      unsigned s = static_cast<unsigned>(uint64_t{v} * shards / position_count);
      while (v >= bounds[s + 1]) ++s;  // the integer division may land one shard low
      while (v < bounds[s]) --s;
      ids[k] = global_id[s][streams[s][at[s]++]];
    }
  });
}

}  // namespace pfx_obj

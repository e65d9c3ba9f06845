#include "obj_dedup.hpp"

#include <stdexcept>

#include "obj_parallel.hpp"
#include "obj_vertex_table.hpp"

namespace pfx_obj {

namespace {

// Which shard a hash belongs to, from its top bits (the table uses the low ones).
unsigned shard_of(uint64_t hash, unsigned shards) { return static_cast<unsigned>(((hash >> 40) * shards) >> 24); }

struct Shard {
  std::vector<VertexKey> keys;          // in order of first use within the shard
  std::vector<uint64_t> first_corners;  // the file ordinal of each key's first corner
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

void deduplicate(const std::vector<DedupChunk>& chunks, unsigned threads, std::vector<VertexKey>* vertices,
                 std::vector<std::vector<uint32_t>>* corner_vertex) {
  const unsigned shards = threads < 1 ? 1 : (threads > 64 ? 64 : threads);
  uint64_t total_corners = 0;
  corner_vertex->assign(chunks.size(), {});
  for (size_t c = 0; c < chunks.size(); ++c) {
    total_corners += chunks[c].corner_count;
    (*corner_vertex)[c].resize(chunks[c].corner_count);
  }
  if (total_corners > kNoIndex) throw std::length_error("more than 2^32 - 1 face corners");

  if (shards == 1) {
    // The sequential case: vertex ids are final as they are handed out.
    VertexTable table(total_corners / 3);
    vertices->clear();
    for_each_corner(chunks, [&](size_t c, uint64_t corner, const VertexKey& key) {
      bool inserted;
      uint32_t id = table.find_or_insert(key, hash_key(key), static_cast<uint32_t>(vertices->size()), &inserted);
      if (inserted) vertices->push_back(key);
      (*corner_vertex)[c][corner] = id;
    });
    return;
  }

  // First, which shard each corner belongs to (chunks in parallel, each writing its own range).
  std::vector<std::vector<uint8_t>> corner_shard(chunks.size());
  std::vector<std::vector<uint64_t>> shard_counts(chunks.size(), std::vector<uint64_t>(shards, 0));
  run_parallel(threads, chunks.size(), [&](size_t c, unsigned) {
    corner_shard[c].resize(chunks[c].corner_count);
    for_each_corner({chunks[c]}, [&](size_t, uint64_t corner, const VertexKey& key) {
      const unsigned s = shard_of(hash_key(key), shards);
      corner_shard[c][corner] = static_cast<uint8_t>(s);
      ++shard_counts[c][s];
    });
  });
  // Then each shard numbers its keys, writing the ids of its corners to its own stream (threads
  // writing interleaved corners of one array would fight over cache lines).
  std::vector<Shard> shard_data(shards);
  std::vector<std::vector<uint32_t>> streams(shards);
  run_on_each_worker(shards, [&](unsigned s) {
    Shard& shard = shard_data[s];
    uint64_t own = 0;
    for (const auto& counts : shard_counts) own += counts[s];
    streams[s].reserve(own);
    VertexTable table(own / 3);
    for_each_corner(chunks, [&](size_t c, uint64_t corner, const VertexKey& key) {
      if (corner_shard[c][corner] != s) return;
      bool inserted;
      uint32_t id = table.find_or_insert(key, hash_key(key), static_cast<uint32_t>(shard.keys.size()), &inserted);
      if (inserted) {
        shard.keys.push_back(key);
        shard.first_corners.push_back(chunks[c].first_corner + corner);
      }
      streams[s].push_back(id);
    });
  });

  // Global ids in order of first use: merge the shards' lists, each already in that order.
  uint64_t total = 0;
  for (const Shard& shard : shard_data) total += shard.keys.size();
  vertices->resize(total);
  std::vector<std::vector<uint32_t>> global_id(shards);
  std::vector<size_t> head(shards, 0);
  for (unsigned s = 0; s < shards; ++s) global_id[s].resize(shard_data[s].keys.size());
  for (uint64_t g = 0; g < total; ++g) {
    unsigned best = shards;
    uint64_t best_corner = ~uint64_t{0};
    for (unsigned s = 0; s < shards; ++s)
      if (head[s] < shard_data[s].keys.size() && shard_data[s].first_corners[head[s]] < best_corner) {
        best = s;
        best_corner = shard_data[s].first_corners[head[s]];
      }
    global_id[best][head[best]] = static_cast<uint32_t>(g);
    (*vertices)[g] = shard_data[best].keys[head[best]];
    ++head[best];
  }
  // Where each chunk's corners start in each shard's stream.
  std::vector<std::vector<uint64_t>> stream_start(chunks.size(), std::vector<uint64_t>(shards, 0));
  for (size_t c = 1; c < chunks.size(); ++c)
    for (unsigned s = 0; s < shards; ++s) stream_start[c][s] = stream_start[c - 1][s] + shard_counts[c - 1][s];
  run_parallel(threads, chunks.size(), [&](size_t c, unsigned) {
    std::vector<uint32_t>& ids = (*corner_vertex)[c];
    const std::vector<uint8_t>& owner = corner_shard[c];
    std::vector<uint64_t> at = stream_start[c];
    for (size_t k = 0; k < ids.size(); ++k) {
      const unsigned s = owner[k];
      ids[k] = global_id[s][streams[s][at[s]++]];
    }
  });
}

}  // namespace pfx_obj

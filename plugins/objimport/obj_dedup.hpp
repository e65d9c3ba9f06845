// One vertex per distinct face corner, keyed by its full 32-bit indices (position, texture
// coordinate, normal) and, for a corner without a normal, the normal group its normal will be
// generated for (obj_normals.hpp): nothing is packed, so nothing collides. Vertices are numbered in
// the order of their first corner in the file, by one VertexNumbering that sees every corner in
// file order (obj_numbering.cpp), so the numbers never depend on the thread count.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "obj_buffer.hpp"
#include "obj_chunk.hpp"

namespace pfx_obj {

// Smoothing group of faces before any `s` statement: smoothed together, as if `s 1`.
constexpr uint32_t kDefaultSmoothing = 1;
// Normal group of a face with smoothing off: its own ordinal in the file, marked by the top bit.
constexpr uint32_t kFlatFaceBit = 0x80000000u;

struct VertexKey {
  uint32_t v;      // 0-based position index
  uint32_t vt;     // 0-based texture coordinate index, or kNoIndex
  uint32_t vn;     // 0-based normal index, or kNoIndex
  uint32_t group;  // 0 when vn is given; otherwise the normal group of the corner's face
  bool operator==(const VertexKey& o) const { return v == o.v && vt == o.vt && vn == o.vn && group == o.group; }
};

struct VertexKeyHash {
  size_t operator()(const VertexKey& k) const {
    const uint64_t a = (uint64_t{k.v} | uint64_t{k.vt} << 32) * 0x9E3779B97F4A7C15ull;
    const uint64_t b = (uint64_t{k.vn} | uint64_t{k.group} << 32) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<size_t>(a ^ (b >> 29) ^ (b << 35));
  }
};

// Distinct keys numbered in order of first insertion. Variants of one position (different vt, vn
// or normal group) are chained from a table indexed by the position itself, so a lookup reads one
// slot of a dense array and one key — in files that list vertices in the order faces use them,
// both are already in cache. A position with more than kMaxChain variants (a pathological file)
// sends the rest to a hash table, so no lookup walks far.
class VertexNumbering {
 public:
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

  // Room for that many keys and positions, reserved before the first insertion.
  void reserve(uint64_t keys, uint64_t positions) {
    keys_.reserve(keys);
    next_.reserve(keys);
    head_.reserve(positions);
  }
  // Keys with v below position_count may be numbered from now on.
  void cover(uint32_t position_count) { if (position_count > head_.size()) head_.resize(position_count, kNoIndex); }

  // The distinct keys, in order of first insertion, taken once the last is inserted.
  BigVector<VertexKey> take_keys() { return std::move(keys_); }

 private:
  static constexpr uint32_t kMaxChain = 8;
  uint32_t add(const VertexKey& key) {
    if (keys_.size() >= kNoIndex) throw std::length_error("more than 2^32 - 1 distinct vertices");
    keys_.push_back(key);
    next_.push_back(kNoIndex);
    return static_cast<uint32_t>(keys_.size() - 1);
  }
  uint32_t find_or_insert_overflow(const VertexKey& key) {
    const auto [it, fresh] = overflow_.emplace(key, static_cast<uint32_t>(keys_.size()));
    return fresh ? add(key) : it->second;
  }

  BigVector<uint32_t> head_;   // per position: its first variant, or kNoIndex
  BigVector<uint32_t> next_;   // per vertex: the next variant of its position
  BigVector<VertexKey> keys_;  // in order of first insertion
  std::unordered_map<VertexKey, uint32_t, VertexKeyHash> overflow_;
};

}  // namespace pfx_obj

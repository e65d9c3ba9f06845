// The hash table behind deduplication: a VertexKey to a 32-bit id, open addressing with linear
// probing and the key stored in the slot, so a probe reads one cache line.
#pragma once

#include <cstdint>
#include <vector>

#include "obj_dedup.hpp"

namespace pfx_obj {

inline uint64_t hash_key(const VertexKey& k) {
  uint64_t a = (uint64_t{k.v} | uint64_t{k.vt} << 32) * 0x9E3779B97F4A7C15ull;
  uint64_t b = (uint64_t{k.vn} | uint64_t{k.group} << 32) * 0xC2B2AE3D27D4EB4Full;
  uint64_t h = a ^ ((b << 31) | (b >> 33));
  h ^= h >> 32;
  h *= 0xD6E8FEB86659FD93ull;
  h ^= h >> 32;
  return h;
}

// Open addressing with linear probing; the key is stored in the slot so a probe touches one line.
class VertexTable {
 public:
  explicit VertexTable(uint64_t expected) {
    uint64_t capacity = 1024;
    while (capacity < expected + expected / 2) capacity *= 2;
    resize(capacity);
  }

  // The id of key, inserting it as `next_id` when new (then *inserted is true).
  uint32_t find_or_insert(const VertexKey& key, uint64_t hash, uint32_t next_id, bool* inserted) {
    for (uint64_t i = hash & mask_;; i = (i + 1) & mask_) {
      Slot& slot = slots_[i];
      if (slot.id == kNoIndex) {
        slot.key = key;
        slot.id = next_id;
        *inserted = true;
        if (++size_ * 5 > slots_.size() * 3) grow();
        return next_id;
      }
      if (slot.key == key) {
        *inserted = false;
        return slot.id;
      }
    }
  }

 private:
  struct Slot {
    VertexKey key;
    uint32_t id;
  };

  void resize(uint64_t capacity) {
    slots_.assign(capacity, Slot{{0, 0, 0, 0}, kNoIndex});
    mask_ = capacity - 1;
  }

  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    resize(old.size() * 2);
    for (const Slot& slot : old) {
      if (slot.id == kNoIndex) continue;
      uint64_t i = hash_key(slot.key) & mask_;
      while (slots_[i].id != kNoIndex) i = (i + 1) & mask_;
      slots_[i] = slot;
    }
  }

  std::vector<Slot> slots_;
  uint64_t mask_ = 0;
  uint64_t size_ = 0;
};

}  // namespace pfx_obj

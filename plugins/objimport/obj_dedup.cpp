#include "obj_dedup.hpp"

#include <algorithm>
#include <stdexcept>


namespace pfx_obj {

void VertexNumbering::grow(uint32_t position_count, uint64_t position_room, uint64_t key_count, uint64_t key_room) {
  if (key_count > keys_.capacity()) {
    const uint64_t room = std::max({key_count, key_room, 2 * uint64_t{keys_.capacity()}});
    keys_.reserve(room);
    next_.reserve(room);
  }
  if (position_count > head_.capacity())
    head_.reserve(std::max({uint64_t{position_count}, position_room, 2 * uint64_t{head_.capacity()}}));
  if (position_count > head_.size()) head_.resize(position_count, kNoIndex);
}

uint32_t VertexNumbering::add(const VertexKey& key) {
  if (keys_.size() >= kNoIndex) throw std::length_error("more than 2^32 - 1 distinct vertices");
  keys_.push_back(key);
  next_.push_back(kNoIndex);
  return static_cast<uint32_t>(keys_.size() - 1);
}

}  // namespace pfx_obj

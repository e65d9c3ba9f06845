#include "obj_dedup.hpp"

#include <algorithm>
#include <stdexcept>

#include "obj_vertex_table.hpp"

namespace pfx_obj {

VertexNumbering::VertexNumbering() = default;
VertexNumbering::~VertexNumbering() = default;

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

uint32_t VertexNumbering::find_or_insert_overflow(const VertexKey& key) {
  if (!overflow_) overflow_ = std::make_unique<VertexTable>(1024);
  bool inserted;
  const uint32_t id = overflow_->find_or_insert(key, hash_key(key), static_cast<uint32_t>(keys_.size()), &inserted);
  if (inserted) add(key);
  return id;
}

}  // namespace pfx_obj

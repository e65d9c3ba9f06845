#include "obj_dedup.hpp"

#include <algorithm>
#include <stdexcept>

#include "obj_vertex_table.hpp"

namespace pfx_obj {

VertexNumbering::VertexNumbering(uint32_t position_count, uint64_t max_keys) : head_(position_count, kNoIndex) {
  keys_.reserve(max_keys);
  next_.reserve(max_keys);
}

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

void VertexNumbering::clear() {
  for (const VertexKey& key : keys_) head_[key.v] = kNoIndex;
  keys_.clear();
  next_.clear();
  overflow_.reset();
}

void VertexNumbering::keep_pages_for_reuse() {
  free_array(&keys_);
  keep_for_reuse(&head_);
  keep_for_reuse(&next_);
  overflow_.reset();
}

void merge_chunk_keys(std::vector<BigVector<VertexKey>>* chunk_keys, uint32_t position_count,
                      BigVector<VertexKey>* file_keys, std::vector<BigVector<uint32_t>>* to_file) {
  uint64_t total = 0;
  for (const auto& keys : *chunk_keys) total += keys.size();
  VertexNumbering file(position_count, total);
  to_file->assign(chunk_keys->size(), {});
  for (size_t c = 0; c < chunk_keys->size(); ++c) {
    BigVector<VertexKey>& keys = (*chunk_keys)[c];
    BigVector<uint32_t>& map = (*to_file)[c];
    map.resize(keys.size());
    for (size_t i = 0; i < keys.size(); ++i) map[i] = file.find_or_insert(keys[i]);
    free_array(&keys);
  }
  file_keys->swap(file.keys());
}

}  // namespace pfx_obj

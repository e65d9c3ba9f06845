#include "obj_dedup.hpp"

#include <algorithm>
#include <stdexcept>


namespace pfx_obj {

uint32_t VertexNumbering::add(const VertexKey& key) {
  if (keys_.size() >= kNoIndex) throw std::length_error("more than 2^32 - 1 distinct vertices");
  keys_.push_back(key);
  next_.push_back(kNoIndex);
  return static_cast<uint32_t>(keys_.size() - 1);
}

}  // namespace pfx_obj

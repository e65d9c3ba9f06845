// The vertex data of every chunk seen as one array per kind, without copying it together: element
// i of the file lies in the chunk whose range holds it. Readers remember the chunk of their last
// lookup, so lookups in nearly increasing order (vertices numbered by first use) cost a compare.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pfx_obj {

class ChunkedElements {
  struct Part {
    uint32_t first, end;
    const float* data;
  };

 public:
  // width: floats per element. absent: what a chunk without data (null) gives for each of its
  // elements (colours: white where a chunk's v had none).
  explicit ChunkedElements(size_t width, const float* absent = nullptr) : width_(width), absent_(absent) {}

  // Chunks in file order: elements [first, first + count) of the file, at data (or null).
  void add(uint32_t first, uint32_t count, const float* data) {
    if (count > 0) parts_.push_back({first, first + count, data});
  }

  class Reader {
   public:
    explicit Reader(const ChunkedElements& elements) : elements_(elements) {}
    // Element i, which must lie in an added range.
    const float* at(uint32_t i) {
      if (!part_ || i < part_->first || i >= part_->end) {
        const auto& parts = elements_.parts_;
        part_ = &*(std::upper_bound(parts.begin(), parts.end(), i, [](uint32_t v, const Part& p) { return v < p.first; }) - 1);
      }
      return part_->data ? part_->data + size_t{i - part_->first} * elements_.width_ : elements_.absent_;
    }

   private:
    const ChunkedElements& elements_;
    const Part* part_ = nullptr;
  };

 private:
  size_t width_;
  const float* absent_;
  std::vector<Part> parts_;
};

}  // namespace pfx_obj

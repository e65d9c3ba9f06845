// A file's bytes in one piece: mapped read-only when it is a regular file (no copy), read in one
// go otherwise (a pipe, /dev/stdin).
#pragma once

#include <string>
#include <string_view>

namespace pfx_obj {

class FileBytes {
 public:
  FileBytes() = default;
  ~FileBytes();
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  // False with *error = "PATH: reason" (no such file, a folder, unreadable, ...).
  bool open(const std::string& path, std::string* error);
  std::string_view bytes() const { return {data_, size_}; }
  // Whether bytes() is this object's own read-only mapping of the file, whose pages
  // release_read_pages may drop.
  bool mapped() const { return mapping_ != nullptr; }

 private:
  const char* data_ = "";
  size_t size_ = 0;
  void* mapping_ = nullptr;
  std::string copy_;
};

// Drops the pages wholly inside `range` — part of a FileBytes mapping — from this process's page
// tables; a later read maps them again from the page cache, so the bytes stay readable. The parser
// calls it for each chunk as soon as that chunk is parsed: unmapping the whole file at the end
// cost one thread 3-5 ms at 99 MB, which this spreads over the parsing threads, and a large
// file's pages no longer all count towards the import's peak memory at once.
void release_read_pages(std::string_view range);

// The whole of a small file (a material library) as a string; false when it cannot be read.
bool read_small_file(const std::string& path, std::string* out, std::string* error);

}  // namespace pfx_obj

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
  // Drops the mapped pages wholly inside `range`, a part of bytes() already read, from this
  // process's page tables (a later read maps them again from the page cache), so that a large
  // file does not count whole towards the import's resident memory. Nothing for a copy.
  void drop_pages(std::string_view range) const;

 private:
  const char* data_ = "";
  size_t size_ = 0;
  void* mapping_ = nullptr;
  std::string copy_;
};

}  // namespace pfx_obj

// A file's bytes in one piece: mapped read-only when it is a regular file (no copy), read in one
// go otherwise (a pipe, /dev/stdin).
#pragma once

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace pfx_obj {

class FileBytes {
 public:
  FileBytes() = default;
  ~FileBytes() { if (mapping_) ::munmap(mapping_, size_); }
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  // False with *error = "PATH: reason" (no such file, a folder, unreadable, ...).
  bool open(const std::string& path, std::string* error) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    const bool ok = fd >= 0 && read_whole(fd, path, error);
    if (fd < 0) *error = path + ": " + (errno == ENOENT ? std::string("no such file") : std::strerror(errno));
    if (fd >= 0) ::close(fd);
    return ok;
  }
  std::string_view bytes() const { return {data_, size_}; }

  // Drops the mapped pages wholly inside `range`, a part of bytes() already read, from this
  // process's page tables (a later read maps them again from the page cache), so that a large
  // file does not count whole towards the import's resident memory. Nothing for a copy.
  void drop_pages(std::string_view range) const {
    if (!mapping_) return;
    const uintptr_t page = static_cast<uintptr_t>(::sysconf(_SC_PAGESIZE));
    const uintptr_t begin = (reinterpret_cast<uintptr_t>(range.data()) + page - 1) / page * page;
    const uintptr_t end = (reinterpret_cast<uintptr_t>(range.data()) + range.size()) / page * page;
    if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
  }

 private:
  bool read_whole(int fd, const std::string& path, std::string* error) {
    struct stat info {};
    if (::fstat(fd, &info) != 0 || S_ISDIR(info.st_mode)) {
      *error = path + ": " + (S_ISDIR(info.st_mode) ? std::string("is a folder, not a file") : std::strerror(errno));
      return false;
    }
    if (S_ISREG(info.st_mode) && info.st_size > 0) {
      // Not populated up front: the reading threads fault the pages in as they read, in parallel.
      void* mapping = ::mmap(nullptr, static_cast<size_t>(info.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
      if (mapping != MAP_FAILED) {
        size_ = static_cast<size_t>(info.st_size);
        ::madvise(mapping, size_, MADV_SEQUENTIAL);  // the parser reads front to back, each chunk by one thread
        ::madvise(mapping, size_, MADV_WILLNEED);
        mapping_ = mapping;
        data_ = static_cast<const char*>(mapping);
        return true;
      }
    }
    char buffer[1 << 16];  // not a regular file (a pipe, /dev/stdin), or not mappable: read whole
    while (const ssize_t n = ::read(fd, buffer, sizeof buffer)) {  // (0: the end)
      if (n > 0) copy_.append(buffer, static_cast<size_t>(n));
      if (n < 0 && errno != EINTR) {
        *error = path + ": " + std::strerror(errno);
        return false;
      }
    }
    data_ = copy_.data();
    size_ = copy_.size();
    return true;
  }

  const char* data_ = "";
  size_t size_ = 0;
  void* mapping_ = nullptr;
  std::string copy_;
};

}  // namespace pfx_obj

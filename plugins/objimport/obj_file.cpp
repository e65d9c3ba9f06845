#include "obj_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace pfx_obj {

namespace {

struct Descriptor {
  int fd;
  ~Descriptor() { if (fd >= 0) ::close(fd); }
};

}  // namespace

FileBytes::~FileBytes() {
  if (mapping_) ::munmap(mapping_, size_);
}

bool FileBytes::open(const std::string& path, std::string* error) {
  Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  struct stat info {};
  if (file.fd < 0 || ::fstat(file.fd, &info) != 0 || S_ISDIR(info.st_mode)) {
    *error = path + ": " + (file.fd >= 0 && S_ISDIR(info.st_mode) ? std::string("is a folder, not a file")
                            : errno == ENOENT ? std::string("no such file") : std::strerror(errno));
    return false;
  }
  if (S_ISREG(info.st_mode) && info.st_size > 0) {
    // Not populated up front: the reading threads fault the pages in as they read, in parallel.
    void* mapping = ::mmap(nullptr, static_cast<size_t>(info.st_size), PROT_READ, MAP_PRIVATE, file.fd, 0);
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
  for (ssize_t n; (n = ::read(file.fd, buffer, sizeof buffer)) != 0;) {
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

void FileBytes::drop_pages(std::string_view range) const {
  if (!mapping_) return;
  const uintptr_t page = static_cast<uintptr_t>(::sysconf(_SC_PAGESIZE));
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(range.data()) + page - 1) / page * page;
  const uintptr_t end = (reinterpret_cast<uintptr_t>(range.data()) + range.size()) / page * page;
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
}

}  // namespace pfx_obj

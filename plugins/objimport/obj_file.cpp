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

bool read_all(int fd, std::string* out) {
  char buffer[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) return true;
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    out->append(buffer, static_cast<size_t>(n));
  }
}

bool open_for_reading(const std::string& path, Descriptor* file, struct stat* info, std::string* error) {
  file->fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (file->fd < 0) {
    *error = path + ": " + (errno == ENOENT ? std::string("no such file") : std::strerror(errno));
    return false;
  }
  if (::fstat(file->fd, info) != 0) {
    *error = path + ": " + std::strerror(errno);
    return false;
  }
  if (S_ISDIR(info->st_mode)) {
    *error = path + ": is a folder, not a file";
    return false;
  }
  return true;
}

}  // namespace

FileBytes::~FileBytes() {
  if (mapping_) ::munmap(mapping_, size_);
}

bool FileBytes::open(const std::string& path, std::string* error) {
  Descriptor file{-1};
  struct stat info {};
  if (!open_for_reading(path, &file, &info, error)) return false;
  if (S_ISREG(info.st_mode) && info.st_size > 0) {
    size_ = static_cast<size_t>(info.st_size);
    // Not populated up front: the reading threads fault the pages in as they read, in parallel.
    void* mapping = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, file.fd, 0);
    if (mapping != MAP_FAILED) {
      // The parser reads front to back, each chunk by one thread.
      ::madvise(mapping, size_, MADV_SEQUENTIAL);
      ::madvise(mapping, size_, MADV_WILLNEED);
      mapping_ = mapping;
      data_ = static_cast<const char*>(mapping);
      return true;
    }
    size_ = 0;
  }
  if (!read_all(file.fd, &copy_)) {
    *error = path + ": " + std::strerror(errno);
    return false;
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

bool read_small_file(const std::string& path, std::string* out, std::string* error) {
  FileBytes file;
  if (!file.open(path, error)) return false;
  out->assign(file.bytes());
  return true;
}

}  // namespace pfx_obj

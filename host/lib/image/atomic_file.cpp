#include "atomic_file.hpp"

#include <fstream>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pfx::app {
namespace {

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string name_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Data must reach the disk before the rename, or a crash could leave an empty file under the
// final name on some file systems.
bool flush_to_disk(const std::string& file, std::string* reason) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    *reason = std::string("cannot reopen the temporary file: ") + std::strerror(errno);
    return false;
  }
  // Some file systems (e.g. certain FUSE mounts) do not support fsync; that is no reason to
  // lose the output, so only real I/O errors count.
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL || errno == EROFS || errno == ENOTSUP;
  const int saved = errno;
  ::close(fd);
  if (!ok) *reason = std::string("cannot flush to disk: ") + std::strerror(saved);
  return ok;
}

std::string temp_path_prefix_for(const std::string& path) {
  const std::string folder = folder_of(path);
  const std::string prefix = "." + name_of(path) + ".tmp-" + std::to_string(::getpid()) + "-";
  // Keep the caller's spelling for a bare file name so messages stay readable.
  return path.find('/') == std::string::npos ? prefix : folder + "/" + prefix;
}

}  // namespace

bool write_atomically(const std::string& path, const WriteFileFn& write, std::string* error) {
  auto fail = [&](const std::string& reason) {
    if (error) *error = "cannot write " + path + ": " + reason;
    return false;
  };
  if (path.empty()) return fail("empty path");
  if (name_of(path).empty()) return fail("the path names a folder, not a file");

  const std::string folder = folder_of(path);
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0) {
    return fail("folder " + folder + " does not exist or is not accessible (" +
                std::strerror(errno) + ")");
  }
  if (!S_ISDIR(st.st_mode)) return fail(folder + " is not a folder");

  // The counter keeps two writers in one process (threads) from sharing a temporary name.
  static std::atomic<unsigned> counter{0};
  const std::string temp = temp_path_prefix_for(path) + std::to_string(counter++);

  std::string reason;
  bool ok = false;
  try {
    ok = write(temp, &reason);
  } catch (const std::exception& e) {
    reason = std::string("unexpected error: ") + e.what();
  } catch (...) {
    reason = "unexpected error";
  }
  if (ok) ok = flush_to_disk(temp, &reason);
  if (ok && std::rename(temp.c_str(), path.c_str()) != 0) {
    reason = std::string("cannot rename the temporary file into place: ") + std::strerror(errno);
    ok = false;
  }
  if (!ok) {
    std::remove(temp.c_str());
    return fail(reason.empty() ? "unknown error" : reason);
  }
  return true;
}

bool write_text_atomically(const std::string& path, const std::string& text, std::string* error) {
  return write_atomically(
      path,
      [&](const std::string& temp_path, std::string* reason) {
        std::ofstream out(temp_path, std::ios::binary);
        out << text;
        out.close();
        if (!out) *reason = "write failed";
        return static_cast<bool>(out);
      },
      error);
}

}  // namespace pfx::app

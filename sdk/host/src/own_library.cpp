#include "own_library.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace pfx::host {
namespace {

// Which owner holds which library handle: one entry per open, so an owner opening a library twice
// holds it twice. Never destroyed, so that a registry in static storage, destroyed at exit after
// any function-local static, still finds it.
struct Holders {
  std::mutex mutex;
  std::vector<std::pair<void*, const void*>> held;  // (library, owner)
};

Holders& holders() {
  static Holders* const all = new Holders;
  return *all;
}

// Records that `owner` holds `library`, unless `only_if_unshared` and another owner holds it.
bool hold(const void* owner, void* library, bool only_if_unshared) {
  Holders& all = holders();
  std::lock_guard<std::mutex> lock(all.mutex);
  if (only_if_unshared)
    for (const auto& [held, by] : all.held)
      if (held == library && by != owner) return false;
  all.held.emplace_back(library, owner);
  return true;
}

// The loader's message (it starts with the file's name) with `file` shown as `shown_as`.
std::string loader_error(const std::string& file, const std::string& shown_as) {
  const char* text = dlerror();
  std::string message = text ? text : "unknown dlopen error";
  for (size_t at = message.find(file); at != std::string::npos; at = message.find(file, at + shown_as.size()))
    message.replace(at, file.size(), shown_as);
  return message;
}

// RTLD_LOCAL: two plugins never bind each other's symbols. RTLD_NOW: a missing symbol is an error
// now, not a crash in the middle of a frame.
void* open_library(const std::string& file) { return dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL); }

}  // namespace

// The name does not end in .so, so a folder scan never picks the copy up; it starts with a dot, so
// a listing hides it. The folder beside the original comes first: a temporary folder may be
// mounted noexec.
bool make_private_copy(const std::string& path, std::string* copy, std::string* reason) {
  static std::atomic<uint64_t> serial{0};
  const fs::path original(path);
  const std::string name = "." + original.filename().string() + ".pfx-private-" + std::to_string(::getpid()) + "-" +
                           std::to_string(++serial);
  std::error_code ec;
  for (const fs::path& folder : {original.parent_path(), fs::temp_directory_path(ec)}) {
    fs::path candidate = folder / name;
    if (fs::copy_file(original, candidate, fs::copy_options::overwrite_existing, ec)) {
      *copy = candidate.string();
      return true;
    }
    *reason = ec.message();
  }
  return false;
}

// The handle is recorded after dlopen and forgotten before dlclose, outside the lock both times:
// no lock of ours is held while the loader runs a library's constructors or destructors. Two
// owners opening the same file at once get the same handle; whichever records it second loads a
// copy. An owner closing records nothing more after its plugin's deinit, so another owner that
// still finds the handle held takes a copy, and one that no longer finds it finds deinit done.
void* open_own_library(const void* owner, const std::string& file, const std::string& shown_as, std::string* reason) {
  void* library = open_library(file);
  if (!library) {
    *reason = loader_error(file, shown_as);
    return nullptr;
  }
  if (hold(owner, library, true)) return library;
  dlclose(library);  // another owner's: its plugin's globals belong to that owner's host

  const std::string why = "another registry of this process holds the library, and ";
  std::string copy;
  if (!make_private_copy(file, &copy, reason)) {
    *reason = why + "no private copy can be made: " + *reason;
    return nullptr;
  }
  library = open_library(copy);
  if (!library) *reason = why + "its private copy cannot be loaded: " + loader_error(copy, shown_as);
  std::error_code ec;
  fs::remove(copy, ec);  // the mapping keeps the library alive
  if (library) hold(owner, library, false);
  return library;
}

void close_own_library(const void* owner, void* library) {
  if (!library) return;
  {
    Holders& all = holders();
    std::lock_guard<std::mutex> lock(all.mutex);
    auto it = std::find(all.held.begin(), all.held.end(), std::make_pair(library, owner));
    if (it != all.held.end()) all.held.erase(it);
  }
  dlclose(library);
}

}  // namespace pfx::host

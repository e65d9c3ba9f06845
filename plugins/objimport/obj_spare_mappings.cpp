#include "obj_spare_mappings.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <mutex>
#include <vector>

namespace pfx_obj {

namespace {

struct Spare {
  void* p;
  size_t bytes, written;
};

std::mutex spares_mutex;
std::vector<Spare> spares;

size_t whole_pages(size_t bytes) {
  static const size_t page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
  return (bytes + page - 1) / page * page;
}

}  // namespace

void keep_spare_mapping(void* p, size_t bytes, size_t written) {
  std::lock_guard<std::mutex> lock(spares_mutex);
  try {
    spares.push_back({p, whole_pages(bytes), written});
  } catch (...) {
    ::munmap(p, bytes);  // no room to remember it: simply freed
  }
}

void* take_spare_mapping(size_t bytes) {
  const size_t want = whole_pages(bytes);
  std::lock_guard<std::mutex> lock(spares_mutex);
  size_t best = spares.size();
  for (size_t i = 0; i < spares.size(); ++i)
    if (spares[i].bytes >= want && (best == spares.size() || spares[i].written > spares[best].written)) best = i;
  if (best == spares.size()) return nullptr;
  Spare spare = spares[best];
  // The start is taken (the caller frees `bytes` later). The rest stays kept where it has written
  // pages — a small array takes a piece of a large mapping, not all of it — and is unmapped where
  // it has none.
  if (spare.bytes > want) {
    char* rest = static_cast<char*>(spare.p) + want;
    if (spare.written > want) {
      spares[best] = {rest, spare.bytes - want, spare.written - want};
      return spare.p;
    }
    if (::munmap(rest, spare.bytes - want) != 0) {
      spares.erase(spares.begin() + static_cast<std::ptrdiff_t>(best));
      ::munmap(spare.p, spare.bytes);
      return nullptr;
    }
  }
  spares.erase(spares.begin() + static_cast<std::ptrdiff_t>(best));
  return spare.p;
}

void release_spare_mappings() {
  std::vector<Spare> all;
  {
    std::lock_guard<std::mutex> lock(spares_mutex);
    all.swap(spares);
  }
  for (const Spare& spare : all) ::munmap(spare.p, spare.bytes);
}

}  // namespace pfx_obj

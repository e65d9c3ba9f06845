// Giving a large result's memory back on the threads it was imported with. Freeing its arrays on
// one thread after a two-thread import of 487 MB took 14.3 ms (median of 7; 9.1 ms after a
// one-thread import): the kernel's work of unmapping the written pages, half of them last
// touched on the other core. Two threads each calling munmap mostly wait for each other's hold
// on the address space; madvise(MADV_DONTNEED) holds it only for reading, so the threads drop the
// pages side by side — 7.0 ms — and the unmapping that frees each array afterwards finds none
// left. (Another day, 9 runs: 9.4 against 5.0 ms; docs/importers/obj.md, session 9.)
#pragma once

#include <cstddef>
#include <vector>

#include <pfx/services.h>

#include "obj_import.hpp"
#include "obj_pages.hpp"

namespace pfx_obj {

// Drops the whole pages inside the ranges on at most `threads` workers of the host's pool (their
// contents read as zero after). The ranges must be the caller's own mappings, about to be
// unmapped; a page only partly inside is left alone. Nothing at all without a pool, on one
// thread, or below kMinParallelFreeBytes.
void drop_pages_in_parallel(const pfx_thread_pool* pool, unsigned threads, const std::vector<ByteRange>& ranges);

// Below this, handing the work to other threads costs about as much as it saves (measured when the
// importer started its own: 0.05-0.15 ms to start a thread; freeing 8 MB on one thread takes about
// 0.7 ms).
constexpr size_t kMinParallelFreeBytes = size_t{8} << 20;

// Frees the mesh's vertex and index arrays, their pages dropped on `threads` workers first.
void free_mesh_in_parallel(const pfx_thread_pool* pool, unsigned threads, ObjMesh* mesh);

}  // namespace pfx_obj

// The parallel parse gives the same bytes for any thread count and any chunk size: a generated
// file using every statement (relative indices across chunk boundaries, material and smoothing
// changes, colours, polygons, line continuations, CRLF) is imported many ways and compared. And the
// workers' placement (obj_helper_thread.hpp) leaves the caller's CPU affinity as it found it.
#include <sched.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "obj_parallel.hpp"
#include "obj_test_support.hpp"

using pfx_obj_test::check_same;
using pfx_obj_test::import_text;
using pfx_obj_test::varied_file;


TEST_CASE("obj threads: the same output for any thread count and chunk size", "[objimport][threads]") {
  const std::string text = varied_file(20000, 99);
  auto reference = import_text(text, 1, size_t{1} << 30);  // one chunk, one thread: the sequential parse
  REQUIRE(reference.ok);
  REQUIRE(reference.mesh.submeshes.size() == 4);  // m0, m1, m2 and the faces before any usemtl
  REQUIRE_FALSE(reference.mesh.colors.empty());
  // Chunk by chunk (obj_streamed.cpp, the default) and through the staged pipeline.
  for (bool streamed : {true, false})
    for (unsigned threads : {1u, 2u, 3u, 4u, 7u})
      for (size_t chunk : {size_t{0}, size_t{97}, size_t{4096}, size_t{100000}}) {
        INFO((streamed ? "streamed" : "staged") << ", threads " << threads << ", chunk bytes " << chunk);
        auto r = import_text(text, threads, chunk, "", true, streamed);
        REQUIRE(r.ok);
        check_same(reference.mesh, r.mesh);
      }
}

TEST_CASE("obj threads: the first error in file order wins whatever the cut", "[objimport][threads]") {
  std::string text = varied_file(3000, 5);
  const size_t middle = text.find("\nf ", text.size() / 2);
  text.insert(middle + 1, "f 1 2 0\n");  // an error in the middle...
  text += "f 1 2 999999\n";              // ...and a later one of another stage
  auto reference = import_text(text, 1, size_t{1} << 30);
  REQUIRE_FALSE(reference.ok);
  CHECK(reference.error.find("index 0") != std::string::npos);
  for (bool streamed : {true, false})
    for (unsigned threads : {2u, 5u})
      for (size_t chunk : {size_t{64}, size_t{5000}}) {
        auto r = import_text(text, threads, chunk, "", true, streamed);
        CHECK(r.error == reference.error);
      }
}

TEST_CASE("obj threads: a relative index reaching exactly one chunk back (found by the fuzzer)", "[objimport][threads]") {
  // With tiny chunks the face's chunk has no vn of its own, so "-1" is stored as position 0 of
  // that chunk — which once read as "no normal" and gave the corner a generated one.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 -1 0\nf 1//-1 2//-1 3//-1\n";
  auto whole = import_text(text, 1, size_t{1} << 30);
  REQUIRE(whole.ok);
  CHECK(whole.mesh.normals == std::vector<float>{0, -1, 0, 0, -1, 0, 0, -1, 0});
  for (bool streamed : {true, false})
    for (size_t chunk : {size_t{1}, size_t{5}, size_t{11}}) {
      auto cut = import_text(text, 2, chunk, "", true, streamed);
      REQUIRE(cut.ok);
      CHECK(cut.mesh.normals == whole.mesh.normals);
    }
}

namespace {

cpu_set_t affinity_now() {
  cpu_set_t set;
  CPU_ZERO(&set);
  REQUIRE(sched_getaffinity(0, sizeof set, &set) == 0);
  return set;
}

// Each worker's CPU affinity during one run_parallel of `threads` workers. Jobs are handed out as
// workers ask, so each job waits until every one has started: no worker takes two. The workers
// call sched_getaffinity themselves, not affinity_now: Catch's assertions are for the test's own
// thread only.
std::vector<cpu_set_t> affinity_of_each_worker(unsigned threads) {
  std::vector<cpu_set_t> seen(threads);
  std::vector<char> ran(threads, 0);
  std::atomic<unsigned> started{0};
  pfx_obj::run_parallel(threads, threads, [&](size_t, unsigned worker) {
    CPU_ZERO(&seen[worker]);
    sched_getaffinity(0, sizeof seen[worker], &seen[worker]);
    ran[worker] = 1;
    ++started;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (started.load() < threads && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
  });
  REQUIRE(std::count(ran.begin(), ran.end(), 1) == static_cast<long>(threads));
  return seen;
}

}  // namespace

TEST_CASE("obj threads: workers pinned to distinct CPUs only while a run lasts", "[objimport][threads]") {
  const cpu_set_t before = affinity_now();
  const unsigned cpus = static_cast<unsigned>(CPU_COUNT(&before));
  if (cpus >= 2) {
    // As many workers as allowed CPUs (at most 4): each pinned to a CPU of its own during the run.
    const unsigned workers = std::min(cpus, 4u);
    const std::vector<cpu_set_t> seen = affinity_of_each_worker(workers);
    for (unsigned w = 0; w < workers; ++w) {
      INFO("worker " << w << " of " << workers);
      REQUIRE(CPU_COUNT(&seen[w]) == 1);
      cpu_set_t inside;
      CPU_AND(&inside, &seen[w], &before);
      CHECK(CPU_COUNT(&inside) == 1);  // within the caller's allowed set
      for (unsigned other = 0; other < w; ++other) CHECK_FALSE(CPU_EQUAL(&seen[w], &seen[other]));
    }
  }
  // One worker, or more workers than CPUs: none pinned (helpers allow themselves every CPU of the
  // caller's set once started).
  for (unsigned threads : {1u, cpus + 1}) {
    const std::vector<cpu_set_t> seen = affinity_of_each_worker(threads);
    for (unsigned w = 0; w < threads; ++w) {
      INFO("worker " << w << " of " << threads);
      CHECK(CPU_EQUAL(&seen[w], &before));
    }
  }
  // The caller's affinity comes back after every run, an import that fails included.
  const cpu_set_t between = affinity_now();
  CHECK(CPU_EQUAL(&before, &between));
  auto failed = import_text("v 0 0 0\nf 1 2 3 4 5\n", 2, 4);
  CHECK_FALSE(failed.ok);
  auto fine = import_text(varied_file(2000, 3), 2, 4096);
  CHECK(fine.ok);
  const cpu_set_t after = affinity_now();
  CHECK(CPU_EQUAL(&before, &after));
}

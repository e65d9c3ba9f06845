// The parallel parse gives the same bytes for any thread count and any chunk size: a generated
// file using every statement (relative indices across chunk boundaries, material and smoothing
// changes, colours, polygons, line continuations, CRLF) is imported many ways and compared, on
// pools that run fewer tasks at once than they offer too. And the importer works on the host's
// threads alone: it starts none and changes no thread's affinity, scheduling or signal mask.
#include <dirent.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <pfx/host/plugin_registry.hpp>
#include <pfx/host/thread_pool.hpp>

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
  for (unsigned threads : {1u, 2u, 3u, 4u, 7u})
      for (size_t chunk : {size_t{0}, size_t{97}, size_t{4096}, size_t{100000}}) {
        INFO("threads " << threads << ", chunk bytes " << chunk);
        auto r = import_text(text, threads, chunk);
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
  for (unsigned threads : {2u, 5u})
      for (size_t chunk : {size_t{64}, size_t{5000}}) {
        auto r = import_text(text, threads, chunk);
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
  for (size_t chunk : {size_t{1}, size_t{5}, size_t{11}}) {
      auto cut = import_text(text, 2, chunk);
      REQUIRE(cut.ok);
      CHECK(cut.mesh.normals == whole.mesh.normals);
    }
}

namespace {

// A pool that offers four tasks at once but runs a run's tasks one after another on the calling
// thread (the contract allows it, as it allows a nested run to run serially): an importer whose
// tasks waited for each other would hang here.
struct SerialPool {
  pfx_thread_pool service{sizeof(pfx_thread_pool), nullptr, [](void*) -> uint32_t { return 4; },
                          [](void*, pfx_task_fn task, void* user, uint32_t count, uint32_t) {
                            for (uint32_t i = 0; i < count; ++i) task(user, i);
                          }};
};

// A pool that offers four tasks at once but has two: a run of four tasks gets two at a time.
struct NarrowPool {
  pfx::host::ThreadPool inner{2};
  pfx_thread_pool service{sizeof(pfx_thread_pool), &inner, [](void*) -> uint32_t { return 4; },
                          [](void* data, pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel) {
                            static_cast<pfx::host::ThreadPool*>(data)->run(task, user, count, max_parallel);
                          }};
};

}  // namespace

TEST_CASE("obj threads: the same output on a pool that runs fewer tasks at once than it offers", "[objimport][threads]") {
  const std::string text = varied_file(6000, 17);
  auto reference = import_text(text, 1, size_t{1} << 30);
  REQUIRE(reference.ok);
  SerialPool serial;
  NarrowPool narrow;
  for (const pfx_thread_pool* pool : {&serial.service, &narrow.service})
      for (size_t chunk : {size_t{0}, size_t{97}, size_t{4096}}) {
        INFO((pool == &serial.service ? "serial" : "narrow") << ", chunk bytes " << chunk);
        pfx_obj::ImportOptions options;
        options.pool = pool;
        options.threads = 0;  // all four the pool offers
        options.chunk_bytes = chunk;
        pfx_obj::ObjMesh mesh;
        std::string error;
        REQUIRE(pfx_obj::import_obj_text(text, "test.obj", "", options, &mesh, &error));
        check_same(reference.mesh, mesh);
      }
}

namespace {

int threads_in_process() {
  int n = 0;
  DIR* tasks = opendir("/proc/self/task");
  if (!tasks) return -1;
  while (dirent* entry = readdir(tasks))
    if (entry->d_name[0] != '.') ++n;
  closedir(tasks);
  return n;
}

// What a thread's owner decides and a guest must leave alone.
struct ThreadState {
  cpu_set_t affinity;
  int policy = 0, priority = 0, nice = 0;
  sigset_t blocked;
  static ThreadState now() {
    ThreadState s;
    CPU_ZERO(&s.affinity);
    sched_getaffinity(0, sizeof s.affinity, &s.affinity);
    sched_param param{};
    pthread_getschedparam(pthread_self(), &s.policy, &param);
    s.priority = param.sched_priority;
    s.nice = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
    sigemptyset(&s.blocked);
    pthread_sigmask(SIG_BLOCK, nullptr, &s.blocked);
    return s;
  }
  bool operator==(const ThreadState& o) const {
    if (!CPU_EQUAL(&affinity, &o.affinity) || policy != o.policy || priority != o.priority || nice != o.nice) return false;
    for (int sig = 1; sig < NSIG; ++sig)
      if (sigismember(&blocked, sig) != sigismember(&o.blocked, sig)) return false;
    return true;
  }
};

// The host's pool as a plugin gets it, with every task checked: the thread it ran on is in the
// same state after the task as before.
struct CheckingPool {
  pfx::host::ThreadPool inner{3};
  std::atomic<int> runs{0}, tasks{0}, changed{0};
  std::mutex mutex;
  std::set<std::thread::id> threads;
  pfx_thread_pool service{sizeof(pfx_thread_pool), this,
                          [](void* data) -> uint32_t { return static_cast<CheckingPool*>(data)->inner.concurrency(); },
                          [](void* data, pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel) {
                            static_cast<CheckingPool*>(data)->run(task, user, count, max_parallel);
                          }};
  struct Wrapped {
    CheckingPool* pool;
    pfx_task_fn task;
    void* user;
  };
  void run(pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel) {
    ++runs;
    Wrapped wrapped{this, task, user};
    inner.run([](void* w, uint32_t index) {
      auto* self = static_cast<Wrapped*>(w);
      const ThreadState before = ThreadState::now();
      self->task(self->user, index);
      if (!(ThreadState::now() == before)) ++self->pool->changed;
      ++self->pool->tasks;
      std::lock_guard<std::mutex> lock(self->pool->mutex);
      self->pool->threads.insert(std::this_thread::get_id());
    }, &wrapped, count, max_parallel);
  }
};

// The progress callback runs on the calling thread in the middle of the import: where an importer
// that pinned its caller or started threads would show it.
struct Watch {
  ThreadState caller;
  int threads = 0;
  std::atomic<int> calls{0}, caller_changed{0}, threads_changed{0};
  static void progress(void* user, float) {
    auto* watch = static_cast<Watch*>(user);
    ++watch->calls;
    if (!(ThreadState::now() == watch->caller)) ++watch->caller_changed;
    if (threads_in_process() != watch->threads) ++watch->threads_changed;
  }
};

}  // namespace

TEST_CASE("obj threads: the plugin works on the host's threads alone and changes none of them", "[objimport][threads]") {
  CheckingPool pool;
  pool.inner.start();  // the host's threads exist before the import: any new one is the importer's
  auto registry = std::make_unique<pfx::host::PluginRegistry>([](const char*) { return pfx_gl_proc{nullptr}; }, nullptr,
                                                              "test_obj_threads");
  registry->set_thread_pool(&pool.service);
  std::string error;
  REQUIRE(registry->load(PFX_TEST_OBJ_PLUGIN, &error));
  const pfx_importer_desc* importer = registry->find_importer("obj")->desc;
  const std::string text = varied_file(60000, 23);  // 2 MB: several chunks per worker
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.bytes = text.data();
  request.byte_count = text.size();
  request.progress = Watch::progress;
  for (uint32_t threads : {0u, 2u, 1u}) {
    INFO("request.threads " << threads);
    Watch watch;
    watch.caller = ThreadState::now();
    watch.threads = threads_in_process();
    pool.runs = 0;
    pool.tasks = 0;
    request.threads = threads;
    request.progress_user = &watch;
    pfx_import_result* result = nullptr;
    CHECK(importer->import(&request, &result) == PFX_OK);
    importer->release(result);
    CHECK(watch.calls > 0);
    CHECK(watch.caller_changed == 0);
    CHECK(watch.threads_changed == 0);
    CHECK(ThreadState::now() == watch.caller);
    CHECK(threads_in_process() == watch.threads);
    // The parallel stages ran on the host's pool (with one task at a time: serially, without it).
    if (threads == 1) CHECK(pool.runs == 0);
    else CHECK(pool.tasks > 0);
    CHECK(pool.changed == 0);
  }
  request.progress = nullptr;
  request.threads = 0;
  pfx_import_result* pooled = nullptr;
  REQUIRE(importer->import(&request, &pooled) == PFX_OK);

  // A host that offers no pool: the same mesh, on the calling thread, no thread started. (Its
  // registry loads its own copy of the library beside the first one's, so the two keep their pools.)
  auto bare = std::make_unique<pfx::host::PluginRegistry>([](const char*) { return pfx_gl_proc{nullptr}; }, nullptr,
                                                          "test_obj_threads");
  bare->set_thread_pool(nullptr);
  REQUIRE(bare->load(PFX_TEST_OBJ_PLUGIN, &error));
  const pfx_importer_desc* serial = bare->find_importer("obj")->desc;
  Watch watch;
  watch.caller = ThreadState::now();
  watch.threads = threads_in_process();
  request.progress = Watch::progress;
  request.progress_user = &watch;
  pool.runs = 0;
  pfx_import_result* alone = nullptr;
  REQUIRE(serial->import(&request, &alone) == PFX_OK);
  CHECK(watch.calls > 0);
  CHECK(watch.threads_changed == 0);
  CHECK(watch.caller_changed == 0);
  CHECK(pool.runs == 0);
  REQUIRE(alone->index_count == pooled->index_count);
  REQUIRE(alone->vertex_count == pooled->vertex_count);
  CHECK(std::equal(alone->indices, alone->indices + alone->index_count, pooled->indices));
  CHECK(std::equal(alone->positions, alone->positions + 3 * size_t{alone->vertex_count}, pooled->positions));
  CHECK(std::equal(alone->normals, alone->normals + 3 * size_t{alone->vertex_count}, pooled->normals));
  serial->release(alone);
  importer->release(pooled);
}

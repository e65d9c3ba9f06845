// libpfxhost's thread pool against the contract of pfx_thread_pool (pfx/services.h): every task
// once, never more at once than asked, nested runs and several callers without deadlock, threads
// started only when needed and all gone with the pool; and the registry offering it to plugins.
#include <catch2/catch.hpp>

#include <dirent.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <pfx/host/plugin_registry.hpp>
#include <pfx/host/thread_pool.hpp>

namespace {

using pfx::host::ThreadPool;

int threads_in_process() {
  int n = 0;
  DIR* tasks = opendir("/proc/self/task");
  REQUIRE(tasks);
  while (dirent* entry = readdir(tasks))
    if (entry->d_name[0] != '.') ++n;
  closedir(tasks);
  return n;
}

// Runs `body(index)` through the C service, as a plugin would.
template <typename Body>
void run_through_service(const pfx_thread_pool* pool, uint32_t count, uint32_t max_parallel, Body& body) {
  pool->run(pool->pool_data, [](void* user, uint32_t index) { (*static_cast<Body*>(user))(index); }, &body, count,
            max_parallel);
}

// Tasks that count how many of them are inside at once. Until `expected` have been inside
// together, each one waits for the others, so a pool that can run that many at once shows it
// however the machine schedules its threads, and one that cannot (a serial pool) leaves `most`
// below it; the wait ends for good at a deadline, so such a pool fails the test in seconds.
struct OverlapProbe {
  explicit OverlapProbe(int expected)
      : expected(expected), deadline(std::chrono::steady_clock::now() + std::chrono::seconds(5)) {}
  const int expected;
  const std::chrono::steady_clock::time_point deadline;
  std::atomic<int> inside{0}, most{0};
  std::atomic<uint32_t> ran{0};
  void operator()(uint32_t) {
    const int now = ++inside;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    while (most.load() < expected && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    for (volatile int spin = 0; spin < 20000; ++spin) {
    }
    --inside;
    ++ran;
  }
};

}  // namespace

TEST_CASE("thread pool: every task runs exactly once, whatever the pool and the count", "[runtime][thread_pool]") {
  for (unsigned concurrency : {1u, 2u, 5u}) {
    ThreadPool pool(concurrency);
    CHECK(pool.concurrency() == concurrency);
    CHECK(pool.service()->concurrency(pool.service()->pool_data) == concurrency);
    for (uint32_t count : {0u, 1u, 3u, 1000u})
      for (uint32_t max_parallel : {0u, 1u, 2u, 64u}) {
        INFO("concurrency " << concurrency << ", count " << count << ", max_parallel " << max_parallel);
        std::vector<std::atomic<int>> runs(count);
        auto body = [&](uint32_t index) { ++runs[index]; };
        run_through_service(pool.service(), count, max_parallel, body);
        CHECK(std::all_of(runs.begin(), runs.end(), [](const std::atomic<int>& r) { return r.load() == 1; }));
      }
  }
}

TEST_CASE("thread pool: as many tasks at once as max_parallel or the concurrency allows, never more",
          "[runtime][thread_pool]") {
  ThreadPool pool(4);
  for (uint32_t max_parallel : {1u, 2u, 3u}) {
    INFO("max_parallel " << max_parallel);
    OverlapProbe probe(static_cast<int>(max_parallel));
    run_through_service(pool.service(), 400, max_parallel, probe);
    CHECK(probe.ran == 400);
    CHECK(probe.most == static_cast<int>(max_parallel));
  }
  OverlapProbe probe(4);
  run_through_service(pool.service(), 400, 0, probe);
  CHECK(probe.most == 4);
}

TEST_CASE("thread pool: threads start at the first parallel run and end with the pool", "[runtime][thread_pool]") {
  const int before = threads_in_process();
  {
    ThreadPool pool(3);
    CHECK(pool.threads_started() == 0);
    CHECK(threads_in_process() == before);
    // A run of one task at a time needs no thread.
    std::atomic<uint32_t> ran{0};
    std::set<std::thread::id> where;
    std::mutex where_mutex;
    auto serial = [&](uint32_t) {
      ++ran;
      std::lock_guard<std::mutex> lock(where_mutex);
      where.insert(std::this_thread::get_id());
    };
    run_through_service(pool.service(), 50, 1, serial);
    CHECK(ran == 50);
    CHECK(where == std::set<std::thread::id>{std::this_thread::get_id()});  // the caller did them all
    CHECK(pool.threads_started() == 0);
    auto parallel = [&](uint32_t) { ++ran; };
    run_through_service(pool.service(), 50, 0, parallel);
    CHECK(pool.threads_started() == 2);  // concurrency 3: the caller and two threads
    CHECK(threads_in_process() == before + 2);
  }
  CHECK(threads_in_process() == before);
  ThreadPool single(1);
  single.start();
  CHECK(single.threads_started() == 0);
}

TEST_CASE("thread pool: a task's nested run completes, on pools of any size", "[runtime][thread_pool]") {
  for (unsigned concurrency : {1u, 2u, 4u}) {
    ThreadPool pool(concurrency);
    std::atomic<uint32_t> inner{0};
    auto outer = [&](uint32_t) {
      auto body = [&](uint32_t) { ++inner; };
      run_through_service(pool.service(), 16, 0, body);
    };
    run_through_service(pool.service(), 16, 0, outer);
    CHECK(inner == 16u * 16u);
  }
}

TEST_CASE("thread pool: several threads calling run at once each get their own tasks", "[runtime][thread_pool]") {
  ThreadPool pool(3);
  constexpr int kCallers = 4;
  std::vector<uint64_t> sums(kCallers, 0);
  std::vector<std::thread> callers;
  for (int c = 0; c < kCallers; ++c)
    callers.emplace_back([&, c] {
      for (int round = 0; round < 20; ++round) {
        std::atomic<uint64_t> sum{0};
        auto body = [&](uint32_t index) { sum += index + 1; };
        run_through_service(pool.service(), 500, 0, body);
        sums[c] += sum;
      }
    });
  for (std::thread& t : callers) t.join();
  for (uint64_t sum : sums) CHECK(sum == 20u * (500u * 501u / 2));
}

TEST_CASE("registry: plugins get the thread pool service, the host's own pool, or none", "[runtime][thread_pool]") {
  auto pool_of = [](const pfx::host::PluginRegistry& registry) -> const pfx_thread_pool* {
    const pfx_host* host = registry.plugins().at(0)->host;
    REQUIRE(PFX_STRUCT_HAS(host, pfx_host, get_service));
    REQUIRE(host->get_service);
    CHECK(host->get_service(host->host_data, "pfx.no_such_service/1") == nullptr);
    CHECK(host->get_service(host->host_data, "pfx.thread_pool/2") == nullptr);
    return static_cast<const pfx_thread_pool*>(host->get_service(host->host_data, PFX_SERVICE_THREAD_POOL));
  };
  auto no_gl = [](const char*) -> pfx_gl_proc { return nullptr; };
  std::string error;
  {
    pfx::host::PluginRegistry registry(no_gl, nullptr);
    REQUIRE(registry.load(PFX_TEST_MINIMAL_PLUGIN, &error));
    const pfx_thread_pool* pool = pool_of(registry);
    REQUIRE(pool);
    CHECK(pool->struct_size >= PFX_THREAD_POOL_MIN_SIZE);
    CHECK(pool->concurrency(pool->pool_data) == std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<uint32_t> ran{0};
    auto body = [&](uint32_t) { ++ran; };
    run_through_service(pool, 100, 0, body);
    CHECK(ran == 100);
  }
  ThreadPool hosts_pool(7);
  {
    pfx::host::PluginRegistry registry(no_gl, nullptr);
    registry.set_thread_pool(hosts_pool.service());
    REQUIRE(registry.load(PFX_TEST_MINIMAL_PLUGIN, &error));
    CHECK(pool_of(registry) == hosts_pool.service());
  }
  {
    pfx::host::PluginRegistry registry(no_gl, nullptr);
    registry.set_thread_pool(nullptr);
    REQUIRE(registry.load(PFX_TEST_MINIMAL_PLUGIN, &error));
    CHECK(pool_of(registry) == nullptr);
  }
}

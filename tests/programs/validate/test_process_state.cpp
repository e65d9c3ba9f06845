// The validator's reading of the process state must not change it: a snapshot taken on several
// threads at once (the call, the host's thread pool and the progress callback of one import) reads
// the umask of the process as it is, and leaves it so.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <atomic>
#include <thread>
#include <vector>

#include "process_state.hpp"

using pfx::validate::process_state_changes;
using pfx::validate::snapshot_process_state;

TEST_CASE("process state: snapshots on eight threads at once read the umask and leave it as it was", "[validate]") {
  // An unusual umask, so a snapshot that reads another's temporary 0 (or the default 022) shows.
  const mode_t original = ::umask(027);
  const pfx::validate::ProcessState before = snapshot_process_state();
  REQUIRE(before.umask == 027);
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < 300; ++i)
        if (snapshot_process_state().umask != 027) ++wrong;
    });
  for (std::thread& thread : threads) thread.join();
  const mode_t after = ::umask(original);  // read by setting it, here on one thread alone
  CHECK(after == 027);
  CHECK(wrong == 0);
  ::umask(027);
  CHECK(process_state_changes(before, snapshot_process_state()).empty());
  ::umask(original);
}

TEST_CASE("process state: a changed umask is named with both values", "[validate]") {
  const mode_t original = ::umask(022);
  const pfx::validate::ProcessState before = snapshot_process_state();
  ::umask(0);
  const std::vector<std::string> changes = process_state_changes(before, snapshot_process_state());
  ::umask(original);
  REQUIRE(changes.size() == 1);
  CHECK(changes[0] == "the umask changed from 0022 to 0000");
}

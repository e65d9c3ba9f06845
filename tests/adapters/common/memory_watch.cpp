#include "memory_watch.hpp"

#include <sys/prctl.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <string>

namespace pfx::test {

uint64_t anonymous_bytes(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("RssAnon:", 0) == 0) return std::stoull(line.substr(8)) * 1024;
  return 0;
}

void use_small_pages() { REQUIRE(::prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0) == 0); }

}  // namespace pfx::test

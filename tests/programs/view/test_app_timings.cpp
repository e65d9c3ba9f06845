// The panel's reader of the pass times an injected chain writes (pfx-inject --panel).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app_timings.hpp"

namespace {

const char* kTimes =
    R"({"frame":42,"timing":"gpu","chain":"bloom","total_ms":1.5,"passes":[{"effect":"bloom","pass":"composite","ms":1.5}]})";

std::string scratch_file(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("pfx-app-timings-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  return (folder / name).string();
}

}  // namespace

TEST_CASE("the panel reads the application's pass times once the file appears, though the clock stands still",
          "[view][panel]") {
  // pfx-inject's tests stop every clock with libfaketime: the panel's clock reads one time
  // throughout, and the times must still arrive.
  const std::string path = scratch_file("stopped.json");
  std::filesystem::remove(path);
  pfx::app::AppTimingsReader reader(path);
  CHECK_FALSE(reader.poll(7.0));  // no file yet
  std::ofstream(path) << kTimes;
  int polls = 0;
  bool read = false;
  while (!read && polls < 100) read = reader.poll(7.0), ++polls;
  REQUIRE(read);
  CHECK(polls <= 16);
  CHECK(reader.latest().frame == 42);
  REQUIRE(reader.latest().times.passes.size() == 1);
  CHECK(reader.latest().times.passes[0].pass == "composite");
  CHECK_FALSE(reader.poll(7.0));  // the same file: nothing new
  std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

TEST_CASE("with a running clock the panel looks again after a quarter second, not every frame", "[view][panel]") {
  const std::string path = scratch_file("running.json");
  std::filesystem::remove(path);
  pfx::app::AppTimingsReader reader(path);
  CHECK_FALSE(reader.poll(1.0));
  std::ofstream(path) << kTimes;
  CHECK_FALSE(reader.poll(1.1));  // within the quarter second: not looked at
  CHECK(reader.poll(1.3));
  CHECK(reader.latest().frame == 42);
  std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

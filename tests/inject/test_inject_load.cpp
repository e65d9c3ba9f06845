// Held under load: an application run for 5,000 frames with the chain does not grow. The GL
// objects of its context after frame 5,000 are those after frame 500, and its resident memory does
// not grow in both halves of the run, as the injector counts them (--resources-at): nothing the
// chain makes per frame, per depth check or per plan is left behind. The frame is small so the run
// is quick; its length is the point.
#include <catch2/catch.hpp>

#include <regex>

#include "inject_run.hpp"

using namespace pfx::test;

namespace {

struct Counts {
  long long resident_kib = -1;
  std::string objects;  // the GL object counts as logged
};

Counts counts_at(const std::string& log, int frame) {
  const std::regex line("frame " + std::to_string(frame) + ": resident memory ([0-9]+) KiB; GL objects: ([^\n]*)");
  std::smatch match;
  Counts counts;
  if (std::regex_search(log, match, line)) {
    counts.resident_kib = std::stoll(match[1].str());
    counts.objects = match[2].str();
  }
  return counts;
}

}  // namespace

TEST_CASE("5,000 frames with the default chain: GL objects equal, memory not growing") {
  ScratchFolder folder("load");
  const InjectRun run = run_injected(folder, "load", {"--resources-at", "500,2750,5000", "--quit-after", "5000"},
                                     {PFX_GLXGEARS, "-geometry", "48x48"}, false);
  INFO(run.result.output << run.log);
  REQUIRE(run.result.exit_code == 0);
  REQUIRE(run.log.find("chain: dof,bloom,glare") != std::string::npos);
  const Counts early = counts_at(run.log, 500), middle = counts_at(run.log, 2750), late = counts_at(run.log, 5000);
  REQUIRE(early.resident_kib > 0);
  REQUIRE(middle.resident_kib > 0);
  REQUIRE(late.resident_kib > 0);
  CHECK(middle.objects == early.objects);
  CHECK(late.objects == early.objects);
  // Resident memory: equal to the KiB in quiet runs here (120828 KiB at frames 500, 2000, 3500
  // and 5000). Once, under a load average of 11, Mesa's pools took 1.5 MiB more in one step
  // between 500 and 5,000. A leak grows in both halves of the run (the C library's heap grows
  // 132 KiB at a time, so a hundred bytes a frame shows in each), a pool that settles late in one:
  // one half must not grow at all.
  CHECK((middle.resident_kib == early.resident_kib || late.resident_kib == middle.resident_kib));
}

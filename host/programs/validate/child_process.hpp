// Every check runs in a child process (fork), so a plugin that crashes, hangs or calls exit is
// reported as a failed check instead of taking pfx-validate down. The child tells the parent what
// it is doing and what it found through a pipe, one line per report, so the parent can also say
// where a crash happened.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace pfx::validate {

// The child's side of the pipe. Each call is one write(2), so nothing is lost when the child
// dies right after it.
class CheckReporter {
 public:
  explicit CheckReporter(int fd) : fd_(fd) {}
  // What the child is about to do ("calling get_effect(0)"): the last step names a crash's place.
  void step(const std::string& what) { send("step", what); }
  // One problem found; any problem fails the check.
  void problem(const std::string& what) { send("problem", what); }
  // A fact for the parent (an effect id, the plugin id...), as key and value.
  void fact(const std::string& key, const std::string& value) { send("fact", key + "=" + value); }
  // Sent by the harness when the check returned normally.
  void done() { send("done", ""); }

 private:
  void send(const char* kind, const std::string& text);
  int fd_;
};

struct ChildReport {
  enum class End { Finished, Exited, Signalled, TimedOut, ForkFailed };
  End end = End::Finished;
  int exit_code = 0;  // Exited: the code of an exit before done()
  int signal = 0;     // Signalled
  std::vector<std::string> steps, problems;
  std::vector<std::pair<std::string, std::string>> facts;
  std::string stdout_text;  // what the child wrote to its stdout (a plugin must write nothing)
  std::string stderr_text;  // the tail of its stderr, shown with crashes

  // "crashed with signal 11 (Segmentation fault) during: calling get_effect(0)", or "" when the
  // child finished normally.
  std::string abnormal_end() const;
  std::string fact(const std::string& key) const;
};

// Forks, runs body in the child with stdout and stderr captured, and waits at most timeout_s
// seconds (then kills it). The parent must hold no GL context and no plugin: the child starts
// from a clean slate.
ChildReport run_in_child(const std::function<void(CheckReporter&)>& body, double timeout_s);

}  // namespace pfx::validate

#include "sequence_loop.hpp"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>

#include "atomic_file.hpp"
#include "exit_codes.hpp"

namespace pfx::app {

namespace {

// The signal that asked us to stop; the loop looks at it between frames, so the frame being
// written is finished (or fails) and no temporary file is left behind.
volatile std::sig_atomic_t stop_signal = 0;
extern "C" void request_stop(int signal) { stop_signal = signal; }

// SIGINT and SIGTERM (what Slurm sends a cancelled or pre-empted task before SIGKILL) stop the
// loop after the current frame; a second one acts as it would without us (SA_RESETHAND). The
// handlers the process had are put back when the loop ends.
class StopOnSignal {
 public:
  StopOnSignal() {
    stop_signal = 0;
    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // no SA_RESTART: a read blocked on a slow file gives up
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~StopOnSignal() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

std::string clock_text(double seconds) {
  const long long s = static_cast<long long>(seconds + 0.5);
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(text, sizeof text, "%lld:%02lld", s / 60, s % 60);
  return text;
}

// Progress on stderr: on a terminal one line, rewritten after each frame; elsewhere (a farm
// task's log) one line per frame, so the log says what each frame did.
class Progress {
 public:
  explicit Progress(long long total) : total_(total), terminal_(::isatty(STDERR_FILENO) == 1) {}

  void frame_done(long long index, long long frame, const std::string& what, double seconds, double per_frame) {
    const double left = per_frame * static_cast<double>(total_ - index - 1);
    if (terminal_) {
      std::fprintf(stderr, "\r\033[Kframe %lld [%lld/%lld] %s, %.2f s/frame, about %s left", frame, index + 1, total_,
                   what.c_str(), per_frame, clock_text(left).c_str());
    } else {
      std::fprintf(stderr, "frame %lld [%lld/%lld]: %s in %.2f s, about %s left\n", frame, index + 1, total_,
                   what.c_str(), seconds, clock_text(left).c_str());
    }
    std::fflush(stderr);
  }
  // A message on a line of its own, even while the progress line is showing.
  void message(const std::string& text) {
    std::fprintf(stderr, "%spfx-render: %s\n", terminal_ ? "\r\033[K" : "", text.c_str());
  }
  void finish() {
    if (terminal_) std::fputc('\n', stderr);
  }

 private:
  long long total_;
  bool terminal_;
};

std::string frame_list(const std::vector<long long>& frames) {
  std::string text;
  for (size_t i = 0; i < frames.size() && i < 20; ++i) text += (i ? " " : "") + std::to_string(frames[i]);
  if (frames.size() > 20) text += " ...";
  return text;
}

}  // namespace

int run_sequence(const RenderOptions& options, const RenderFrameFn& render) {
  using Clock = std::chrono::steady_clock;
  const FrameRange range = frames_to_render(options.sequence);
  StopOnSignal stop_on_signal;
  Progress progress(range.count());
  const auto start = Clock::now();
  long long rendered = 0, skipped = 0;
  double render_seconds = 0;
  std::vector<long long> failed;
  for (long long index = 0; index < range.count() && !stop_signal; ++index) {
    const FrameFiles files = frame_files(options, range.at(index));
    const auto frame_start = Clock::now();
    nlohmann::ordered_json line = {{"frame", files.frame}};
    std::string what;
    if (!options.sequence.overwrite && frame_done(files)) {
      ++skipped;
      what = "skipped (complete)";
      line["status"] = "skipped";
      line["files"] = files.outputs;
    } else {
      nlohmann::ordered_json report;
      std::string error;
      if (render(files, &report, &error)) {
        ++rendered;
        render_seconds += std::chrono::duration<double>(Clock::now() - frame_start).count();
        what = "rendered";
        line["status"] = "rendered";
      } else {
        failed.push_back(files.frame);
        what = "FAILED";
        line["status"] = "failed";
        line["error"] = error;
        progress.message("frame " + std::to_string(files.frame) + ": " + error);
      }
      line["seconds"] = std::chrono::duration<double>(Clock::now() - frame_start).count();
      for (auto& [key, value] : report.items()) line[key] = value;
      std::string report_error;
      if (!files.report.empty() && !write_text_atomically(files.report, line.dump(2) + "\n", &report_error))
        progress.message("warning: frame " + std::to_string(files.frame) + ": " + report_error);
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - frame_start).count();
    // Time left from the frames rendered so far: skipped and failed ones cost next to nothing.
    progress.frame_done(index, files.frame, what, seconds,
                        rendered ? render_seconds / static_cast<double>(rendered) : seconds);
    if (options.json) {
      std::puts(line.dump().c_str());
      std::fflush(stdout);
    }
  }
  progress.finish();
  const long long total = range.count(), left = total - rendered - skipped - static_cast<long long>(failed.size());
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::string summary = std::to_string(total) + " frames: " + std::to_string(rendered) + " rendered, " +
                        std::to_string(skipped) + " skipped (already complete), " + std::to_string(failed.size()) +
                        " failed" + (failed.empty() ? "" : " (" + frame_list(failed) + ")");
  if (stop_signal) summary += ", " + std::to_string(left) + " not started: stopped by signal " +
                              std::to_string(stop_signal) + " (run the same command again to finish)";
  std::fprintf(stderr, "%s in %s\n", summary.c_str(), clock_text(seconds).c_str());
  if (options.json) {
    nlohmann::ordered_json last;
    last["summary"] = {{"frames", total},   {"rendered", rendered}, {"skipped", skipped},
                       {"failed", failed},  {"not_started", left},  {"seconds", seconds},
                       {"stopped_by_signal", static_cast<int>(stop_signal)}};
    std::puts(last.dump().c_str());
  }
  if (stop_signal) return exit_code::kSignalBase + stop_signal;
  return failed.empty() ? exit_code::kOk : exit_code::kSomeFramesFailed;
}

}  // namespace pfx::app

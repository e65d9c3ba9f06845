// A thread that runs an adapter's GL work with a context of its own. A host hands an adapter CPU
// frames on whatever thread it likes, and that thread may have a context of its own current
// (Kdenlive's GPU effects, a GLX context: eglMakeCurrent fails there; a Python script's own GL
// window), so the adapter never touches the caller's GL: its work runs on a thread it owns, with
// its own surfaceless EGL 4.5 core context, and the caller waits for it. The frei0r plugins share
// one worker per process (acquire: their frames take turns, and the renderer uses every core for
// each); the Python module gives each Chain its own (start), so that chains on different threads
// run at the same time. A worker stops, destroying its context, when its last holder lets go.
#pragma once

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace pfx::adapters {

class GlWorker {
 public:
  // The worker of this process, started if none runs; each holder keeps it running.
  static std::shared_ptr<GlWorker> acquire();
  // A worker of the caller's own, shared with nobody.
  static std::shared_ptr<GlWorker> start();
  ~GlWorker();  // on the last holder's thread: stops the worker, which destroys its context
  GlWorker(const GlWorker&) = delete;
  GlWorker& operator=(const GlWorker&) = delete;

  // Runs `job` on the worker with its context current, and waits for it. False with *error when
  // the worker has no context (no EGL, no OpenGL 4.5): the job did not run.
  bool run(const std::function<void()>& job, std::string* error);
  const std::string& renderer() const { return renderer_; }

 private:
  GlWorker();
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_;
  const std::function<void()>* job_ = nullptr;  // the job waiting or running
  bool job_done_ = false;
  bool stopping_ = false;
  bool started_ = false;  // the context was made (or failed): context_error_ says which
  std::string context_error_;
  std::string renderer_;
  std::mutex callers_;  // one caller's job at a time
  std::thread thread_;
};

}  // namespace pfx::adapters

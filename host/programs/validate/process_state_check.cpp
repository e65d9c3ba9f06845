#include "process_state_check.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <set>

#include <pfx/host/import_result.hpp>
#include <pfx/host/thread_pool.hpp>

#include "process_state.hpp"
#include "render_rig.hpp"
#include "synthetic_inputs.hpp"

namespace pfx::validate {
namespace {

// A small OBJ model (a 30 x 30 height field with texture coordinates, normals and one polygon),
// what every importer is handed, named with the importer's first extension. An importer of another
// format may refuse it: only what the calls leave behind counts here.
std::string sample_model() {
  std::string text = "# pfx-validate\n";
  char line[128];
  constexpr int n = 30;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      std::snprintf(line, sizeof line, "v %d %d %g\nvt %g %g\nvn 0 0 1\n", x, y, 0.01 * ((x * 7 + y * 3) % 10),
                    x / double(n), y / double(n));
      text += line;
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const int a = y * n + x + 1, b = a + 1, c = a + n, d = c + 1;
      std::snprintf(line, sizeof line, "f %d/%d/%d %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, a, b, b, b, d, d, d, c, c, c);
      text += line;
    }
  return text;
}

// Compares the state after each call with the state after the one before, so each change is
// named with the call that made it.
class StateWatch {
 public:
  explicit StateWatch(CheckReporter& report) : report_(report), last_(snapshot_process_state()) {}
  void after(const std::string& call) {
    ProcessState now = snapshot_process_state();
    for (const std::string& change : process_state_changes(last_, now)) report_.problem(call + ": " + change);
    last_ = std::move(now);
  }

 private:
  CheckReporter& report_;
  ProcessState last_;
};

// What the plugin changed in the middle of an import: seen from the progress callback, on the
// calling thread, and around every task it runs on the host's pool, on the pool's threads. A
// change undone before the call returns is still a change to somebody else's thread while it lasts.
struct DuringImport {
  pfx::host::ThreadPool* pool = nullptr;
  ProcessState caller_before;
  std::mutex mutex;
  std::set<std::string> changes;
  pfx_thread_pool service{};

  explicit DuringImport(pfx::host::ThreadPool* inner) : pool(inner) {
    service.struct_size = sizeof service;
    service.pool_data = this;
    service.concurrency = [](void* self) -> uint32_t { return static_cast<DuringImport*>(self)->pool->concurrency(); };
    service.run = [](void* self, pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel) {
      static_cast<DuringImport*>(self)->run(task, user, count, max_parallel);
    };
  }
  void note(const std::string& where, const ProcessState& before, const ProcessState& after) {
    std::vector<std::string> found = process_state_changes(before, after);
    std::lock_guard<std::mutex> lock(mutex);
    for (const std::string& change : found) changes.insert(where + ": " + change);
  }
  static void progress(void* self, float) {
    auto* watch = static_cast<DuringImport*>(self);
    watch->note("in the middle of the call (seen from its progress callback)", watch->caller_before,
                snapshot_process_state());
  }
  struct Task {
    DuringImport* watch;
    pfx_task_fn task;
    void* user;
  };
  void run(pfx_task_fn task, void* user, uint32_t count, uint32_t max_parallel) {
    Task wrapped{this, task, user};
    pool->run(
        [](void* data, uint32_t index) {
          auto* t = static_cast<Task*>(data);
          const ProcessState before = snapshot_process_state();
          t->task(t->user, index);
          t->watch->note("a task it ran on the host's thread pool", before, snapshot_process_state());
        },
        &wrapped, count, max_parallel);
  }
};

}  // namespace

void check_process_state(const std::string& path, CheckReporter& report) {
  // A driver writes its on-disk shader cache from threads it starts when a program is first
  // compiled and not found there: with a cold cache (a fresh machine, a new driver) the plugin's
  // first create would seem to leave them running. This check runs in a child of its own, so it
  // turns the caches of Mesa and NVIDIA's driver off for that child alone, before the context
  // exists: the threads that can then appear are the plugin's.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  setenv("__GL_SHADER_DISK_CACHE", "0", 1);
  RenderRig rig(report);
  if (!rig.open_context()) return;
  // The host's threads, and the driver's, exist before the first look: a thread that appears
  // later is the plugin's.
  pfx::host::ThreadPool pool;
  pool.start();
  StateWatch watch(report);

  report.step("dlopen(RTLD_NOW | RTLD_LOCAL)");
  // Kept open until the child ends, so the library stays mapped whatever the registry does.
  void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* why = dlerror();
    report.problem(std::string("cannot be loaded: ") + (why ? why : "unknown dlopen error"));
    return;
  }
  watch.after("loading the library (its static constructors)");
  DuringImport during(&pool);
  const bool loaded = rig.load(path, &during.service);
  watch.after("init");
  if (!loaded) return;

  std::vector<std::string> effects;
  for (const pfx::host::EffectInfo& info : rig.registry()->effects()) effects.push_back(info.desc->id);
  for (const std::string& id : effects) {
    const bool created = rig.add_effect(id);
    watch.after("create of '" + id + "'");
    if (!created) continue;
    rig.render(gradient_image(24, 16), "gradient 24x16");
    watch.after("declare and the passes of '" + id + "'");
    rig.remove_effect();
    watch.after("destroy of '" + id + "'");
  }

  const std::string model = sample_model();
  for (const pfx::host::ImporterInfo& info : rig.registry()->importers()) {
    const std::string id = info.desc->id;
    pfx_import_request request{};
    request.struct_size = sizeof request;
    request.bytes = model.data();
    request.byte_count = model.size();
    const std::string name = std::string("pfx-validate-sample.") + info.desc->extensions[0];
    request.name = name.c_str();
    request.progress = DuringImport::progress;
    request.progress_user = &during;
    report.step("import of '" + id + "'");
    during.caller_before = snapshot_process_state();
    pfx::host::ImportResult result(*info.desc, request);
    watch.after("import of '" + id + "'");
    for (const std::string& change : during.changes) report.problem("import of '" + id + "', " + change);
    during.changes.clear();
    report.step("release of '" + id + "'");
    result.reset();
    watch.after("release of '" + id + "'");
  }

  report.step("deinit and unloading");
  rig.unload();
  watch.after("deinit and unloading");
}

}  // namespace pfx::validate

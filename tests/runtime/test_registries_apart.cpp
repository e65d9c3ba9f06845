// Several registries in one process, as a module making one per chain or an adapter with several
// filter instances has them: each registry's plugins keep their own globals and get their own init
// and deinit, so what a plugin keeps of its host (the thread pool, where its log goes) stays with
// that host, also after another registry is gone. A registry loads a private copy of a library
// only while another live registry holds the same library; otherwise it loads the file itself.
#include <catch2/catch.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "gl_test_support.hpp"

namespace fs = std::filesystem;
using pfx::host::PluginRegistry;

namespace {

const std::string kObjImport = std::string(PFX_PLUGIN_OUTPUT_DIR) + "/pfx_objimport.so";

// A pool that counts the tasks it is asked to run and runs them one after another on the calling
// thread (the contract allows it). It offers two at once, so the importer splits its stages.
struct CountingPool {
  std::atomic<uint32_t> tasks{0};
  pfx_thread_pool service{sizeof(pfx_thread_pool), this, [](void*) -> uint32_t { return 2; },
                          [](void* data, pfx_task_fn task, void* user, uint32_t count, uint32_t) {
                            static_cast<CountingPool*>(data)->tasks += count;
                            for (uint32_t i = 0; i < count; ++i) task(user, i);
                          }};
};

std::unique_ptr<PluginRegistry> registry_loading(const std::string& plugin, const pfx_thread_pool* pool,
                                                 pfx::test::CollectedLog* log = nullptr) {
  auto registry = pfx::test::make_registry(log);
  registry->set_thread_pool(pool);
  std::string error;
  INFO(error);
  REQUIRE(registry->load(plugin, &error));
  return registry;
}

// Imports a model the import tests use through the registry's OBJ importer: its vertex count.
uint32_t import_model(const PluginRegistry& registry) {
  const pfx::host::ImporterInfo* info = registry.find_importer("obj");
  REQUIRE(info);
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.path = PFX_TEST_OBJ_MODEL;
  request.threads = 0;  // as many as the host's pool offers
  pfx_import_result* result = nullptr;
  const pfx_status status = info->desc->import(&request, &result);
  INFO((result && result->error ? result->error : ""));
  REQUIRE(status == PFX_OK);
  const uint32_t vertices = result->vertex_count;
  info->desc->release(result);
  return vertices;
}

// The file the dynamic loader mapped the registry's OBJ importer from.
std::string mapped_file(const PluginRegistry& registry) {
  const pfx::host::ImporterInfo* info = registry.find_importer("obj");
  REQUIRE(info);
  Dl_info where{};
  REQUIRE(dladdr(reinterpret_cast<void*>(info->desc->import), &where) != 0);
  REQUIRE(where.dli_fname);
  return where.dli_fname;
}

// Files of the plugin folder whose name starts with the plugin's own and is not the plugin: a
// private copy left behind.
std::vector<std::string> copies_left_beside(const std::string& plugin) {
  const fs::path original(plugin);
  std::vector<std::string> left;
  for (const auto& item : fs::directory_iterator(original.parent_path())) {
    const std::string name = item.path().filename().string();
    if (name != original.filename().string() && name.find(original.filename().string()) != std::string::npos)
      left.push_back(name);
  }
  return left;
}

}  // namespace

TEST_CASE("two registries loading the OBJ importer each run its imports on their own pool", "[registry][apart]") {
  CountingPool pool_a, pool_b;
  auto a = registry_loading(kObjImport, &pool_a.service);
  auto b = registry_loading(kObjImport, &pool_b.service);

  const uint32_t vertices = import_model(*a);
  CHECK(vertices > 0);
  const uint32_t a_tasks = pool_a.tasks;
  CHECK(a_tasks > 0);
  CHECK(pool_b.tasks == 0);

  pool_a.tasks = 0;
  CHECK(import_model(*b) == vertices);
  CHECK(pool_a.tasks == 0);
  CHECK(pool_b.tasks == a_tasks);  // the same model on a pool of the same size: the same tasks

  // B's deinit leaves A's plugin as it was: still on A's pool, not serial, not on B's.
  pool_b.tasks = 0;
  b.reset();
  CHECK(import_model(*a) == vertices);
  CHECK(pool_a.tasks == a_tasks);
  CHECK(pool_b.tasks == 0);
}

TEST_CASE("two registries loading tiledlights each get its log, also after the other is gone", "[registry][apart]") {
  pfx::test::CollectedLog log_a, log_b;
  const std::string plugin = std::string(PFX_PLUGIN_OUTPUT_DIR) + "/pfx_tiledlights.so";
  auto a = registry_loading(plugin, nullptr, &log_a);
  auto b = registry_loading(plugin, nullptr, &log_b);

  // A request the reference refuses with a message to its host's log: a light of negative
  // intensity. One pixel, every G-buffer input given.
  pfx::host::ParamStore params;
  params.add_effect(a->find_effect("tiledlights")->desc);
  pfx_frame frame = pfx::test::make_frame(1, 1);
  pfx_light light{};
  light.intensity = -1.0f;
  frame.lights = &light;
  frame.light_count = 1;
  std::vector<float> pixel{0.5f, 0.5f, 0.5f, 1.0f}, depth{0.5f}, normal{0.0f, 0.0f, 1.0f, 0.0f}, output(4);
  pfx_reference_request request{};
  request.struct_size = sizeof request;
  request.effect_id = "tiledlights";
  request.kind = PFX_REFERENCE_MODEL;
  request.frame = &frame;
  request.params = params.values("tiledlights");
  request.color = request.albedo = request.emissive = pixel.data();
  request.normal = normal.data();
  request.depth = depth.data();
  request.output = output.data();
  auto refusals_in = [](const pfx::test::CollectedLog& log) {
    return std::count_if(log.lines.begin(), log.lines.end(), [](const std::string& line) {
      return line.find("tiledlights reference: light 0: intensity must be finite and >= 0") != std::string::npos;
    });
  };

  CHECK(a->find_plugin("org.pfx.tiledlights")->references->evaluate(&request) == PFX_INVALID_ARGUMENT);
  CHECK(refusals_in(log_a) == 1);
  CHECK(refusals_in(log_b) == 0);
  CHECK(b->find_plugin("org.pfx.tiledlights")->references->evaluate(&request) == PFX_INVALID_ARGUMENT);
  CHECK(refusals_in(log_a) == 1);
  CHECK(refusals_in(log_b) == 1);

  b.reset();
  CHECK(a->find_plugin("org.pfx.tiledlights")->references->evaluate(&request) == PFX_INVALID_ARGUMENT);
  CHECK(refusals_in(log_a) == 2);
}

TEST_CASE("two registries run bloom at once, and one keeps running when the other is gone", "[registry][apart]") {
  const std::string plugin = std::string(PFX_PLUGIN_OUTPUT_DIR) + "/pfx_bloom.so";
  auto first = std::make_unique<pfx::test::ChainRig>(plugin.c_str());
  auto second = std::make_unique<pfx::test::ChainRig>(plugin.c_str());
  first->add("bloom");
  second->add("bloom");
  const pfx::app::Image input = pfx::test::test_image(24, 16);
  const pfx::app::Image before = first->render(input);
  CHECK(before.rgba != input.rgba);  // bloom changed the picture
  CHECK(second->render(input).rgba == before.rgba);

  first.reset();
  CHECK(second->render(input).rgba == before.rgba);
}

TEST_CASE("a registry loads a private copy only while another registry holds the library", "[registry][apart]") {
  {
    auto a = registry_loading(kObjImport, nullptr);
    CHECK(mapped_file(*a) == kObjImport);
    auto b = registry_loading(kObjImport, nullptr);
    CHECK(b->find_plugin("org.pfx.objimport")->path == kObjImport);
    const std::string copy = mapped_file(*b);
    CHECK(copy != kObjImport);
    CHECK_FALSE(fs::exists(copy));  // removed once mapped
    CHECK(copies_left_beside(kObjImport).empty());

    // Only B's copy is left once A is gone: the next registry loads the file itself.
    a.reset();
    auto c = registry_loading(kObjImport, nullptr);
    CHECK(mapped_file(*c) == kObjImport);
  }
  // Registries made one after the other all load the file itself.
  for (int i = 0; i < 2; ++i) {
    auto r = registry_loading(kObjImport, nullptr);
    CHECK(mapped_file(*r) == kObjImport);
  }
}

TEST_CASE("a library that cannot be loaded is named by its path, never by the private copy", "[registry][apart][errors]") {
  const fs::path dir = fs::temp_directory_path() / ("pfx-apart-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string plugin = (dir / "minimal.so").string();
  fs::copy_file(PFX_TEST_MINIMAL_PLUGIN, plugin);
  auto a = registry_loading(plugin, nullptr);

  // A rebuild that the loader cannot map: an ELF header and nothing after it. Renamed over the
  // plugin as a linker does, so A's mapping is untouched.
  const std::string truncated = (dir / "minimal.so.new").string();
  {
    std::ifstream in(PFX_TEST_MINIMAL_PLUGIN, std::ios::binary);
    std::vector<char> header(64);
    in.read(header.data(), 64);
    std::ofstream(truncated, std::ios::binary).write(header.data(), 64);
  }
  fs::rename(truncated, plugin);
  const std::string named_by_path = plugin + ": cannot be loaded: " + plugin + ": ";

  // Loaded from a reload's private copy.
  std::string error;
  CHECK_FALSE(a->reload("org.pfx.test.minimal", nullptr, &error));
  INFO(error);
  CHECK(error.rfind(named_by_path, 0) == 0);
  CHECK(error.find("pfx-private") == std::string::npos);

  // Loaded from the copy a second registry makes while A holds the library.
  auto b = pfx::test::make_registry();
  CHECK_FALSE(b->load(plugin, &error));
  INFO(error);
  CHECK(error.rfind(plugin + ": cannot be loaded: another registry of this process holds the library, and its "
                    "private copy cannot be loaded: " + plugin + ": ", 0) == 0);
  CHECK(error.find("pfx-private") == std::string::npos);

  CHECK(a->find_effect("gain"));  // A's version still runs
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);  // no copy left
  fs::remove_all(dir);
}

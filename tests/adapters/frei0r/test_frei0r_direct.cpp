// The frei0r plugins hosted directly, as a frei0r host does it (dlopen, the f0r_* functions),
// to check what the real hosts cannot show from outside: construct is cheap (no thread, no GL),
// the GL runs on a thread of the plugin's own and works while the caller has a GLX or EGL
// context current (left current and untouched), instances on several threads and of several
// sizes at once, parameters made from the descriptors, and destruction freeing the thread.
// Runs under Xvfb (a GLX context needs an X server).
#include <catch2/catch.hpp>

#include <dirent.h>
#include <dlfcn.h>

#include <cmath>
#include <fstream>
#include <map>
#include <thread>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <EGL/egl.h>

extern "C" {
#include <frei0r.h>
}

#include "headless_context.hpp"

namespace {

// One frei0r library, loaded for the test's duration.
struct Frei0r {
  void* handle = nullptr;
  int (*init)() = nullptr;
  void (*deinit)() = nullptr;
  void (*plugin_info)(f0r_plugin_info_t*) = nullptr;
  void (*param_info)(f0r_param_info_t*, int) = nullptr;
  f0r_instance_t (*construct)(unsigned, unsigned) = nullptr;
  void (*destruct)(f0r_instance_t) = nullptr;
  void (*set_param)(f0r_instance_t, f0r_param_t, int) = nullptr;
  void (*get_param)(f0r_instance_t, f0r_param_t, int) = nullptr;
  void (*update)(f0r_instance_t, double, const uint32_t*, uint32_t*) = nullptr;

  explicit Frei0r(const std::string& name) {
    handle = dlopen((std::string(PFX_FREI0R_DIR "/") + name).c_str(), RTLD_NOW | RTLD_LOCAL);
    INFO(dlerror());
    REQUIRE(handle);
    load(&init, "f0r_init");
    load(&deinit, "f0r_deinit");
    load(&plugin_info, "f0r_get_plugin_info");
    load(&param_info, "f0r_get_param_info");
    load(&construct, "f0r_construct");
    load(&destruct, "f0r_destruct");
    load(&set_param, "f0r_set_param_value");
    load(&get_param, "f0r_get_param_value");
    load(&update, "f0r_update");
    REQUIRE(init() == 1);
  }
  ~Frei0r() {
    deinit();
    dlclose(handle);
  }
  template <class F>
  void load(F* function, const char* name) {
    *function = reinterpret_cast<F>(dlsym(handle, name));
    REQUIRE(*function);
  }
  void set_string(f0r_instance_t instance, int index, const char* text) {
    set_param(instance, const_cast<char**>(&text), index);
  }
};

// A frame with detail, a few bright spots and alpha of every value, different for each seed.
std::vector<uint32_t> frame(int width, int height, int seed) {
  std::vector<uint32_t> pixels(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint32_t r = (x * 7 + seed * 31) % 256, g = (y * 5 + seed * 17) % 256, b = ((x ^ y) * 3) % 256;
      const uint32_t a = (x * 3 + y * 5 + seed) % 256;  // every alpha a frame may carry
      const bool spot = (x + seed) % 13 == 0 && (y + seed) % 11 == 0;
      pixels[static_cast<size_t>(y) * width + x] = spot ? 0xffffffffu : (a << 24) | (b << 16) | (g << 8) | r;
    }
  return pixels;
}

// The threads of this process (/proc/self/task).
int thread_count() {
  int count = 0;
  DIR* tasks = opendir("/proc/self/task");
  REQUIRE(tasks);
  while (dirent* entry = readdir(tasks)) count += entry->d_name[0] != '.';
  closedir(tasks);
  return count;
}

// Bloom at threshold 0.5 over `frames` seeds, one instance, on the calling thread.
std::vector<std::vector<uint32_t>> bloom_frames(Frei0r& plugin, int width, int height, int first_seed, int frames) {
  f0r_instance_t instance = plugin.construct(width, height);
  REQUIRE(instance);
  plugin.set_string(instance, 0, "bloom");
  plugin.set_string(instance, 1, "bloom.threshold=0.5");
  std::vector<std::vector<uint32_t>> out;
  for (int i = 0; i < frames; ++i) {
    const auto in = frame(width, height, first_seed + i);
    out.emplace_back(in.size());
    plugin.update(instance, i / 25.0, in.data(), out.back().data());
  }
  plugin.destruct(instance);
  return out;
}

}  // namespace

TEST_CASE("frei0r: construct starts no thread and no GL, the first frame starts the plugin's GL thread and keeps alpha, destruct ends it",
          "[adapters][frei0r][direct]") {
  Frei0r plugin("pfx_chain.so");
  // The GL driver starts threads of its own at its first use and keeps them: one frame first,
  // then the plugin's own thread is the one that comes and goes.
  bloom_frames(plugin, 16, 16, 0, 1);
  const int before = thread_count();
  std::vector<f0r_instance_t> instances;
  for (int i = 0; i < 3; ++i) instances.push_back(plugin.construct(640, 480));
  CHECK(thread_count() == before);
  CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT);
  const auto in = frame(32, 24, 1);
  std::vector<uint32_t> out(in.size());
  f0r_instance_t small = plugin.construct(32, 24);
  plugin.update(small, 0, in.data(), out.data());
  CHECK(thread_count() == before + 1);
  CHECK(out != in);  // bloom by default
  bool alpha_kept = true;
  for (size_t i = 0; i < in.size(); ++i) alpha_kept &= (in[i] >> 24) == (out[i] >> 24);
  CHECK(alpha_kept);
  for (auto instance : instances) plugin.destruct(instance);
  CHECK(thread_count() == before + 1);  // the instance that rendered still holds it
  plugin.destruct(small);
  CHECK(thread_count() == before);
  CHECK(plugin.construct(0, 10) == nullptr);
  CHECK(plugin.construct(16385, 10) == nullptr);
}

TEST_CASE("frei0r: with no effect, or only no-ops, the frame comes back as it was, also in place",
          "[adapters][frei0r][direct]") {
  Frei0r plugin("pfx_chain.so");
  const auto in = frame(37, 21, 3);
  for (const char* set : {"", "bloom.strength=0;glare.strength=0"}) {
    f0r_instance_t instance = plugin.construct(37, 21);
    REQUIRE(instance);
    plugin.set_string(instance, 0, *set ? "bloom,glare" : "none");
    plugin.set_string(instance, 1, set);
    std::vector<uint32_t> out(in.size(), 0);
    plugin.update(instance, 0, in.data(), out.data());
    CHECK(out == in);
    std::vector<uint32_t> same = in;
    plugin.update(instance, 0.04, same.data(), same.data());
    CHECK(same == in);
    plugin.destruct(instance);
  }
}

TEST_CASE("frei0r: frames render while the calling thread has a GLX or an EGL context current, which stays current and untouched",
          "[adapters][frei0r][direct]") {
  Frei0r plugin("pfx_chain.so");
  const auto expected = bloom_frames(plugin, 48, 32, 3, 2);
  REQUIRE(expected[0] != frame(48, 32, 3));

  REQUIRE(glfwInit());
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  GLFWwindow* window = glfwCreateWindow(64, 64, "a host's GLX context", nullptr, nullptr);
  REQUIRE(window);
  glfwMakeContextCurrent(window);
  using Viewport = void (*)(int, int, int, int);
  using GetIntegers = void (*)(unsigned, int*);
  auto viewport = reinterpret_cast<Viewport>(glfwGetProcAddress("glViewport"));
  auto get_integers = reinterpret_cast<GetIntegers>(glfwGetProcAddress("glGetIntegerv"));
  viewport(3, 5, 7, 11);
  CHECK(bloom_frames(plugin, 48, 32, 3, 2) == expected);
  CHECK(glfwGetCurrentContext() == window);
  int box[4] = {};
  get_integers(0x0BA2 /* GL_VIEWPORT */, box);
  CHECK((box[0] == 3 && box[1] == 5 && box[2] == 7 && box[3] == 11));
  glfwDestroyWindow(window);
  glfwTerminate();

  std::string error;
  auto context = pfx::app::HeadlessContext::create(&error);
  INFO(error);
  REQUIRE(context);
  const EGLContext mine = eglGetCurrentContext();
  CHECK(bloom_frames(plugin, 48, 32, 3, 2) == expected);
  CHECK(eglGetCurrentContext() == mine);
}

TEST_CASE("frei0r: instances on two threads at once, and of two sizes, give the frames each gives alone",
          "[adapters][frei0r][direct]") {
  Frei0r plugin("pfx_chain.so");
  const auto alone_a = bloom_frames(plugin, 40, 30, 10, 4);
  const auto alone_b = bloom_frames(plugin, 57, 23, 20, 4);  // another size, odd sides
  std::vector<std::vector<uint32_t>> a, b;
  std::thread first([&] { a = bloom_frames(plugin, 40, 30, 10, 4); });
  std::thread second([&] { b = bloom_frames(plugin, 57, 23, 20, 4); });
  first.join();
  second.join();
  CHECK(a == alone_a);
  CHECK(b == alone_b);
}

TEST_CASE("frei0r: pfx_bloom's parameters are bloom's descriptors: names, types, display-referred defaults on 0-1",
          "[adapters][frei0r][direct]") {
  Frei0r plugin("pfx_bloom.so");
  f0r_plugin_info_t info{};
  plugin.plugin_info(&info);
  CHECK(std::string(info.name) == "pfx_bloom");
  CHECK(info.plugin_type == F0R_PLUGIN_TYPE_FILTER);
  CHECK(info.color_model == F0R_COLOR_MODEL_RGBA8888);
  std::map<std::string, std::pair<int, int>> params;  // name -> index, type
  for (int i = 0; i < info.num_params; ++i) {
    f0r_param_info_t param{};
    plugin.param_info(&param, i);
    params[param.name] = {i, param.type};
  }
  CHECK(params["threshold"].second == F0R_PARAM_DOUBLE);
  CHECK(params["mode"].second == F0R_PARAM_STRING);
  CHECK(params["karis"].second == F0R_PARAM_BOOL);
  CHECK(params["tint"].second == F0R_PARAM_COLOR);
  const int threshold = params["threshold"].first, mode = params["mode"].first;
  f0r_instance_t instance = plugin.construct(32, 24);
  double value = -1;
  plugin.get_param(instance, &value, threshold);
  CHECK(value == Approx(0.6 / 8));  // the display-referred 0.6 on a slider over 0-8
  value = 0.0625;
  plugin.set_param(instance, &value, threshold);
  plugin.get_param(instance, &value, threshold);
  CHECK(value == Approx(0.0625));
  const char* text = nullptr;
  plugin.set_string(instance, mode, "gaussian");
  plugin.get_param(instance, &text, mode);
  CHECK(std::string(text) == "gaussian");
  plugin.set_string(instance, mode, "nosuch");  // refused, the value before it kept
  plugin.get_param(instance, &text, mode);
  CHECK(std::string(text) == "gaussian");
  double nan = std::nan("");
  plugin.set_param(instance, &nan, threshold);
  plugin.get_param(instance, &value, threshold);
  CHECK(value == Approx(0.0625));
  plugin.destruct(instance);
}

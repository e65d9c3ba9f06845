// Hot reload in libpfxhost (PluginRegistry::reload, Chain::refresh, reload_plugin, PluginWatcher)
// with the reloadable fixture: a plugin swapped for its next build while a chain runs it. Results
// are checked against the fixture's formulas computed here.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <pfx/host/hot_reload.hpp>
#include <pfx/host/plugin_watcher.hpp>

#include "gl_test_support.hpp"
#include "image_texture.hpp"

namespace fs = std::filesystem;
using pfx::app::Image;

namespace {

std::string build_of(const std::string& name) {
  return std::string(PFX_TEST_RELOADABLE_DIR) + "/reloadable_" + name + ".so";
}

// A plugin folder of its own, holding "reloadable.so", replaced the way a linker replaces its
// output: the new file is written beside it and renamed over it (a new inode; the running copy
// is untouched).
struct PluginFolder {
  fs::path dir = fs::temp_directory_path() / ("pfx-reload-test-" + std::to_string(::getpid()));
  std::string plugin = (dir / "reloadable.so").string();
  explicit PluginFolder(const std::string& first_build) {
    fs::create_directories(dir);
    install(first_build);
  }
  ~PluginFolder() { fs::remove_all(dir); }
  void install(const std::string& build) {
    const fs::path temp = dir / "reloadable.so.new";
    fs::copy_file(build_of(build), temp, fs::copy_options::overwrite_existing);
    fs::rename(temp, plugin);
  }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& item : fs::directory_iterator(dir)) names.push_back(item.path().filename().string());
    return names;
  }
};

struct Rig {
  pfx::test::CollectedLog log;
  std::unique_ptr<pfx::host::PluginRegistry> registry = pfx::test::make_registry(&log);
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  explicit Rig(const std::string& plugin) {
    std::string error;
    INFO(error);
    REQUIRE(registry->load(plugin, &error));
    chain = std::make_unique<pfx::host::Chain>(*registry, params);
  }
  // One pixel of colour c through the chain: the output's red channel.
  float render(float c) {
    Image img;
    img.width = img.height = 1;
    img.rgba = {c, c, c, 1.0f};
    pfx::host::FrameTextures textures;
    textures.color = pfx::app::upload_color_texture(img);
    uint32_t output = pfx::app::create_color_texture(1, 1);
    std::string error;
    bool ok = chain->render(pfx::test::make_frame(1, 1), textures, output, &error);
    INFO(error);
    CHECK(ok);
    Image result = pfx::app::download_color_texture(output, 1, 1);
    pfx::app::delete_texture(textures.color);
    pfx::app::delete_texture(output);
    return result.rgba[0];
  }
  bool reload(pfx::host::ReloadResult* result, std::string* error) {
    return pfx::host::reload_plugin(*registry, params, *chain, "org.pfx.test.reloadable", result, error);
  }
};

}  // namespace

TEST_CASE("a rebuilt plugin replaces the running one and keeps the parameter values", "[reload]") {
  PluginFolder folder("v1");
  Rig rig(folder.plugin);
  std::string error;
  REQUIRE(rig.chain->add("fade", &error));
  REQUIRE(rig.chain->add("tint", &error));
  REQUIRE(rig.params.set_assignment("tint.strength=3", &error));
  // V1: fade halves, tint multiplies: 2 -> 1 -> 3.
  CHECK(rig.render(2.0f) == Approx(3.0f));

  folder.install("v2");
  pfx::host::ReloadResult result;
  INFO(error);
  REQUIRE(rig.reload(&result, &error));
  CHECK(result.old_version == "1.0.0");
  CHECK(result.new_version == "2.0.0");
  // fade is gone from the new build: it leaves the chain and the store.
  CHECK(result.effects_dropped == std::vector<std::string>{"fade"});
  REQUIRE(rig.chain->size() == 1);
  CHECK(rig.chain->effect_id(0) == "tint");
  CHECK_FALSE(rig.params.has_effect("fade"));
  // strength kept (3), offset is new (default 0.25): 2 * 3 + 0.25.
  CHECK(rig.params.get_text("tint.strength") == "3");
  CHECK(rig.params.get_text("tint.offset") == "0.25");
  CHECK(rig.render(2.0f) == Approx(6.25f));
  CHECK(rig.registry->find_plugin("org.pfx.test.reloadable")->version == "2.0.0");
  CHECK(rig.registry->find_plugin("org.pfx.test.reloadable")->path == folder.plugin);
  // The private copy it was loaded from is gone; the folder holds only the plugin.
  CHECK(folder.files() == std::vector<std::string>{"reloadable.so"});

  // A second reload of the same file works too (a fresh private name each time).
  REQUIRE(rig.reload(&result, &error));
  CHECK(rig.render(2.0f) == Approx(6.25f));
}

TEST_CASE("a rebuilt plugin keeps the values of each instance apart", "[reload][instances]") {
  PluginFolder folder("v1");
  Rig rig(folder.plugin);
  std::string error;
  REQUIRE(rig.chain->add("tint", &error));
  REQUIRE(rig.chain->add("tint", &error));
  REQUIRE(rig.params.set_assignment("tint.strength=2", &error));
  REQUIRE(rig.params.set_assignment("tint#2.strength=3", &error));
  CHECK(rig.render(1.0f) == Approx(6.0f));  // v1: 1 * 2 * 3

  folder.install("v2");
  INFO(error);
  REQUIRE(rig.reload(nullptr, &error));
  CHECK(rig.params.instance_count("tint") == 2);
  CHECK(rig.params.get_text("tint.strength") == "2");
  CHECK(rig.params.get_text("tint#2.strength") == "3");
  // v2 adds the offset (0.25) after each: (1 * 2 + 0.25) * 3 + 0.25.
  CHECK(rig.render(1.0f) == Approx(7.0f));
}

TEST_CASE("a rebuilt plugin the loader refuses leaves the old version running", "[reload][errors]") {
  PluginFolder folder("v2");
  Rig rig(folder.plugin);
  std::string error;
  REQUIRE(rig.chain->add("tint", &error));
  REQUIRE(rig.params.set_assignment("tint.offset=1", &error));
  CHECK(rig.render(2.0f) == Approx(3.0f));

  folder.install("broken_abi");
  CHECK_FALSE(rig.reload(nullptr, &error));
  CHECK(error == folder.plugin +
                     ": ABI major version mismatch: plugin built for ABI 99." +
                         std::to_string(PFX_ABI_MINOR) + ", host implements ABI 1." + std::to_string(PFX_ABI_MINOR));
  CHECK(rig.registry->find_plugin("org.pfx.test.reloadable")->version == "2.0.0");
  CHECK(rig.params.get_text("tint.offset") == "1");
  CHECK(rig.render(2.0f) == Approx(3.0f));

  // Then a good build again: reloads as if nothing had happened.
  folder.install("v1");
  REQUIRE(rig.reload(nullptr, &error));
  CHECK(rig.render(2.0f) == Approx(2.0f));  // v1: no offset; strength 1
}

TEST_CASE("a rebuilt plugin whose effect cannot be created leaves the old version running", "[reload][errors]") {
  PluginFolder folder("v1");
  Rig rig(folder.plugin);
  std::string error;
  REQUIRE(rig.chain->add("tint", &error));
  REQUIRE(rig.chain->add("fade", &error));
  REQUIRE(rig.params.set_assignment("tint.strength=5", &error));
  CHECK(rig.render(1.0f) == Approx(2.5f));

  folder.install("broken_shader");
  CHECK_FALSE(rig.reload(nullptr, &error));
  CHECK(error == folder.plugin + ": effect 'tint' of the new version could not be created (status -5)");
  // The plugin's own log says why.
  bool shader_logged = false;
  for (const auto& line : rig.log.lines) shader_logged |= line.find("reloadable: shader:") != std::string::npos;
  CHECK(shader_logged);
  // Everything as before: both effects, the old descriptors in the store, the old results.
  REQUIRE(rig.chain->size() == 2);
  CHECK(rig.params.has_effect("fade"));
  CHECK(rig.params.descriptor("tint", "offset") == nullptr);
  CHECK(rig.params.get_text("tint.strength") == "5");
  CHECK(rig.render(1.0f) == Approx(2.5f));
  CHECK(rig.registry->find_plugin("org.pfx.test.reloadable")->version == "1.0.0");
}

TEST_CASE("reload refuses an unknown plugin, a missing file and another plugin's id", "[reload][errors]") {
  PluginFolder folder("v1");
  Rig rig(folder.plugin);
  std::string error;
  REQUIRE(rig.chain->add("tint", &error));
  CHECK_FALSE(pfx::host::reload_plugin(*rig.registry, rig.params, *rig.chain, "org.pfx.nothing", nullptr, &error));
  CHECK(error == "no plugin 'org.pfx.nothing' is loaded");

  fs::remove(folder.plugin);
  CHECK_FALSE(rig.reload(nullptr, &error));
  CHECK(error.rfind(folder.plugin + ": cannot make a private copy to reload from", 0) == 0);

  fs::copy_file(PFX_TEST_MINIMAL_PLUGIN, folder.plugin);
  CHECK_FALSE(rig.reload(nullptr, &error));
  CHECK(error == folder.plugin + ": the rebuilt library has plugin id 'org.pfx.test.minimal', not 'org.pfx.test.reloadable'");
  CHECK(rig.render(2.0f) == Approx(2.0f));
}

TEST_CASE("the watcher reports a changed file once, after it has settled", "[reload][watcher]") {
  const fs::path dir = fs::temp_directory_path() / ("pfx-watch-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "p.so").string();
  std::ofstream(file) << "one";
  pfx::host::PluginWatcher watcher(0.2);
  watcher.watch("p", file);
  CHECK(watcher.poll(0.0).empty());
  CHECK(watcher.poll(5.0).empty());  // unchanged, however long

  std::ofstream(file) << "two, longer";
  CHECK(watcher.poll(10.0).empty());   // change seen: settling starts
  CHECK(watcher.poll(10.1).empty());   // not settled
  std::ofstream(file, std::ios::app) << " and more";  // still being written
  CHECK(watcher.poll(10.25).empty());  // changed again: settling restarts
  CHECK(watcher.poll(10.4).empty());
  CHECK(watcher.poll(10.5) == std::vector<std::string>{"p"});
  CHECK(watcher.poll(11.0).empty());  // reported once

  // Deleted: waited for, not reported; reported once it is back and settled.
  fs::remove(file);
  CHECK(watcher.poll(20.0).empty());
  CHECK(watcher.poll(21.0).empty());
  std::ofstream(file) << "three";
  CHECK(watcher.poll(22.0).empty());
  CHECK(watcher.poll(22.3) == std::vector<std::string>{"p"});

  // Replaced by rename (what a linker or `install` does): a new inode is a change.
  const std::string next = (dir / "p.so.new").string();
  std::ofstream(next) << "three";  // same size, same content
  fs::rename(next, file);
  CHECK(watcher.poll(30.0).empty());
  CHECK(watcher.poll(30.5) == std::vector<std::string>{"p"});

  watcher.forget("p");
  std::ofstream(file) << "four";
  CHECK(watcher.poll(40.0).empty());
  CHECK(watcher.poll(41.0).empty());
  fs::remove_all(dir);
}

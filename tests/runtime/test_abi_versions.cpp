// The growth rule (core.h) from libpfxhost's side: the minimal plugin built against the headers of
// ABI 1.0, of today, and of a future 1.99 (bigger structs, arrays further apart) loads, describes
// its parameters and renders the same pixels; and every shipped plugin accepts a host struct of
// the first published size, as an engine built against ABI 1.0 hands it over.
#include <catch2/catch.hpp>

#include <dlfcn.h>

#include <cstring>
#include <filesystem>

#include "gl_test_support.hpp"
#include "image_texture.hpp"

namespace {

struct Build {
  const char* name;
  const char* path;
  uint32_t abi_minor;
};
const Build kBuilds[] = {{"today's", PFX_TEST_MINIMAL_PLUGIN, PFX_ABI_MINOR},
                         {"ABI 1.0", PFX_TEST_MINIMAL_OLD_PLUGIN, 0},
                         {"future ABI 1.99", PFX_TEST_MINIMAL_FUTURE_PLUGIN, 99}};

std::vector<std::string> param_ids(const pfx_effect_desc* effect) {
  std::vector<std::string> ids;
  for (uint32_t i = 0; i < effect->param_count; ++i) ids.push_back(effect->params[i].id);
  return ids;
}

// gain 2.5 then a 1.5 px box blur over the test image, read back.
pfx::app::Image render_minimal(const char* path) {
  auto registry = pfx::test::make_registry();
  std::string error;
  INFO(path << ": " << error);
  REQUIRE(registry->load(path, &error));
  pfx::host::ParamStore params;
  pfx::host::Chain chain(*registry, params);
  REQUIRE(chain.add("gain", &error));
  REQUIRE(chain.add("boxblur", &error));
  REQUIRE(params.set_assignment("gain.gain=2.5", &error));
  REQUIRE(params.set_assignment("gain.channels=luma", &error));
  REQUIRE(params.set_assignment("boxblur.radius=1.5", &error));
  const pfx::app::Image input = pfx::test::test_image(23, 11);
  pfx::host::FrameTextures textures;
  textures.color = pfx::app::upload_color_texture(input);
  const uint32_t output = pfx::app::create_color_texture(input.width, input.height);
  const bool ok = chain.render(pfx::test::make_frame(input.width, input.height), textures, output, &error);
  pfx::app::Image result = pfx::app::download_color_texture(output, input.width, input.height);
  pfx::app::delete_texture(textures.color);
  pfx::app::delete_texture(output);
  REQUIRE(ok);
  REQUIRE(chain.report().passes.size() == 4);  // gain, then boxblur's down, box and up
  return result;
}

}  // namespace

TEST_CASE("a plugin built against ABI 1.0, today's or a future 1.99 header describes the same parameters",
          "[abi]") {
  for (const Build& build : kBuilds) {
    INFO(build.name);
    auto registry = pfx::test::make_registry();
    std::string error;
    REQUIRE(registry->load(build.path, &error));
    REQUIRE(registry->plugins().size() == 1);
    CHECK(registry->plugins()[0]->abi_minor == build.abi_minor);
    const pfx::host::EffectInfo* gain = registry->find_effect("gain");
    const pfx::host::EffectInfo* blur = registry->find_effect("boxblur");
    REQUIRE(gain);
    REQUIRE(blur);
    // Indexing the future build's parameters by this host's sizeof would land inside element 0.
    CHECK(param_ids(gain->desc) == std::vector<std::string>{"gain", "channels"});
    CHECK(param_ids(blur->desc) == std::vector<std::string>{"radius"});
    CHECK(gain->desc->params[1].type == PFX_PARAM_ENUM);
    CHECK(gain->desc->params[1].item_count == 2);
    CHECK(gain->desc->params[0].default_value.v[0] == 1.0);
    CHECK(gain->desc->params[0].display_max == 4.0);
    CHECK(blur->desc->params[0].hard_max > 0);
  }
}

TEST_CASE("a plugin built against ABI 1.0 or a future 1.99 header renders today's pixels bit for bit", "[abi]") {
  const pfx::app::Image today = render_minimal(PFX_TEST_MINIMAL_PLUGIN);
  for (const Build& build : kBuilds) {
    INFO(build.name);
    const pfx::app::Image other = render_minimal(build.path);
    REQUIRE(other.rgba.size() == today.rgba.size());
    CHECK(std::memcmp(other.rgba.data(), today.rgba.data(), today.rgba.size() * sizeof(float)) == 0);
  }
}

namespace {

void log_nowhere(void*, pfx_log_level, const char*) {}
pfx_gl_proc context_proc(void*, const char* name) { return pfx::app::HeadlessContext::get_proc_address(nullptr, name); }

}  // namespace

TEST_CASE("every shipped plugin accepts a host struct of ABI 1.0 and runs without host services", "[abi]") {
  pfx::test::gl_context();
  // The first published pfx_host: no get_service. A plugin that checked struct_size against its
  // own sizeof, or read get_service regardless, would refuse or crash here.
  pfx_host host{};
  host.struct_size = static_cast<uint32_t>(PFX_HOST_MIN_SIZE);
  host.abi_major = PFX_ABI_MAJOR;
  host.abi_minor = 0;
  host.host_name = "ABI 1.0 host";
  host.log = log_nowhere;
  host.get_proc_address = context_proc;
  int plugins = 0;
  for (const auto& file : std::filesystem::directory_iterator(PFX_PLUGIN_OUTPUT_DIR)) {
    if (file.path().extension() != ".so") continue;
    INFO(file.path().string());
    void* library = dlopen(file.path().c_str(), RTLD_NOW | RTLD_LOCAL);
    REQUIRE(library);
    auto get_entry = reinterpret_cast<pfx_get_entry_fn>(dlsym(library, PFX_ENTRY_SYMBOL));
    REQUIRE(get_entry);
    const pfx_entry* entry = get_entry();
    REQUIRE(entry->init(&host) == PFX_OK);
    if (auto effects = static_cast<const pfx_effect_factory*>(entry->get_factory(PFX_EFFECTS_FACTORY_ID))) {
      for (uint32_t i = 0; i < effects->effect_count(); ++i) {
        const pfx_effect_desc* effect = effects->get_effect(i);
        INFO(effect->id);
        void* instance = nullptr;
        CHECK(effect->create(&host, &instance) == PFX_OK);
        if (instance) effect->destroy(instance);
      }
    }
    if (auto importers = static_cast<const pfx_importer_factory*>(entry->get_factory(PFX_IMPORTERS_FACTORY_ID))) {
      // Without a thread pool to ask for, an importer runs serially and gets the same model.
      static const char kQuad[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
      for (uint32_t i = 0; i < importers->importer_count(); ++i) {
        const pfx_importer_desc* importer = importers->get_importer(i);
        if (std::string(importer->extensions[0]) != "obj") continue;
        pfx_import_request request{};
        request.struct_size = sizeof request;
        request.bytes = kQuad;
        request.byte_count = sizeof kQuad - 1;
        request.threads = 0;
        pfx_import_result* result = nullptr;
        CHECK(importer->import(&request, &result) == PFX_OK);
        REQUIRE(result);
        CHECK(result->vertex_count == 4);
        CHECK(result->index_count == 6);
        importer->release(result);
      }
    }
    entry->deinit();
    dlclose(library);
    ++plugins;
  }
  CHECK(plugins >= 4);  // bloom, dof, tiledlights, objimport
}

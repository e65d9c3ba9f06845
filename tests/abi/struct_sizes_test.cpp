// The first published size of every ABI struct, pinned in numbers, and the table of docs/sdk.md
// §1.7 that host and plugin writers read them from. A struct's minimum never changes: a change here
// means a field of a published version moved, which breaks every binary built before it.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <pfx/pfx.h>
#include <pfx/vulkan_effects.h>

namespace {

struct Sizes {
  size_t minimum, today;
};

// x86-64 and other LP64 targets. "today" is sizeof with this tree's headers (ABI 1.9).
const std::map<std::string, Sizes>& pinned() {
  static const std::map<std::string, Sizes> sizes = {
      {"pfx_entry", {64, 64}},          {"pfx_host", {48, 56}},
      {"pfx_param_desc", {140, 176}},   {"pfx_effect_factory", {24, 24}},
      {"pfx_effect_desc", {88, 96}},    {"pfx_frame", {200, 200}},
      {"pfx_light", {32, 32}},          {"pfx_target_desc", {40, 40}},
      {"pfx_pass_desc", {56, 56}},      {"pfx_declaration", {40, 48}},
      {"pfx_pass_context", {68, 72}},   {"pfx_reference_factory", {24, 24}},
      {"pfx_reference_request", {64, 88}}, {"pfx_importer_factory", {24, 24}},
      {"pfx_importer_desc", {56, 56}},  {"pfx_import_request", {64, 64}},
      {"pfx_import_result", {184, 184}}, {"pfx_import_material", {80, 104}},
      {"pfx_thread_pool", {32, 32}},    {"pfx_source_factory", {40, 56}},
      {"pfx_vk_device", {56, 56}},      {"pfx_vk_frame_image", {28, 32}},
      {"pfx_vulkan_effect_factory", {40, 48}}};
  return sizes;
}

#define PFX_SIZES(type, minimum) {#type, {minimum, sizeof(type)}}
std::map<std::string, Sizes> compiled() {
  return {PFX_SIZES(pfx_entry, PFX_ENTRY_MIN_SIZE),
          PFX_SIZES(pfx_host, PFX_HOST_MIN_SIZE),
          PFX_SIZES(pfx_param_desc, PFX_PARAM_DESC_MIN_SIZE),
          PFX_SIZES(pfx_effect_factory, PFX_EFFECT_FACTORY_MIN_SIZE),
          PFX_SIZES(pfx_effect_desc, PFX_EFFECT_DESC_MIN_SIZE),
          PFX_SIZES(pfx_frame, PFX_FRAME_MIN_SIZE),
          PFX_SIZES(pfx_light, PFX_LIGHT_MIN_SIZE),
          PFX_SIZES(pfx_target_desc, PFX_TARGET_DESC_MIN_SIZE),
          PFX_SIZES(pfx_pass_desc, PFX_PASS_DESC_MIN_SIZE),
          PFX_SIZES(pfx_declaration, PFX_DECLARATION_MIN_SIZE),
          PFX_SIZES(pfx_pass_context, PFX_PASS_CONTEXT_MIN_SIZE),
          PFX_SIZES(pfx_reference_factory, PFX_REFERENCE_FACTORY_MIN_SIZE),
          PFX_SIZES(pfx_reference_request, PFX_REFERENCE_REQUEST_MIN_SIZE),
          PFX_SIZES(pfx_importer_factory, PFX_IMPORTER_FACTORY_MIN_SIZE),
          PFX_SIZES(pfx_importer_desc, PFX_IMPORTER_DESC_MIN_SIZE),
          PFX_SIZES(pfx_import_request, PFX_IMPORT_REQUEST_MIN_SIZE),
          PFX_SIZES(pfx_import_result, PFX_IMPORT_RESULT_MIN_SIZE),
          PFX_SIZES(pfx_import_material, PFX_IMPORT_MATERIAL_MIN_SIZE),
          PFX_SIZES(pfx_thread_pool, PFX_THREAD_POOL_MIN_SIZE),
          PFX_SIZES(pfx_source_factory, PFX_SOURCE_FACTORY_MIN_SIZE),
          PFX_SIZES(pfx_vk_device, PFX_VK_DEVICE_MIN_SIZE),
          PFX_SIZES(pfx_vk_frame_image, PFX_VK_FRAME_IMAGE_MIN_SIZE),
          PFX_SIZES(pfx_vulkan_effect_factory, PFX_VULKAN_EFFECT_FACTORY_MIN_SIZE)};
}
#undef PFX_SIZES

// The rows "| `pfx_x` | since | minimum | today | ... |" of docs/sdk.md §1.7.
std::map<std::string, Sizes> documented() {
  std::ifstream doc(PFX_SDK_DOC);
  std::map<std::string, Sizes> sizes;
  std::string line;
  bool in_section = false;
  while (std::getline(doc, line)) {
    if (line.rfind("### ", 0) == 0) in_section = line.rfind("### 1.7 ", 0) == 0;
    if (!in_section || line.rfind("| `pfx_", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    std::string cell;
    while (std::getline(row, cell, '|')) cells.push_back(cell);
    if (cells.size() < 4) continue;
    const std::string name = cells[0].substr(cells[0].find('`') + 1, cells[0].rfind('`') - cells[0].find('`') - 1);
    sizes[name] = {std::stoul(cells[2]), std::stoul(cells[3])};
  }
  return sizes;
}

}  // namespace

TEST_CASE("every struct's first published size and today's size are the pinned numbers", "[abi]") {
  if (sizeof(void*) != 8) SUCCEED("the numbers are pinned for LP64 targets only");
  else {
    for (const auto& [name, sizes] : compiled()) {
      INFO(name);
      REQUIRE(pinned().count(name));
      CHECK(sizes.minimum == pinned().at(name).minimum);
      CHECK(sizes.today == pinned().at(name).today);
    }
    CHECK(compiled().size() == pinned().size());
  }
}

TEST_CASE("docs/sdk.md publishes the same sizes", "[abi]") {
  const auto doc = documented();
  for (const auto& [name, sizes] : pinned()) {
    INFO(name << " in docs/sdk.md §1.7");
    REQUIRE(doc.count(name));
    CHECK(doc.at(name).minimum == sizes.minimum);
    CHECK(doc.at(name).today == sizes.today);
  }
  CHECK(doc.size() == pinned().size());
}

TEST_CASE("a struct's minimum covers every field a 1.0 reader relies on", "[abi]") {
  // Spot checks against the layout rule itself, independent of the pinned numbers.
  CHECK(PFX_HOST_MIN_SIZE == offsetof(pfx_host, get_service));
  CHECK(PFX_REFERENCE_REQUEST_MIN_SIZE == offsetof(pfx_reference_request, normal));
  CHECK(PFX_PARAM_DESC_MIN_SIZE <= sizeof(pfx_param_desc));
  pfx_host host{};
  host.struct_size = static_cast<uint32_t>(PFX_HOST_MIN_SIZE);
  CHECK_FALSE(PFX_STRUCT_HAS(&host, pfx_host, get_service));
  CHECK(PFX_STRUCT_HAS(&host, pfx_host, get_proc_address));
  host.struct_size = sizeof host;
  CHECK(PFX_STRUCT_HAS(&host, pfx_host, get_service));
}

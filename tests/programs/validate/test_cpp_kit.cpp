// The SDK's C++ kit (sdk/helpers/include/pfx/cpp/) on its own: what a field left out becomes, that
// the result passes pfx-validate's descriptor checks, that the declaration builder refuses what
// does not fit instead of writing past its storage, and what the entry made from a Plugin offers.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include <pfx/cpp/declaration.hpp>
#include <pfx/cpp/descriptors.hpp>
#include <pfx/cpp/plugin_entry.hpp>

#include "descriptor_checks.hpp"

namespace {

const pfx_enum_item kItems[] = {{"a", "A"}, {"b", "B"}, {"c", "C"}};

const pfx_param_desc kBare = pfx::desc::param("bare").float_range(0, 4);
const pfx_param_desc kEnum = pfx::desc::param("pick").items(kItems).default_value(2).display_default(1);
const pfx_param_desc kSteps = pfx::desc::param("steps").int_range(1, 9).display_range(2, 5).logarithmic().default_value(3);

pfx_status no_create(const pfx_host*, void**) { return PFX_ERROR; }
void no_destroy(void*) {}
pfx_status no_declare(void*, const pfx_frame*, const pfx_value*, pfx_declaration*) { return PFX_ERROR; }
pfx_status no_run(void*, const pfx_pass_context*) { return PFX_ERROR; }

constexpr pfx_effect_desc kEffect =
    pfx::desc::effect("e").create(no_create).destroy(no_destroy).declare(no_declare).run_pass(no_run);
constexpr const pfx_effect_desc* kEffects[] = {&kEffect};
constexpr auto kPlugin = pfx::plugin::Plugin("org.pfx.test.kit").effects(kEffects);
using KitEntry = pfx::plugin::Entry<kPlugin>;

}  // namespace

TEST_CASE("a parameter's fields left out take the documented defaults", "[kit]") {
  CHECK(kBare.struct_size == sizeof(pfx_param_desc));
  CHECK(std::string(kBare.label) == "bare");  // the id
  CHECK(std::string(kBare.tooltip).empty());
  CHECK(std::string(kBare.unit).empty());
  CHECK(std::string(kBare.group).empty());
  CHECK(kBare.type == PFX_PARAM_FLOAT);
  CHECK((kBare.display_min == 0 && kBare.display_max == 4));  // the hard range
  CHECK(kBare.step == Approx(0.04));                           // a hundredth of the display range
  CHECK(kBare.default_value.v[0] == 0);
  CHECK(kBare.flags == 0);

  CHECK(kEnum.type == PFX_PARAM_ENUM);
  CHECK(kEnum.item_count == 3);
  CHECK((kEnum.hard_min == 0 && kEnum.hard_max == 2));  // one value per item
  CHECK(kEnum.step == 1);
  CHECK(kEnum.default_value.v[0] == 2);
  CHECK(kEnum.flags == PFX_PARAM_HAS_DISPLAY_DEFAULT);
  CHECK(kEnum.display_default.v[0] == 1);

  CHECK(kSteps.step == 1);
  CHECK((kSteps.display_min == 2 && kSteps.display_max == 5));
  CHECK(kSteps.flags == PFX_PARAM_LOGARITHMIC);

  // Every default is one pfx-validate accepts, but for the tooltip a UI needs: that one is the
  // author's to write.
  for (const pfx_param_desc* p : {&kBare, &kEnum, &kSteps}) {
    INFO(p->id);
    CHECK(pfx::validate::param_descriptor_problems(*p) ==
          std::vector<std::string>{"parameter '" + std::string(p->id) + "': no tooltip"});
    pfx_param_desc with_tooltip = *p;
    with_tooltip.tooltip = "What it does.";
    CHECK(pfx::validate::param_descriptor_problems(with_tooltip).empty());
  }
  CHECK(std::string(kEffect.label) == "e");
  CHECK(std::string(kEffect.description).empty());
}

TEST_CASE("the declaration builder refuses what outgrows it and leaves the declaration untouched", "[kit]") {
  pfx::desc::DeclarationBuilder<1, 2> d;
  pfx_declaration out{};
  out.struct_size = sizeof out;
  d.clear();
  d.target("half", 8, 4);
  d.pass("down", "half").input(PFX_INPUT_NAME_COLOR).tag(7);
  d.pass("up", PFX_OUTPUT_NAME).input(PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST).input("half").blend(PFX_BLEND_ADD);
  REQUIRE(d.finish(&out) == PFX_OK);
  REQUIRE(out.pass_count == 2);
  CHECK(out.target_count == 1);
  CHECK(out.targets[0].width == 8);
  CHECK(out.targets[0].format == PFX_FORMAT_RGBA16F);
  CHECK(out.passes[0].user_tag == 7);
  CHECK(out.passes[0].load == PFX_LOAD_DONT_CARE);
  CHECK(out.passes[1].input_count == 2);
  CHECK(out.passes[1].inputs[0].filter == PFX_FILTER_NEAREST);
  CHECK(out.passes[1].inputs[1].filter == PFX_FILTER_LINEAR);
  CHECK(out.passes[1].blend == PFX_BLEND_ADD);

  pfx_declaration fresh{};
  fresh.struct_size = sizeof fresh;
  d.clear();
  d.pass("a", PFX_OUTPUT_NAME);
  d.pass("b", PFX_OUTPUT_NAME);
  d.pass("c", PFX_OUTPUT_NAME).input("x");  // a third pass in room for two
  CHECK(d.finish(&fresh) == PFX_ERROR);
  CHECK(fresh.passes == nullptr);

  d.clear();
  d.target("t0", 1, 1);
  d.target("t1", 1, 1);  // a second target in room for one
  CHECK(d.finish(&fresh) == PFX_ERROR);

  d.clear();
  auto many = d.pass("many", PFX_OUTPUT_NAME);
  for (uint32_t i = 0; i <= PFX_MAX_PASS_INPUTS; ++i) many.input(PFX_INPUT_NAME_COLOR);
  CHECK(d.finish(&fresh) == PFX_ERROR);

  d.clear();  // and it recovers
  d.pass("one", PFX_OUTPUT_NAME);
  CHECK(d.finish(&fresh) == PFX_OK);
  CHECK(fresh.pass_count == 1);
}

TEST_CASE("the entry made from a Plugin checks the host and offers only what it was given", "[kit]") {
  const pfx_entry& entry = KitEntry::kEntry;
  CHECK(entry.struct_size == sizeof(pfx_entry));
  CHECK(entry.abi_major == PFX_ABI_MAJOR);
  CHECK(std::string(entry.id) == "org.pfx.test.kit");
  CHECK(std::string(entry.name) == "org.pfx.test.kit");  // left out: the id
  CHECK(std::string(entry.version) == "0.0.0");
  CHECK(entry.init(nullptr) == PFX_INVALID_ARGUMENT);
  pfx_host too_small{};
  too_small.struct_size = 8;
  CHECK(entry.init(&too_small) == PFX_INVALID_ARGUMENT);

  const auto* effects = static_cast<const pfx_effect_factory*>(entry.get_factory(PFX_EFFECTS_FACTORY_ID));
  REQUIRE(effects != nullptr);
  CHECK(effects->effect_count() == 1);
  CHECK(effects->get_effect(0) == &kEffect);
  CHECK(effects->get_effect(1) == nullptr);
  CHECK(entry.get_factory(PFX_REFERENCES_FACTORY_ID) == nullptr);
  CHECK(entry.get_factory(PFX_IMPORTERS_FACTORY_ID) == nullptr);
  CHECK(entry.get_factory("pfx.unknown/1") == nullptr);
  CHECK(entry.get_factory(nullptr) == nullptr);
}

// The parameter store against hand-written descriptors: validation per descriptor, NaN always
// refused, and text and JSON round trips.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "param_fixture.hpp"

using pfx::test::make_param;
using pfx::test::ParamFixture;

TEST_CASE("values start at their defaults and parse in every text form", "[params]") {
  ParamFixture f;
  const pfx_value* v = f.store.values("bloom");
  REQUIRE(v);
  CHECK(v[0].v[0] == 1);
  CHECK(v[1].v[0] == 6);
  std::string error;
  CHECK(f.store.set("bloom.threshold", "+.5", &error));
  CHECK(v[0].v[0] == 0.5);
  CHECK(f.store.set("bloom.mode", "chain13", &error));
  CHECK(v[2].v[0] == 1);
  CHECK(f.store.set("bloom.mode", "2", &error));
  CHECK(v[2].v[0] == 2);
  CHECK(f.store.set("bloom.tint", "1, 0.5,0.25", &error));
  CHECK(v[3].v[1] == 0.5);
  CHECK(v[3].v[2] == 0.25);
  CHECK(f.store.set("bloom.tint", "2", &error));  // one number fills a colour
  CHECK((v[3].v[0] == 2 && v[3].v[1] == 2 && v[3].v[2] == 2));
  CHECK(f.store.set_assignment("bloom.karis = off", &error));
  CHECK(v[4].v[0] == 0);
  CHECK(f.store.set("bloom.focus", "inf", &error));  // the hard range includes infinity
  CHECK(std::isinf(v[5].v[0]));
}

TEST_CASE("NaN is always refused and leaves the value alone", "[params][hard]") {
  ParamFixture f;
  std::string error;
  for (const char* text : {"nan", "NaN", "-nan"}) {
    CHECK_FALSE(f.store.set("bloom.threshold", text, &error));
    CHECK(error == "bloom.threshold: NaN is not a valid value");
  }
  pfx_value nan_value{};
  nan_value.v[0] = std::nan("");
  CHECK_FALSE(f.store.set_value("bloom", "threshold", nan_value, &error));
  CHECK(f.store.values("bloom")[0].v[0] == 1);
}

TEST_CASE("out-of-range values are clamped or refused as the descriptor says", "[params]") {
  ParamFixture f;
  std::string error, note;
  CHECK(f.store.set("bloom.threshold", "1e9", &error, &note));
  CHECK(f.store.values("bloom")[0].v[0] == 100);
  CHECK(note == "clamped to 100");
  CHECK(f.store.set("bloom.threshold", "-inf", &error, &note));
  CHECK(f.store.values("bloom")[0].v[0] == 0);
  CHECK_FALSE(f.store.set("bloom.levels", "17", &error));
  CHECK(error == "bloom.levels: 17 is outside [0, 16]");
  CHECK_FALSE(f.store.set("bloom.levels", "2.5", &error));
  CHECK(error == "bloom.levels: 2.5 is not a whole number");
  CHECK_FALSE(f.store.set("bloom.mode", "fast", &error));
  CHECK(error == "bloom.mode: 'fast' is not one of: chain, chain13, gaussian");
  CHECK_FALSE(f.store.set("bloom.tint", "1,2", &error));
  CHECK_FALSE(f.store.set("bloom.threshold", "1.5x", &error));
  CHECK(error == "bloom.threshold: '1.5x' is not a number");
  CHECK(f.store.values("bloom")[1].v[0] == 6);
}

TEST_CASE("numbers beyond a double keep their sign: too large is infinite, too small is zero", "[params][hard]") {
  // The values a double holds are worked out by hand: DBL_MAX is about 1.8e308 and the smallest
  // denormal 4.9e-324, so 1e999 and 1.8e308 are too large, 1e-999 and 2e-400 too small.
  ParamFixture f;
  std::string error, note;
  const pfx_value* v = f.store.values("bloom");
  CHECK(f.store.set("bloom.threshold", "-1e999", &error, &note));  // [0, 100]: its minimum, not its maximum
  CHECK(v[0].v[0] == 0);
  CHECK(note == "clamped to 0");
  CHECK(f.store.set("bloom.threshold", "1.8e308", &error, &note));
  CHECK(v[0].v[0] == 100);
  CHECK(f.store.set("bloom.threshold", "1e-999", &error, &note));  // zero, not infinity
  CHECK(v[0].v[0] == 0);
  CHECK(f.store.set("bloom.threshold", "-0.0002e-398", &error, &note));
  CHECK(v[0].v[0] == 0);
  CHECK_FALSE(std::signbit(v[0].v[0]));
  CHECK(f.store.set("bloom.threshold", "4.9e-324", &error, &note));  // a denormal is a value
  CHECK(v[0].v[0] == std::numeric_limits<double>::denorm_min());
  CHECK(f.store.set("bloom.focus", "+1e999", &error));  // [0.01, inf]
  CHECK(std::isinf(v[5].v[0]));
  CHECK(f.store.set("bloom.focus", "12345678901234567890e99999999999999", &error));
  CHECK(std::isinf(v[5].v[0]));
  CHECK(f.store.set("bloom.focus", "0.000000001e-99999999999999", &error, &note));
  CHECK(v[5].v[0] == 0.01);
  CHECK(f.store.set("bloom.tint", "-1e999,1e-999,1e999", &error));  // each component its own
  CHECK((v[3].v[0] == 0 && v[3].v[1] == 0 && v[3].v[2] > 0));
  // The same through a text preset (--set's form) and a JSON preset.
  REQUIRE(f.store.from_text("bloom.threshold=-1e999\nbloom.focus=1e-999\n", &error));
  v = f.store.values("bloom");
  CHECK(v[0].v[0] == 0);
  CHECK(v[5].v[0] == 0.01);
  REQUIRE(f.store.set_assignment("bloom.threshold=1e999", &error));
  CHECK(v[0].v[0] == 100);
  // JSON: too small is zero; too large is refused by the JSON reader, naming the number, and
  // changes nothing (JSON has no infinity; write "inf" or "-inf" as a string).
  ParamFixture g;
  REQUIRE(g.store.from_json(R"({"bloom": {"threshold": -1e-999, "focus": 1e-999}})", &error));
  CHECK(g.store.values("bloom")[0].v[0] == 0);
  CHECK(g.store.values("bloom")[5].v[0] == 0.01);
  CHECK_FALSE(g.store.from_json(R"({"bloom": {"threshold": -1e999}})", &error));
  CHECK(error.find("number overflow parsing '-1e999'") != std::string::npos);
  REQUIRE(g.store.from_json(R"({"bloom": {"threshold": "-1e999", "focus": "inf"}})", &error));
  CHECK(g.store.values("bloom")[0].v[0] == 0);
  CHECK(std::isinf(g.store.values("bloom")[5].v[0]));
}

TEST_CASE("unknown keys name what exists", "[params]") {
  ParamFixture f;
  std::string error;
  CHECK_FALSE(f.store.set("glare.threshold", "1", &error));
  CHECK(error == "unknown effect 'glare' in 'glare.threshold'");
  CHECK_FALSE(f.store.set("bloom.radius", "1", &error));
  CHECK(error == "effect 'bloom' has no parameter 'radius' (it has: threshold, levels, mode, tint, karis, focus)");
  CHECK_FALSE(f.store.set_assignment("bloom.threshold", &error));
}

TEST_CASE("text and JSON round trips reproduce every value exactly", "[params]") {
  ParamFixture f;
  std::string error;
  REQUIRE(f.store.set("bloom.threshold", "0.1", &error));
  REQUIRE(f.store.set("bloom.mode", "gaussian", &error));
  REQUIRE(f.store.set("bloom.tint", "0.3,0.7,1e-7", &error));
  REQUIRE(f.store.set("bloom.karis", "false", &error));
  const std::string text = f.store.to_text();
  CHECK(text.find("bloom.threshold=0.1\n") != std::string::npos);
  CHECK(text.find("bloom.mode=gaussian\n") != std::string::npos);

  ParamFixture g;
  REQUIRE(g.store.from_text("# a preset\n\n" + text, &error));
  ParamFixture h;
  REQUIRE(h.store.from_json(f.store.to_json(), &error));
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 4; ++c) {
      CHECK(g.store.values("bloom")[i].v[c] == f.store.values("bloom")[i].v[c]);
      CHECK(h.store.values("bloom")[i].v[c] == f.store.values("bloom")[i].v[c]);
    }
  CHECK(f.store.get_text("bloom.tint") == "0.3,0.7,1e-07");
}

TEST_CASE("minus zero is kept as zero, so text and JSON read it back alike", "[params][hard]") {
  // Found by the parameter-text fuzzer: "bloom.levels=-0e999" was kept as -0, written to JSON as
  // -0, which JSON reads back as the integer 0, so the JSON preset no longer matched the text one.
  ParamFixture f;
  std::string error;
  REQUIRE(f.store.from_text("bloom.levels=-0e999\nbloom.tint=-0,0.5,-0.0\n", &error));
  CHECK(f.store.get_text("bloom.levels") == "0");
  CHECK(f.store.get_text("bloom.tint") == "0,0.5,0");
  CHECK_FALSE(std::signbit(f.store.values("bloom")[1].v[0]));
  ParamFixture g;
  REQUIRE(g.store.from_json(f.store.to_json(), &error));
  CHECK(g.store.to_text() == f.store.to_text());
}

TEST_CASE("a bad line or member changes nothing", "[params]") {
  ParamFixture f;
  std::string error;
  CHECK_FALSE(f.store.from_text("bloom.threshold=3\nbloom.levels=99\n", &error));
  CHECK(error == "line 2: bloom.levels: 99 is outside [0, 16]");
  CHECK(f.store.values("bloom")[0].v[0] == 1);
  CHECK_FALSE(f.store.from_json(R"({"bloom": {"threshold": 3, "mode": "nope"}})", &error));
  CHECK(f.store.values("bloom")[0].v[0] == 1);
  CHECK_FALSE(f.store.from_json("{\"bloom\": ", &error));
  CHECK(error.rfind("not valid JSON", 0) == 0);
  CHECK_FALSE(f.store.from_json(R"({"dof": {"focus": 1}})", &error));
}

TEST_CASE("re-registering a reloaded effect keeps values by id and type", "[params]") {
  ParamFixture f;
  std::string error;
  REQUIRE(f.store.set("bloom.threshold", "7", &error));
  REQUIRE(f.store.set("bloom.levels", "3", &error));
  uint64_t before = f.store.revision("bloom");
  // The reloaded plugin turned levels into a float and dropped the rest.
  pfx_param_desc reloaded[2] = {make_param("threshold", PFX_PARAM_FLOAT, 0, 100, 1),
                                make_param("levels", PFX_PARAM_FLOAT, 0, 16, 6)};
  pfx_effect_desc effect{};
  effect.struct_size = sizeof effect;
  effect.id = "bloom";
  effect.params = reloaded;
  effect.param_count = 2;
  f.store.add_effect(&effect);
  CHECK(f.store.values("bloom")[0].v[0] == 7);
  CHECK(f.store.values("bloom")[1].v[0] == 6);
  CHECK(f.store.revision("bloom") > before);
}

TEST_CASE("a display-referred store starts from the display defaults a descriptor gives", "[params]") {
  ParamFixture f;
  f.params[0].flags |= PFX_PARAM_HAS_DISPLAY_DEFAULT;
  f.params[0].display_default.v[0] = 0.6;
  pfx::host::ParamStore display(pfx::host::DefaultSet::DISPLAY_REFERRED);
  display.add_effect(&f.effect);
  pfx::host::ParamStore scene;
  scene.add_effect(&f.effect);
  CHECK(display.values("bloom")[0].v[0] == 0.6);
  CHECK(scene.values("bloom")[0].v[0] == 1);
  // Parameters without a display default start from their one default in both.
  CHECK(display.values("bloom")[1].v[0] == 6);
  // Reset and new instances go back to the store's own kind of default.
  std::string error;
  REQUIRE(display.set("bloom.threshold", "3", &error));
  display.reset("bloom", "threshold");
  CHECK(display.values("bloom")[0].v[0] == 0.6);
  REQUIRE(display.set_instance_count("bloom", 2));
  CHECK(display.values("bloom#2")[0].v[0] == 0.6);
  // A set overrides it as any default.
  REQUIRE(display.set("bloom.threshold", "0.25", &error));
  CHECK(display.values("bloom")[0].v[0] == 0.25);
}

TEST_CASE("a display default is read only where the descriptor's size covers it", "[params][abi]") {
  pfx_param_desc param = make_param("threshold", PFX_PARAM_FLOAT, 0, 100, 1);
  param.flags |= PFX_PARAM_HAS_DISPLAY_DEFAULT;
  param.display_default.v[0] = 0.6;
  CHECK(pfx::host::default_for(param, pfx::host::DefaultSet::DISPLAY_REFERRED).v[0] == 0.6);
  CHECK(pfx::host::default_for(param, pfx::host::DefaultSet::SCENE_REFERRED).v[0] == 1);
  // Written by an ABI 1.3 plugin: the struct ends before display_default, whatever the flag says.
  param.struct_size = PFX_STRUCT_SIZE_THROUGH(pfx_param_desc, item_count);
  CHECK(pfx::host::default_for(param, pfx::host::DefaultSet::DISPLAY_REFERRED).v[0] == 1);
}

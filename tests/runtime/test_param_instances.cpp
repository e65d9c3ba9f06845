// Per-instance values in the parameter store: "bloom#2" names the second instance, plain "bloom"
// the first, text and JSON name the first "bloom" and the others "bloom#N", a store without a
// chain is shaped by set_instance_count, and naming an instance that does not exist is refused
// with the count. (Instances moving and leaving with their values: test_chain_instances.cpp.)
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "param_fixture.hpp"

using pfx::test::ParamFixture;

namespace {

double threshold(const pfx::host::ParamStore& store, const std::string& instance) {
  const pfx_value* values = store.values(instance);
  REQUIRE(values);
  return values[0].v[0];
}

}  // namespace

TEST_CASE("bloom and bloom#1 are the same instance, bloom#2 another with its own values", "[params][instances]") {
  ParamFixture f;
  std::string error;
  CHECK(f.store.instance_count("bloom") == 1);
  REQUIRE(f.store.set_assignment("bloom#1.threshold=2", &error));
  CHECK(f.store.get_text("bloom.threshold") == "2");
  REQUIRE(f.store.set_assignment("bloom.threshold=3", &error));
  CHECK(f.store.get_text("bloom#1.threshold") == "3");
  CHECK(f.store.values("bloom") == f.store.values("bloom#1"));
  CHECK(f.store.values("bloom") == f.store.values("bloom", 1));

  REQUIRE(f.store.set_instance_count("bloom", 2));
  CHECK(threshold(f.store, "bloom#2") == 1);  // a new instance starts at the defaults
  REQUIRE(f.store.set_assignment("bloom#2.threshold=5", &error));
  REQUIRE(f.store.set_assignment("bloom#2.mode=gaussian", &error));
  CHECK(threshold(f.store, "bloom") == 3);
  CHECK(threshold(f.store, "bloom#2") == 5);
  CHECK(f.store.values("bloom", 2) == f.store.values("bloom#2"));
  CHECK(f.store.get_text("bloom.mode") == "chain");
  CHECK(f.store.get_text("bloom#2.mode") == "gaussian");
  CHECK(f.store.descriptor("bloom#2", "mode") == &f.params[2]);

  pfx_value value{};
  value.v[0] = 8;
  REQUIRE(f.store.set_value("bloom#2", "levels", value, &error));
  CHECK(f.store.get_text("bloom#2.levels") == "8");
  CHECK(f.store.get_text("bloom.levels") == "6");
  f.store.reset("bloom#2", "levels");
  CHECK(f.store.get_text("bloom#2.levels") == "6");

  CHECK(pfx::host::ParamStore::instance_name("bloom", 1) == "bloom");
  CHECK(pfx::host::ParamStore::instance_name("bloom", 3) == "bloom#3");
}

TEST_CASE("an instance that does not exist is refused, naming the key and the count", "[params][instances][errors]") {
  ParamFixture f;
  REQUIRE(f.store.set_instance_count("bloom", 2));
  const std::string before = f.store.to_text();
  std::string error;
  CHECK_FALSE(f.store.set_assignment("bloom#3.threshold=2", &error));
  CHECK(error == "'bloom#3.threshold': there is no bloom#3, effect 'bloom' has 2 instances");
  CHECK_FALSE(f.store.set_assignment("bloom#0.threshold=2", &error));
  CHECK(error == "'bloom#0.threshold': instances are numbered from 1 (effect 'bloom' has 2 instances)");
  CHECK_FALSE(f.store.set_assignment("bloom#x.threshold=2", &error));
  CHECK(error == "'bloom#x.threshold': 'x' is not an instance number (effect 'bloom' has 2 instances, bloom#1 "
                 "to bloom#2)");
  CHECK_FALSE(f.store.set_assignment("bloom#.threshold=2", &error));
  CHECK(error.find("'' is not an instance number") != std::string::npos);
  CHECK_FALSE(f.store.set_assignment("bloom#99999999999999999999.threshold=2", &error));
  CHECK(error.find("there is no bloom#99999999999999999999, effect 'bloom' has 2 instances") != std::string::npos);
  CHECK_FALSE(f.store.set_assignment("glare#2.threshold=2", &error));
  CHECK(error == "unknown effect 'glare' in 'glare#2.threshold'");
  CHECK(f.store.values("bloom#3") == nullptr);
  CHECK(f.store.values("bloom", 3) == nullptr);
  CHECK(f.store.values("bloom", 0) == nullptr);
  CHECK(f.store.get_text("bloom#3.threshold").empty());

  REQUIRE(f.store.set_instance_count("bloom", 1));
  CHECK_FALSE(f.store.set_assignment("bloom#2.threshold=2", &error));
  CHECK(error == "'bloom#2.threshold': there is no bloom#2, effect 'bloom' has 1 instance");

  // All or nothing, as before: a bad instance anywhere in a file changes nothing.
  REQUIRE(f.store.set_instance_count("bloom", 2));
  CHECK_FALSE(f.store.from_text("bloom#2.threshold=7\nbloom#3.threshold=7\n", &error));
  CHECK(error == "line 2: 'bloom#3.threshold': there is no bloom#3, effect 'bloom' has 2 instances");
  CHECK_FALSE(f.store.from_json(R"({"bloom#2": {"threshold": 7}, "bloom#3": {}})", &error));
  CHECK(error == "'bloom#3': there is no bloom#3, effect 'bloom' has 2 instances");
  CHECK_FALSE(f.store.from_json(R"({"bloom": {"threshold": 7}, "bloom#1": {"threshold": 8}})", &error));
  CHECK(error == "'bloom' and 'bloom#1' name the same instance");
  CHECK(f.store.to_text() == before);
}

TEST_CASE("text and JSON name the first instance plainly and round-trip two instances", "[params][instances]") {
  ParamFixture f;
  std::string error;
  const std::string single_text = f.store.to_text(), single_json = f.store.to_json();
  CHECK(single_text.find('#') == std::string::npos);  // one instance: exactly today's form
  CHECK(nlohmann::json::parse(single_json).size() == 1);

  REQUIRE(f.store.set_instance_count("bloom", 2));
  REQUIRE(f.store.set_assignment("bloom.threshold=0.1", &error));
  REQUIRE(f.store.set_assignment("bloom#2.threshold=40", &error));
  REQUIRE(f.store.set_assignment("bloom#2.tint=0.5,0.25,2", &error));
  const std::string text = f.store.to_text();
  CHECK(text.find("bloom.threshold=0.1\n") != std::string::npos);
  CHECK(text.find("bloom#2.threshold=40\n") != std::string::npos);
  CHECK(text.find("bloom#2.tint=0.5,0.25,2\n") != std::string::npos);
  CHECK(text.find("bloom#1.") == std::string::npos);
  const auto json = nlohmann::json::parse(f.store.to_json());
  CHECK(json["bloom"]["threshold"] == 0.1);
  CHECK(json["bloom#2"]["threshold"] == 40);
  CHECK(json["bloom#2"]["tint"] == nlohmann::json::parse("[0.5, 0.25, 2]"));

  // Into stores holding two instances at their defaults: every value of both comes back.
  ParamFixture from_text, from_json;
  for (ParamFixture* g : {&from_text, &from_json}) REQUIRE(g->store.set_instance_count("bloom", 2));
  REQUIRE(from_text.store.from_text(text, &error));
  REQUIRE(from_json.store.from_json(f.store.to_json(), &error));
  for (size_t n = 1; n <= 2; ++n)
    for (int i = 0; i < 6; ++i)
      for (int c = 0; c < 4; ++c) {
        CHECK(from_text.store.values("bloom", n)[i].v[c] == f.store.values("bloom", n)[i].v[c]);
        CHECK(from_json.store.values("bloom", n)[i].v[c] == f.store.values("bloom", n)[i].v[c]);
      }
  // A store with one instance refuses the second's values rather than dropping them.
  ParamFixture one;
  CHECK_FALSE(one.store.from_json(f.store.to_json(), &error));
  CHECK(error == "'bloom#2': there is no bloom#2, effect 'bloom' has 1 instance");
}

TEST_CASE("a store without a chain is shaped by set_instance_count, never below one instance",
          "[params][instances]") {
  ParamFixture f;
  std::string error;
  REQUIRE(f.store.set_instance_count("bloom", 3));
  for (int n = 1; n <= 3; ++n)
    REQUIRE(f.store.set_assignment("bloom#" + std::to_string(n) + ".threshold=" + std::to_string(10 * n), &error));
  // Dropping the last blocks keeps the first ones' values; growing again starts at the defaults.
  REQUIRE(f.store.set_instance_count("bloom", 2));
  CHECK(threshold(f.store, "bloom") == 10);
  CHECK(threshold(f.store, "bloom#2") == 20);
  CHECK_FALSE(f.store.set_assignment("bloom#3.threshold=1", &error));
  REQUIRE(f.store.set_instance_count("bloom", 3));
  CHECK(threshold(f.store, "bloom#3") == 1);
  CHECK_FALSE(f.store.set_instance_count("bloom", 0));
  CHECK_FALSE(f.store.set_instance_count("glare", 2));
  CHECK(f.store.instance_count("bloom") == 3);
  // No chain holds the effect: it may be forgotten.
  CHECK(f.store.remove_effect("bloom"));
  CHECK_FALSE(f.store.has_effect("bloom"));
}

TEST_CASE("a reloaded effect keeps the values of every instance", "[params][instances]") {
  ParamFixture f;
  std::string error;
  REQUIRE(f.store.set_instance_count("bloom", 2));
  REQUIRE(f.store.set_assignment("bloom.threshold=7", &error));
  REQUIRE(f.store.set_assignment("bloom#2.threshold=9", &error));
  pfx_param_desc reloaded[1] = {pfx::test::make_param("threshold", PFX_PARAM_FLOAT, 0, 100, 1)};
  pfx_effect_desc effect{};
  effect.struct_size = sizeof effect;
  effect.id = "bloom";
  effect.params = reloaded;
  effect.param_count = 1;
  f.store.add_effect(&effect);
  CHECK(f.store.instance_count("bloom") == 2);
  CHECK(threshold(f.store, "bloom") == 7);
  CHECK(threshold(f.store, "bloom#2") == 9);
}

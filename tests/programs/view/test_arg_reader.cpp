// host/lib/common's ArgReader, which every program's option parser walks its arguments with.
#include <catch2/catch.hpp>

#include "arg_reader.hpp"

using pfx::app::ArgReader;

TEST_CASE("ArgReader hands out each argument and the value after an option", "[common][args]") {
  const std::vector<std::string> list = {"--out", "a.exr", "--set", "x.y=1", "--set", "x.z=2", "file"};
  std::string error, out;
  std::vector<std::string> sets, rest;
  ArgReader args(list, &error);
  while (args.next()) {
    const std::string& arg = args.arg();
    if (arg == "--out") REQUIRE(args.value(&out));
    else if (arg == "--set") REQUIRE(args.value(&sets));
    else rest.push_back(arg);
    CHECK(arg == list[&arg - list.data()]);  // still the option itself after its value was taken
  }
  CHECK(out == "a.exr");
  CHECK(sets == std::vector<std::string>{"x.y=1", "x.z=2"});
  CHECK(rest == std::vector<std::string>{"file"});
  CHECK(error.empty());
}

TEST_CASE("ArgReader says which option lacks its value and which option is unknown", "[common][args]") {
  std::string error, value;
  {
    const std::vector<std::string> list = {"--json", "--out"};
    ArgReader args(list, &error);
    REQUIRE(args.next());
    REQUIRE(args.next());
    CHECK_FALSE(args.value(&value));
    CHECK(error == "--out needs a value");
    CHECK_FALSE(args.next());  // the option without a value was the last argument
  }
  {
    const std::vector<std::string> list = {"--frobnicate"};
    ArgReader args(list, &error);
    REQUIRE(args.next());
    CHECK_FALSE(args.unknown());
    CHECK(error == "unknown option '--frobnicate' (see --help)");
  }
  {
    const std::vector<std::string> list;
    ArgReader args(list, &error);
    CHECK_FALSE(args.next());  // no arguments: nothing to walk
  }
}

// pfx-validate's command line and how folders become plugin files.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "validate_options.hpp"

using pfx::validate::expand_plugin_paths;
using pfx::validate::parse_validate_options;
using pfx::validate::ValidateOptions;

namespace fs = std::filesystem;

TEST_CASE("options: defaults, seed, runs, timeout, json", "[validate][options]") {
  ValidateOptions o;
  std::string error;
  REQUIRE(parse_validate_options({"a.so"}, &o, &error));
  CHECK(o.seed == 1);
  CHECK(o.runs == 8);
  CHECK(o.paths == std::vector<std::string>{"a.so"});
  REQUIRE(parse_validate_options({"--seed", "18446744073709551615", "--runs", "0", "--json", "--timeout", "2.5", "a.so",
                                  "b"}, &o, &error));
  CHECK(o.seed == 18446744073709551615ull);
  CHECK(o.runs == 0);
  CHECK(o.json);
  CHECK(o.timeout_s == 2.5);
  CHECK(o.paths == std::vector<std::string>{"a.so", "b"});
}

TEST_CASE("options: every usage error names the option", "[validate][options]") {
  ValidateOptions o;
  std::string error;
  CHECK_FALSE(parse_validate_options({}, &o, &error));
  CHECK(error == "no plugin given");
  CHECK_FALSE(parse_validate_options({"a.so", "--seed", "-1"}, &o, &error));
  CHECK(error.rfind("--seed -1:", 0) == 0);
  CHECK_FALSE(parse_validate_options({"a.so", "--seed", "18446744073709551616"}, &o, &error));
  CHECK(error.rfind("--seed", 0) == 0);
  CHECK_FALSE(parse_validate_options({"a.so", "--runs", "10001"}, &o, &error));
  CHECK(error == "--runs 10001: expected 0 to 10000");
  CHECK_FALSE(parse_validate_options({"a.so", "--timeout", "nan"}, &o, &error));
  CHECK(error.rfind("--timeout nan:", 0) == 0);
  CHECK_FALSE(parse_validate_options({"a.so", "--runs"}, &o, &error));
  CHECK(error == "--runs needs a value");
  CHECK_FALSE(parse_validate_options({"a.so", "--frobnicate"}, &o, &error));
  CHECK(error == "unknown option '--frobnicate' (see --help)");
  CHECK(parse_validate_options({"--help"}, &o, &error));
  CHECK(o.help);
}

TEST_CASE("a folder means its *.so files in name order, an empty or missing one is an error", "[validate][options]") {
  const fs::path dir = fs::temp_directory_path() / ("pfx-validate-options-" + std::to_string(::getpid()));
  fs::create_directories(dir / "empty");
  for (const char* name : {"b.so", "a.so", "notes.txt"}) std::ofstream(dir / name) << "x";
  std::vector<std::string> files;
  std::string error;
  REQUIRE(expand_plugin_paths({dir.string(), (dir / "notes.txt").string()}, &files, &error));
  CHECK(files == std::vector<std::string>{(dir / "a.so").string(), (dir / "b.so").string(), (dir / "notes.txt").string()});
  CHECK_FALSE(expand_plugin_paths({(dir / "empty").string()}, &files, &error));
  CHECK(error == (dir / "empty").string() + ": no plugin (*.so) in this folder");
  CHECK_FALSE(expand_plugin_paths({(dir / "missing.so").string()}, &files, &error));
  CHECK(error == (dir / "missing.so").string() + ": no such file or folder");
  fs::remove_all(dir);
}

// Decimals as exporters write them, read as the C library's strtod reads them, rounded to float.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "obj_test_support.hpp"

using pfx_obj_test::import_text;

namespace {

float strtod_float(const std::string& token) { return static_cast<float>(std::strtod(token.c_str(), nullptr)); }

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("obj decimals: random plain decimals read as strtod reads them", "[objimport][numbers]") {
  std::mt19937_64 random(2024);
  auto digits = [&](int n) {
    std::string d;
    for (int i = 0; i < n; ++i) d += static_cast<char>('0' + random() % 10);
    return d;
  };
  // [+-] digits [. digits]: 0 to 10 integer digits, 0 to 12 after the point, now and then over 19
  // digits (past the quick path of the reader, read exactly).
  auto number = [&] {
    const char* signs[] = {"", "", "-", "+"};
    std::string text = signs[random() % 4];
    const int whole = static_cast<int>(random() % 11), fraction = static_cast<int>(random() % 13);
    text += digits(whole);
    if (fraction > 0 || random() % 4 == 0) text += "." + digits(fraction);
    if (whole == 0 && fraction == 0) text += "0";
    return text;
  };
  std::string text;
  std::vector<std::string> tokens;
  const int vertices = 30000;
  for (int i = 0; i < vertices; ++i) {
    text += "v";
    for (int k = 0; k < 3; ++k) {
      tokens.push_back(number());
      text += (random() % 8 == 0 ? "\t" : " ") + tokens.back();
    }
    text += random() % 10 == 0 ? "  \n" : "\n";
  }
  for (int i = 0; i < vertices; i += 3)
    text += "f " + std::to_string(i + 1) + " " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";

  auto imported = import_text(text);
  REQUIRE(imported.ok);
  REQUIRE(imported.mesh.positions.size() == tokens.size());  // each v used once, in file order
  for (size_t i = 0; i < tokens.size(); ++i) {
    INFO(tokens[i]);
    REQUIRE(same_bits(imported.mesh.positions[i], strtod_float(tokens[i])));
  }
}

// The fast readers for plain lines (obj_plain_lines.hpp) against the general grammar: the same
// text imported with and without them gives the same bytes, the same warnings and the same errors;
// and the numbers they read equal the C library's strtod rounded to float.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "obj_test_support.hpp"

using pfx_obj_test::check_same;
using pfx_obj_test::import_text;

namespace {

// Text after the lines under test, so that they lie before the readers' margin at the chunk's end.
const std::string kTail = "\n# " + std::string(200, '-') + "\n";

void check_both_ways(const std::string& text, unsigned threads = 1, size_t chunk_bytes = 0) {
  auto plain = import_text(text, threads, chunk_bytes, "", true);
  auto general = import_text(text, threads, chunk_bytes, "", false);
  REQUIRE(plain.ok == general.ok);
  CHECK(plain.error == general.error);
  if (plain.ok) check_same(plain.mesh, general.mesh);
}

float strtod_float(const std::string& token) { return static_cast<float>(std::strtod(token.c_str(), nullptr)); }

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("obj plain lines: the fast readers give what the general grammar gives", "[objimport][plain]") {
  const std::string text = pfx_obj_test::varied_file(20000, 7);
  check_both_ways(text);
  check_both_ways(text, 3, 4096);
  check_both_ways(text, 2, 97);  // chunks shorter than the readers' margin: the general grammar only
}

TEST_CASE("obj plain lines: random plain decimals read as strtod reads them", "[objimport][plain]") {
  std::mt19937_64 random(2024);
  auto digits = [&](int n) {
    std::string d;
    for (int i = 0; i < n; ++i) d += static_cast<char>('0' + random() % 10);
    return d;
  };
  // [+-] digits [. digits]: 0 to 10 integer digits, 0 to 12 after the point, now and then over the
  // readers' 19 digits (the general grammar then reads it).
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
  text += kTail;

  auto imported = import_text(text);
  REQUIRE(imported.ok);
  REQUIRE(imported.mesh.positions.size() == tokens.size());  // each v used once, in file order
  for (size_t i = 0; i < tokens.size(); ++i) {
    INFO(tokens[i]);
    REQUIRE(same_bits(imported.mesh.positions[i], strtod_float(tokens[i])));
  }
  check_both_ways(text);
}

TEST_CASE("obj plain lines: forms the fast readers leave to the general grammar", "[objimport][plain]") {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 1\nvn 0 0 1\n";
  for (const char* lines : {
           "v 1e-5 2 3\nf 1 2 5\n", "v 1 2 3 # comment\nf 1 2 5\n", "f 1 2 3 # comment\n", "f -4 -3 -2\n",
           "f 1/1/1 2/2/1 3//1 4/1\n", "v\t1\t2\t3\t\nf 1 2 5\n", "v 1 2 \\\n 3\nf 1 2 5\n", "f 1 2 \\\n3\n",
           "v 1 2 3\r\nf 1 2 5\r\n", "v 1 2 3\rf 1 2 5\r", "v 0000000000000000000001.5 1 1\nf 1 2 5\n",
           "v 12345678901234567890 1 1\nf 1 2 5\n", "v 1234567890123456789 1 1\nf 1 2 5\n",
           "v 18446744073709551617 .18446744073709551617 1\nf 1 2 5\n",  // 2^64 + 1: 20 digits wrap in 64 bits
           "v 1 2 3 0.5 0.25 1\nf 1 2 5\n",
           "v 1 2 3 4\nf 1 2 5\n", "vt 0.5\nf 1/3 2/3 3/3\n", "vt 0.5 0.5 0.5\nf 1/3 2/3 3/3\n", "f 1 2 3 4 1 2\n",
           "f 0000000001 2 3\n", "f 1234567890 2 3\n", "f +1 2 3\n", "s off\nf 1 2 3\n", "\n\n  \nf 1 2 3\n",
           // malformed: the general grammar's messages, either way
           "v 1.2.3 0 0\n", "v 1 2\n", "v 1 2 3 4 5\n", "vt\n", "vn 1 2\n", "vn 1 2 3 4\n", "v nan 0 0\n",
           "v 1e39 0 0\n", "f 1 2\n", "f 1 2 0\n", "f 1 2 9\n", "f 1/9 2 3\n", "f 1//9 2 3\n", "f 1/ 2 3\n",
           "f 1//2//3 2 3\n", "f 4?1 2 3\n", "f 1 2 3x\n", "v 1 2 3x\n", "v 1 - 3\n", "v . 2 3\n", "f 1 2 3\x01\n"}) {
    INFO(lines);
    check_both_ways(vertices + lines + kTail);
  }
}

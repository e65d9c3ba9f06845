// Number parsing: every form the issue names, against the C library's strtod (rounded to float the
// same way: decimal -> double -> float), and the forms that must be refused.
#include <catch2/catch.hpp>

#include <clocale>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "obj_text.hpp"

using pfx_obj::parse_float;

namespace {

float reference(const std::string& text) { return static_cast<float>(std::strtod(text.c_str(), nullptr)); }

}  // namespace

TEST_CASE("obj numbers: the forms .5, 1., +1, 1e-5 and -0 read as strtod reads them", "[objimport][numbers]") {
  for (const char* text : {".5", "1.", "+1", "1e-5", "-0", "0", "-.25", "+.75e1", "1E5", "1e+5", "123456789",
                           "0.000001", "3.14159265358979323846", "-2.5e-3", "007", "1.5e38", "1e-40"}) {
    float value = 0;
    INFO(text);
    REQUIRE(parse_float(text, &value));
    CHECK(value == reference(text));
    CHECK(std::signbit(value) == std::signbit(reference(text)));
  }
  float zero = 1;
  REQUIRE(parse_float("-0", &zero));
  CHECK(zero == 0.0f);
  CHECK(std::signbit(zero));
}

TEST_CASE("obj numbers: long mantissas and extreme exponents take the exact path", "[objimport][numbers]") {
  for (const char* text : {"1.00000000000000000000000001", "123456789012345678901234567890", "1e308", "1e-320",
                           "0.0000000000000000000000000000000000001", "9007199254740993", "1e23", "4.9e-324"}) {
    double value = 0;
    INFO(text);
    REQUIRE(pfx_obj::parse_double(text, &value));
    CHECK(value == std::strtod(text, nullptr));
  }
}

TEST_CASE("obj numbers: random decimals agree with strtod bit for bit", "[objimport][numbers]") {
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> mantissa(-1000.0, 1000.0);
  std::uniform_int_distribution<int> digits(0, 12), exponent(-30, 30);
  char text[64];
  for (int i = 0; i < 20000; ++i) {
    const double m = mantissa(random);
    const int e = exponent(random);
    if (i % 2) std::snprintf(text, sizeof text, "%.*f", digits(random), m);
    else std::snprintf(text, sizeof text, "%.*fe%d", digits(random), m, e);
    float value = 0;
    INFO(text);
    REQUIRE(parse_float(text, &value));
    REQUIRE(value == reference(text));
  }
}

TEST_CASE("obj numbers: malformed forms are refused", "[objimport][numbers]") {
  for (const char* text : {"", "+", "-", ".", "e5", "1e", "1e+", "1.2.3", "1,5", "0x10", "1f", "--1", "+-1", "nan",
                           "inf", "-inf", "infinity", "1 2", "1/2", "abc", "1e5.5"}) {
    float value = 42;
    INFO(text);
    CHECK_FALSE(parse_float(text, &value));
    CHECK(value == 42);
  }
  CHECK(pfx_obj::is_non_finite_word("NaN"));
  CHECK(pfx_obj::is_non_finite_word("-Inf"));
  CHECK(pfx_obj::is_non_finite_word("+infinity"));
  CHECK_FALSE(pfx_obj::is_non_finite_word("1"));
}

TEST_CASE("obj numbers: a decimal-comma locale changes nothing", "[objimport][numbers]") {
  // Some hosts set LC_NUMERIC; the OBJ decimal point is always '.'.
  const char* previous = std::setlocale(LC_NUMERIC, nullptr);
  std::string saved = previous ? previous : "C";
  std::setlocale(LC_NUMERIC, "de_DE.UTF-8");
  float value = 0;
  CHECK(parse_float("1.5", &value));
  CHECK(value == 1.5f);
  CHECK(parse_float("1.00000000000000000000000001", &value));
  CHECK(value == 1.0f);
  std::setlocale(LC_NUMERIC, saved.c_str());
}

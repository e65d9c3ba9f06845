// The lexer and literal values: every literal form FX shaders write, operators by longest match,
// locations through tabs and continuations.
#include <catch2/catch.hpp>

#include "fx_test_support.hpp"
#include "lexer.hpp"
#include "literals.hpp"

using namespace pfx::fx;

namespace {

TokenList lex(const std::string& text, std::string* errors = nullptr) {
  FileNames names;
  names.add("t.fx");
  Diagnostics diagnostics(names);
  TokenList tokens = lex_all(text, 0, diagnostics);
  if (errors) *errors = diagnostics.format_all();
  return tokens;
}

std::string texts(const TokenList& tokens) {
  std::string out;
  for (const Token& t : tokens) out += (out.empty() ? "" : "|") + t.text;
  return out;
}

NumberLiteral number(const std::string& spelling) {
  std::string error;
  auto literal = parse_number(spelling, error);
  INFO(spelling << ": " << error);
  REQUIRE(literal);
  return *literal;
}

std::string number_error(const std::string& spelling) {
  std::string error;
  CHECK_FALSE(parse_number(spelling, error));
  return error;
}

}  // namespace

TEST_CASE("integer literals: decimal, hex, octal, suffixes", "[fx][lexer]") {
  CHECK(number("42").integer == 42);
  CHECK(number("42").kind == NumberLiteral::Kind::kInt);
  CHECK(number("0x1F").integer == 31);
  CHECK(number("0XfF").integer == 255);
  CHECK(number("017").integer == 15);
  CHECK(number("0").integer == 0);
  CHECK(number("10u").kind == NumberLiteral::Kind::kUint);
  CHECK(number("10U").integer == 10);
  CHECK(number("0xFFFFFFFFu").integer == 0xFFFFFFFFu);
  CHECK(number("7l").kind == NumberLiteral::Kind::kInt);
  CHECK(number("7ul").kind == NumberLiteral::Kind::kUint);
  CHECK(number_error("08") == "invalid digit '8' in integer literal '08'");
  CHECK(number_error("0x") == "invalid integer literal '0x'");
  CHECK(number_error("4294967296") == "integer literal '4294967296' does not fit in 32 bits");
  CHECK(number_error("12abc") == "invalid digit 'a' in integer literal '12abc'");
}

TEST_CASE("float literals: dots, exponents, suffixes", "[fx][lexer]") {
  CHECK(number("1.5f").real == 1.5);
  CHECK(number("1.5f").kind == NumberLiteral::Kind::kFloat);
  CHECK(number("1.").real == 1.0);
  CHECK(number(".5").real == 0.5);
  CHECK(number("1e3").real == 1000.0);
  CHECK(number("2.5e-2").real == Approx(0.025));
  CHECK(number("3E+1F").real == 30.0);
  CHECK(number("0.5h").kind == NumberLiteral::Kind::kHalf);
  CHECK(number("0.5H").real == 0.5);
  CHECK(number("1.0L").kind == NumberLiteral::Kind::kDouble);
  CHECK(number("1f").real == 1.0);  // an f suffix makes an integer spelling a float
  CHECK(number_error("1e") == "invalid floating-point literal '1e'");
  CHECK(number_error("1.2.3") == "invalid floating-point literal '1.2.3'");
}

TEST_CASE("numbers lex as one token, signs in exponents included", "[fx][lexer]") {
  CHECK(texts(lex("1e-3+2 0x1e+1 .5f 1.xxx")) == "1e-3|+|2|0x1e|+|1|.5f|1.xxx");
}

TEST_CASE("strings: escapes and adjacent literals joined", "[fx][lexer]") {
  std::string error;
  CHECK(unescape_string("\"a\\0b\\n\\t\\\\\\\"\"", error) == std::string("a\0b\n\t\\\"", 7));
  CHECK(unescape_string("\"\\x41\\101\"", error) == "AA");
  CHECK(error.empty());
  // An escape ReShade does not know keeps its character, as combo lists write "Color\0\HSV".
  CHECK(unescape_string("\"Color\\0\\HSV: Hue\\0\"", error) == std::string("Color\0HSV: Hue\0", 15));
  CHECK(error.empty());
  // The parser joins adjacent strings, as in ui_items lists split over lines.
  CHECK(pfx::fx::test::parse_to_text("uniform int C < ui_items = \"One\\0\"\n \"Two\\0\"; > = 0;") ==
        "(var uniform int C (@ ui_items \"One\\0Two\\0\") 0)\n");
}

TEST_CASE("operators by longest match", "[fx][lexer]") {
  CHECK(texts(lex("a+++b<<=c>>=d::e...f!=g&&h||i->j")) == "a|++|+|b|<<=|c|>>=|d|::|e|...|f|!=|g|&&|h||||i|-|>|j");
  CHECK(texts(lex("{}[]();,.:?%^~#")) == "{|}|[|]|(|)|;|,|.|:|?|%|^|~|#");
  TokenList unknown = lex("a @ b");
  REQUIRE(unknown.size() == 3);
  CHECK(unknown[1].kind == TokenKind::kUnknown);
}

TEST_CASE("token locations: lines, columns, tabs, continuations, comments", "[fx][lexer]") {
  TokenList tokens = lex("a\n\tbb /* c\n c */ d // e\nf\\\ng h");
  REQUIRE(tokens.size() == 5);
  CHECK(tokens[1].text == "bb");
  CHECK(tokens[1].location.line == 2);
  CHECK(tokens[1].location.column == 2);
  CHECK(tokens[2].text == "d");
  CHECK(tokens[2].location.line == 3);
  CHECK(tokens[2].location.column == 7);
  CHECK(tokens[3].text == "fg");  // a backslash-newline joins the identifier
  CHECK(tokens[3].location.line == 4);
  CHECK(tokens[4].location.line == 5);
  CHECK(tokens[4].location.column == 3);
}

TEST_CASE("unterminated comments and strings are errors, not hangs", "[fx][lexer]") {
  std::string errors;
  lex("a /* never closed", &errors);
  CHECK(errors == "t.fx:1:3: error: unterminated comment\n");
  lex("x = \"no end\ny", &errors);
  CHECK(errors == "t.fx:1:5: error: unterminated string literal\n");
  CHECK(lex("\xEF\xBB\xBFx").at(0).location.column == 1);  // a byte order mark is not a column
}

// Bad FX: every error names file:line:column, and hostile input (deep nesting, long chains,
// unterminated text) ends in an error, never a crash, a hang or a stack overflow.
#include <catch2/catch.hpp>

#include "fx_test_support.hpp"

using pfx::fx::test::errors_of;

namespace {

std::string syntax_errors(const std::string& source) { return errors_of(source, false); }

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

}  // namespace

TEST_CASE("syntax errors give the exact file:line:column", "[fx][bad]") {
  CHECK(syntax_errors("float a = 1\nfloat b;") == "main.fx:2:1: error: expected ';' after a declaration, found 'float'\n");
  CHECK(syntax_errors("void f() {\n  x = ;\n}") == "main.fx:2:7: error: expected an expression, found ';'\n");
  CHECK(syntax_errors("void f() {\n  if (a { }\n}") == "main.fx:2:9: error: expected ')' after the condition, found '{'\n");
  CHECK(syntax_errors("float a = 08;") == "main.fx:1:11: error: invalid digit '8' in integer literal '08'\n");
  CHECK(syntax_errors("float a = 1 @ 2;") == "main.fx:1:13: error: unexpected character '@'\n");
  CHECK(syntax_errors("technique T { pas P {} }") == "main.fx:1:15: error: expected 'pass' or '}', found 'pas'\n");
  CHECK(syntax_errors("technique T { pass P { PixelShader PS; } }") ==
        "main.fx:1:36: error: expected '=' after a state name, found 'PS'\n");
  CHECK(syntax_errors("uniform float a < ui_min = 0.0 > = 1;") ==
        "main.fx:1:32: error: expected ';' after an annotation, found '>'\n");
  CHECK(syntax_errors("void f() {") == "main.fx:1:10: error: '{' is never closed\n");
  CHECK(syntax_errors("struct S { float x; }") == "main.fx:1:22: error: expected ';' after a struct, found end of file\n");
  CHECK(syntax_errors("void f() { switch (a) { x = 1; } }") ==
        "main.fx:1:25: error: expected 'case' or 'default', found 'x'\n");
  CHECK(syntax_errors("void f() { do x(); until (a); }") ==
        "main.fx:1:20: error: expected 'while' after the body of 'do', found 'until'\n");
  CHECK(syntax_errors("float2 v = vector<float, 5>(1);") == "main.fx:1:26: error: expected a size from 1 to 4, found '5'\n");
}

TEST_CASE("the parser recovers and reports later errors too", "[fx][bad]") {
  CHECK(syntax_errors("void f() {\n  x = ;\n  y = ;\n}\nfloat ok;") ==
        "main.fx:2:7: error: expected an expression, found ';'\n"
        "main.fx:3:7: error: expected an expression, found ';'\n");
}

TEST_CASE("unterminated comments and strings", "[fx][bad]") {
  CHECK(syntax_errors("float a; /* never\nclosed") == "main.fx:1:10: error: unterminated comment\n");
  CHECK(first_line(syntax_errors("uniform float a < ui_label = \"oops; > = 1;")) ==
        "main.fx:1:30: error: unterminated string literal");
}

TEST_CASE("10,000 nested parentheses give an error, not a stack overflow", "[fx][bad][limits]") {
  std::string source = "float a = " + std::string(10000, '(') + "1" + std::string(10000, ')') + ";";
  CHECK(first_line(syntax_errors(source)).find("error: nesting deeper than 256 levels") != std::string::npos);
  std::string unary = "float b = " + std::string(10000, '-') + "1;";
  CHECK(first_line(syntax_errors(unary)).find("error: nesting deeper than 256 levels") != std::string::npos);
  std::string blocks = "void f() " + std::string(10000, '{') + std::string(10000, '}');
  CHECK(first_line(syntax_errors(blocks)).find("error: nesting deeper than 256 levels") != std::string::npos);
  std::string lists = "static const float c[1] = " + std::string(10000, '{') + "1" + std::string(10000, '}') + ";";
  CHECK(first_line(syntax_errors(lists)).find("error: nesting deeper than 256 levels") != std::string::npos);
  std::string ifs = "void f() { ";
  for (int i = 0; i < 10000; ++i) ifs += "if (a) ";
  CHECK(first_line(syntax_errors(ifs + "x(); }")).find("error: nesting deeper than 256 levels") != std::string::npos);
  std::string namespaces;
  for (int i = 0; i < 10000; ++i) namespaces += "namespace n {";
  CHECK(first_line(syntax_errors(namespaces)).find("error: nesting deeper than 256 levels") != std::string::npos);
}

TEST_CASE("long operator chains are bounded", "[fx][bad][limits]") {
  std::string sum = "float a = 1";
  for (int i = 0; i < 10000; ++i) sum += " + 1";
  CHECK(first_line(syntax_errors(sum + ";")) == "main.fx:1:4109: error: more than 1024 operators in a row");
  std::string index = "void f() { x = a";
  for (int i = 0; i < 10000; ++i) index += "[0]";
  CHECK(first_line(syntax_errors(index + "; }")).find("error: more than 1024 operators in a row") != std::string::npos);
  // A long chain that stays under the limit is fine.
  std::string fine = "float a = 1";
  for (int i = 0; i < 1000; ++i) fine += " + 1";
  CHECK(syntax_errors(fine + ";").empty());
  CHECK(errors_of(fine + ";").empty());  // semantic analysis walks it too
}

TEST_CASE("garbage never crashes or hangs the front end", "[fx][bad]") {
  const char* inputs[] = {"}}}}", "{{{{", "))))", "technique", "technique T <", "struct", "namespace {",
                          "float", "float a[", "void f(", "#define", "#if", "\"", "/*", "uniform float a <",
                          "texture2D t {", "sampler s { Texture = ", "float a = {", "[[[[", "::::", "float a = b ? c",
                          "switch", "void f() { for (", "int x = (float)", "\\", "a.b.c.d.", "\x01\x02\xff"};
  for (const char* input : inputs) {
    INFO(input);
    CHECK_FALSE(syntax_errors(input).empty());
  }
}

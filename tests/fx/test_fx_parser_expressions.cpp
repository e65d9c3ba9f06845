// Expressions parse with HLSL's precedence and associativity; trees written by hand.
#include <catch2/catch.hpp>

#include "fx_test_support.hpp"

using pfx::fx::test::expression_tree;

TEST_CASE("binary operators follow HLSL precedence", "[fx][parser]") {
  const std::pair<const char*, const char*> cases[] = {
      {"a = b + c * d", "(= a (+ b (* c d)))"},
      {"a + b - c", "(- (+ a b) c)"},
      {"a / b * c % d", "(% (* (/ a b) c) d)"},
      {"a || b && c", "(|| a (&& b c))"},
      {"a | b ^ c & d", "(| a (^ b (& c d)))"},
      {"a & b == c", "(& a (== b c))"},
      {"a == b < c", "(== a (< b c))"},
      {"a < b << 1", "(< a (<< b 1))"},
      {"a << 1 + 2", "(<< a (+ 1 2))"},
      {"a * (b + c)", "(* a (+ b c))"},
      {"a && b || c && d", "(|| (&& a b) (&& c d))"},
      {"a >= b != c <= d", "(!= (>= a b) (<= c d))"},
      {"a >> 2 > 1", "(> (>> a 2) 1)"},
  };
  for (const auto& [source, tree] : cases) {
    INFO(source);
    CHECK(expression_tree(source) == tree);
  }
}

TEST_CASE("assignment and the conditional operator associate to the right", "[fx][parser]") {
  CHECK(expression_tree("a = b = c") == "(= a (= b c))");
  CHECK(expression_tree("a += b ? c : d") == "(+= a (? b c d))");
  CHECK(expression_tree("a ? b : c ? d : e") == "(? a b (? c d e))");
  CHECK(expression_tree("x = (a, b)") == "(= x (, a b))");
  CHECK(expression_tree("a -= 1, b *= 2") == "(, (-= a 1) (*= b 2))");
  const char* compound[] = {"/=", "%=", "&=", "|=", "^=", "<<=", ">>="};
  for (const char* op : compound) CHECK(expression_tree(std::string("a ") + op + " b") == std::string("(") + op + " a b)");
}

TEST_CASE("unary, cast and postfix operators", "[fx][parser]") {
  CHECK(expression_tree("-a * b") == "(* (- a) b)");
  CHECK(expression_tree("!a.x") == "(! (. a x))");
  CHECK(expression_tree("~a % 3") == "(% (~ a) 3)");
  CHECK(expression_tree("- -a") == "(- (- a))");
  CHECK(expression_tree("+a") == "(+ a)");
  CHECK(expression_tree("(float3)x.y") == "(cast float3 (. x y))");
  CHECK(expression_tree("(float)a + b") == "(+ (cast float a) b)");
  CHECK(expression_tree("(int2)(a * 2)") == "(cast int2 (* a 2))");
  CHECK(expression_tree("a[i].x++") == "(post++ (. ([] a i) x))");
  CHECK(expression_tree("++a[0]") == "(++ ([] a 0))");
  CHECK(expression_tree("--a") == "(-- a)");
  CHECK(expression_tree("a--") == "(post-- a)");
  CHECK(expression_tree("f(a, b)[2]") == "([] (call f a b) 2)");
  CHECK(expression_tree("f()") == "(call f)");
  CHECK(expression_tree("m[1][2]") == "([] ([] m 1) 2)");
}

TEST_CASE("constructors, swizzles, namespaces and literals", "[fx][parser]") {
  CHECK(expression_tree("float4(a, 1.0).rgb") == "(. (float4 a 1.0) rgb)");
  CHECK(expression_tree("vector<float, 3>(1, 2, 3)") == "(float3 1 2 3)");
  CHECK(expression_tree("matrix<float, 2, 2>(1, 2, 3, 4)") == "(float2x2 1 2 3 4)");
  CHECK(expression_tree("float3x2(a)") == "(float3x2 a)");
  CHECK(expression_tree("x.xxx") == "(. x xxx)");
  CHECK(expression_tree("m._m00 + m._11") == "(+ (. m _m00) (. m _11))");
  CHECK(expression_tree("A::B::f(x)") == "(call A::B::f x)");
  CHECK(expression_tree("::g + N::v") == "(+ ::g N::v)");
  CHECK(expression_tree("1.5f + 0x10 + 2u + .5h + true") == "(+ (+ (+ (+ 1.5f 0x10) 2u) .5h) true)");
}

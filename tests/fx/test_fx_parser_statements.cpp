// Every statement form, with attributes; trees written by hand.
#include <catch2/catch.hpp>

#include "fx_test_support.hpp"

using pfx::fx::test::parse_to_text;
using pfx::fx::test::statement_tree;

TEST_CASE("if/else and blocks", "[fx][parser]") {
  CHECK(statement_tree("if (a) b = 1; else { c = 2; }") == "(if a (expr (= b 1)) (block (expr (= c 2))))");
  CHECK(statement_tree("if (a) if (b) x(); else y();") == "(if a (if b (expr (call x)) (expr (call y))))");
  CHECK(statement_tree("[branch] if (a) discard;") == "[branch] (if a (discard))");
  CHECK(statement_tree("[flatten] if (a) {} else {}") == "[flatten] (if a (block) (block))");
  CHECK(statement_tree("{ ; }") == "(block (empty))");
}

TEST_CASE("loops", "[fx][parser]") {
  CHECK(statement_tree("[unroll] for (int i = 0; i < 4; i++) x += i;") ==
        "[unroll] (for (decl (var int i 0)) (< i 4) (post++ i) (expr (+= x i)))");
  CHECK(statement_tree("[unroll(4)] for (i = 0, j = 1; i < 4; ++i, --j) {}") ==
        "([unroll] 4) (for (expr (, (= i 0) (= j 1))) (< i 4) (, (++ i) (-- j)) (block))");
  CHECK(statement_tree("for (;;) break;") == "(for _ _ _ (break))");
  CHECK(statement_tree("[loop] while (true) { continue; }") == "[loop] (while true (block (continue)))");
  CHECK(statement_tree("[fastopt] do x--; while (x > 0);") == "[fastopt] (do (expr (post-- x)) (> x 0))");
}

TEST_CASE("switch, jumps and declarations", "[fx][parser]") {
  CHECK(statement_tree("switch (i) { case 0: case 1: a = 1; break; default: discard; }") ==
        "(switch i (case 0 1 (expr (= a 1)) (break)) (case default (discard)))");
  CHECK(statement_tree("[forcecase] switch (i) { case N::K: { return; } }") ==
        "[forcecase] (switch i (case N::K (block (return))))");
  CHECK(statement_tree("return;") == "(return)");
  CHECK(statement_tree("return a + 1;") == "(return (+ a 1))");
  CHECK(statement_tree("float a = 1, b[2] = {1, 2}, c;") == "(decl (var float a 1) (var float b[2] ({} 1 2)) (var float c))");
  CHECK(statement_tree("static const int k = 3;") == "(decl (var static const int k 3))");
  CHECK(statement_tree("float3x3 m = float3x3(1,0,0, 0,1,0, 0,0,1);") ==
        "(decl (var float3x3 m (float3x3 1 0 0 0 1 0 0 0 1)))");
  CHECK(statement_tree("int2 grid[2][3];") == "(decl (var int2 grid[2][3]))");
  CHECK(statement_tree("float sample = 1, linear = sample;") == "(decl (var float sample 1) (var float linear sample))");
  CHECK(statement_tree("sample = linear * 2;") == "(expr (= sample (* linear 2)))");
}

TEST_CASE("struct-typed locals need the struct's name known", "[fx][parser]") {
  CHECK(parse_to_text("struct S { float x; }; void f() { S s; s.x = 1; N::T t; }") ==
        "(struct S (var float x))\n"
        "(function void f () (block (decl (var S s)) (expr (= (. s x) 1)) (decl (var N::T t))))\n");
}

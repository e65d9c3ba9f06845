// The FX preprocessor: macros, conditionals, includes, directives and predefined macros. Every
// expected text is written by hand from the C preprocessor's rules and REFERENCE.md.
#include <catch2/catch.hpp>

#include "fx_test_support.hpp"

using pfx::fx::test::MemoryFiles;
using pfx::fx::test::preprocess_files;
using pfx::fx::test::preprocess_text;

namespace {

std::string expand(const std::string& source) {
  auto out = preprocess_text(source);
  INFO(out->errors);
  CHECK(out->errors.empty());
  return out->text;
}

}  // namespace

TEST_CASE("object-like and function-like macros expand", "[fx][preprocessor]") {
  CHECK(expand("#define N 3\nint a = N;") == "int a = 3;");
  CHECK(expand("#define ADD(a, b) ((a) + (b))\nx = ADD(1, 2);") == "x = ((1) + (2));");
  CHECK(expand("#define F(a, b) a b\nF(1,\n2)") == "1 2");  // arguments over several lines
  CHECK(expand("#define F(a) [a]\nF((1, 2))") == "[(1, 2)]");  // commas inside parentheses
  CHECK(expand("#define F(x) x\nint F;") == "int F;");         // a function-like name without '('
  CHECK(expand("#define E() 7\nE()") == "7");
  CHECK(expand("#define X 1\n#undef X\nX") == "X");
}

TEST_CASE("stringizing and token pasting", "[fx][preprocessor]") {
  CHECK(expand("#define S(x) #x\nS(a  +  b)") == "\"a + b\"");
  CHECK(expand("#define S(x) #x\nS(\"q\")") == "\"\\\"q\\\"\"");
  CHECK(expand("#define CAT(a, b) a ## b\nCAT(tex, 2D) CAT(1, 5)") == "tex2D 15");
  CHECK(expand("#define CAT(a, b) a ## b\nCAT(, x) CAT(y, )") == "x y");  // empty arguments
  // An argument next to ## is not expanded first.
  CHECK(expand("#define ONE 1\n#define CAT(a, b) a ## b\nCAT(ONE, 2)") == "ONE2");
  CHECK(expand("#define V(fmt, ...) f(fmt, __VA_ARGS__)\nV(1, 2, 3)") == "f(1, 2, 3)");
}

// ReShade's preprocessor, like MSVC's, leaves a paste that gives several valid tokens as those
// tokens: public effects write Tint##id##.rgb, which pastes "Tint1" and ".".
TEST_CASE("a paste that gives several valid tokens keeps them, with a warning", "[fx][preprocessor]") {
  auto tint = preprocess_text("#define GET_TINT(id) Tint##id##.rgb\nGET_TINT(1)");
  CHECK(tint->text == "Tint1.rgb");
  CHECK(tint->errors == "main.fx:2:1: warning: pasting \"Tint1\" and \".\" does not give a valid token: kept as they are\n");
  auto plus = preprocess_text("#define CAT(a, b) a ## b\nCAT(+, /)");
  CHECK(plus->text == "+ /");
  CHECK(plus->errors.find("warning: pasting \"+\" and \"/\"") != std::string::npos);
}

TEST_CASE("a macro never expands inside its own expansion", "[fx][preprocessor]") {
  CHECK(expand("#define foo foo + 1\nfoo") == "foo + 1");
  CHECK(expand("#define a b\n#define b a\na b") == "a b");
  // The C standard's example: the g produced by f's body is not expanded again.
  CHECK(expand("#define f(a) a*g\n#define g(a) f(a)\nf(2)(9)") == "2*9*g");
}

// FX files are untrusted input. A directive inside a macro's argument list is undefined in C; GCC
// runs it and finishes the expansion with the definition it started with, and so does pfx. The
// first case, an effect that #undefs its macro while the macro collects its arguments, once made
// the expander read the freed definition (found by fuzz_fx_compiler; also in its regressions).
TEST_CASE("a directive inside a macro's arguments: the expansion keeps the definition it started with",
          "[fx][preprocessor][hard]") {
  CHECK(expand("#define F(x) x\nF(\n#undef F\n1) F(2)") == "1 F(2)");
  CHECK(expand("#define F(x) [x]\n#define G F(\nG\n#undef F\n1) F(2)") == "[1] F(2)");
  auto redefined = preprocess_text("#define F(x) [x]\nF(\n#define F(x) <x>\n1) F(2)");
  CHECK(redefined->text == "[1] <2>");
  CHECK(redefined->errors == "main.fx:3:9: warning: 'F' redefined\n");  // as GCC warns
  const std::string effect =
      "#define F(x) x\n"
      "float4 PS(float4 p : SV_Position) : SV_Target { return F(\n"
      "#undef F\n"
      "1); }\n"
      "technique T { pass { VertexShader = 0; PixelShader = PS; } }\n";
  CHECK(preprocess_text(effect)->text.find("return 1; }") != std::string::npos);
}

TEST_CASE("#if evaluates integer constant expressions", "[fx][preprocessor]") {
  const std::pair<const char*, bool> cases[] = {
      {"1 + 2 * 3 == 7", true},   {"(1 + 2) * 3 == 9", true}, {"-1 < 0", true},       {"0x10 == 16", true},
      {"010 == 8", true},         {"1 << 4 == 16", true},     {"256 >> 4 == 16", true}, {"7 / 2 == 3", true},
      {"7 % 4 == 3", true},       {"-7 / 2 == -3", true},     {"!0", true},          {"~0 == -1", true},
      {"1 ? 2 : 0", true},        {"0 ? 1 : 0", false},       {"(3 & 5) == 1", true}, {"(3 | 5) == 7", true},
      {"(3 ^ 5) == 6", true},     {"1 && 0", false},          {"0 || 2", true},      {"10u == 10", true},
      {"UNDEFINED_NAME == 0", true}, {"defined(N)", true},    {"defined N && N == 4", true},
      {"!defined(MISSING)", true}, {"N > 3 && N < 5", true},  {"true", true},        {"false", false},
      {"2 >= 2 && 2 <= 2 && 1 != 2", true},
      // Wider than the language's 32 bits, as an application hash in Depth3D's headers is.
      {"0xC19572DDF == 51964751327", true}, {"0xFFFFFFFFF > 0xFFFFFFFF", true},
  };
  for (const auto& [expression, expected] : cases) {
    INFO(expression);
    CHECK(expand(std::string("#define N 4\n#if ") + expression + "\nyes\n#else\nno\n#endif") ==
          (expected ? "yes" : "no"));
  }
}

TEST_CASE("#if exists with a quoted file name: whether a quoted #include would find it", "[fx][preprocessor]") {
  MemoryFiles files;
  files.files["main.fx"] =
      "#define HEADER \"there.fxh\"\n"
      "#if exists \"there.fxh\" && exists(\"there.fxh\") && exists HEADER && !exists \"absent.fxh\"\nyes\n#else\nno\n#endif\n";
  files.files["there.fxh"] = "";
  auto out = preprocess_files(files, "main.fx");
  CHECK(out->errors.empty());
  CHECK(out->text == "yes");
  CHECK(preprocess_text("#if exists absent\n#endif")->errors == "main.fx:1:5: error: 'exists' needs a file name in quotes\n");
}

TEST_CASE("#ifdef, #ifndef, #elif chains and skipped groups", "[fx][preprocessor]") {
  CHECK(expand("#define A\n#ifdef A\na\n#endif\n#ifndef A\nnot_a\n#endif") == "a");
  CHECK(expand("#define V 2\n#if V == 1\none\n#elif V == 2\ntwo\n#elif V == 2\nagain\n#else\nother\n#endif") == "two");
  CHECK(expand("#if 0\n#if 1\nbad\n#else\nbad2\n#endif\n#else\ngood\n#endif") == "good");
  // Inside a skipped group unknown directives and stray quotes are not errors.
  CHECK(expand("#if 0\n#foo bar\nit's prose \"unterminated\n#endif\nok") == "ok");
  CHECK(expand("#ifndef G\n#define G 0\n#endif\n#if G\nx\n#else\ny\n#endif") == "y");
}

TEST_CASE("__LINE__, __FILE__, #line and line continuations", "[fx][preprocessor]") {
  CHECK(expand("a\n__LINE__ __FILE__") == "a 2 \"main.fx\"");
  CHECK(expand("__FILE_NAME__ __FILE_STEM__") == "\"main.fx\" \"main\"");
  CHECK(expand("#line 100 \"other.fx\"\n__LINE__ __FILE__") == "100 \"other.fx\"");
  CHECK(expand("#define LONG 1 + \\\n 2\nLONG __LINE__") == "1 + 2 3");
  CHECK(expand("in\\\nt x;") == "int x;");
  auto out = preprocess_text("#line 50\n#error boom");
  CHECK(out->errors == "main.fx:50:2: error: #error boom\n");
}

TEST_CASE("#error, #warning and #pragma", "[fx][preprocessor]") {
  CHECK(preprocess_text("x\n#error custom message here")->errors == "main.fx:2:2: error: #error custom message here\n");
  auto warned = preprocess_text("#warning careful\nx");
  CHECK(warned->errors == "main.fx:1:2: warning: #warning careful\n");
  CHECK(warned->text == "x");
  auto pragmas = preprocess_text("#pragma reshade skipoptimization\n#pragma once\nx");
  CHECK(pragmas->text == "x");
  REQUIRE(pragmas->source.pragmas.size() == 1);
  CHECK(pfx::fx::spell(pragmas->source.pragmas[0].tokens) == "reshade skipoptimization");
  CHECK(pragmas->source.pragmas[0].location.line == 1);
}

TEST_CASE("the predefined macros come from the caller's options", "[fx][preprocessor]") {
  pfx::fx::PreprocessorOptions options;
  options.buffer_width = 800;
  options.buffer_height = 600;
  options.defines = {{"MY_DEF", "5"}};
  auto out = preprocess_text(
      "BUFFER_WIDTH BUFFER_HEIGHT BUFFER_RCP_WIDTH BUFFER_COLOR_BIT_DEPTH BUFFER_COLOR_SPACE __RENDERER__ "
      "__RESHADE__ __RESHADE_PERFORMANCE_MODE__ __VENDOR__ __DEVICE__ MY_DEF",
      options);
  CHECK(out->errors.empty());
  CHECK(out->text == "800 600 (1.0 / 800) 8 1 83200 60300 0 0 0 5");  // 0x14500 == 83200: OpenGL 4.5
  CHECK(expand("#if __RENDERER__ >= 0x10000 && __RENDERER__ < 0x20000\nopengl\n#endif") == "opengl");
  CHECK(expand("#if __RESHADE__ >= 50000\nnew\n#endif") == "new");
}

TEST_CASE("#include: relative to the including file, then the include folders", "[fx][preprocessor]") {
  MemoryFiles files;
  files.files["shaders/main.fx"] = "#include \"common.fxh\"\n#include \"sub/util.fxh\"\n#include \"ReShade.fxh\"\nmain";
  files.files["shaders/common.fxh"] = "common";
  files.files["shaders/sub/util.fxh"] = "#include \"../common2.fxh\"\nutil __FILE__";
  files.files["shaders/common2.fxh"] = "c2";
  files.files["lib/ReShade.fxh"] = "from_lib";
  files.files["lib/common.fxh"] = "the_include_folder_must_not_win";
  pfx::fx::PreprocessorOptions options;
  options.include_folders = {"lib"};
  auto out = preprocess_files(files, "shaders/main.fx", options);
  CHECK(out->errors.empty());
  CHECK(out->text == "common c2 util \"shaders/sub/util.fxh\" from_lib main");
}

TEST_CASE("#pragma once and include guards", "[fx][preprocessor]") {
  MemoryFiles files;
  files.files["main.fx"] = "#include \"once.fxh\"\n#include \"once.fxh\"\n#include \"guard.fxh\"\n#include \"guard.fxh\"";
  files.files["once.fxh"] = "#pragma once\nA";
  files.files["guard.fxh"] = "#ifndef GUARD\n#define GUARD\nB\n#endif";
  auto out = preprocess_files(files, "main.fx");
  CHECK(out->errors.empty());
  CHECK(out->text == "A B");
}

TEST_CASE("#include errors: cycles, missing files, depth", "[fx][preprocessor]") {
  MemoryFiles files;
  files.files["a.fx"] = "#include \"b.fxh\"\n";
  files.files["b.fxh"] = "#include \"a.fx\"\n";
  CHECK(preprocess_files(files, "a.fx")->errors == "b.fxh:1:2: error: #include cycle: a.fx -> b.fxh -> a.fx\n");
  CHECK(preprocess_text("#include \"missing.fxh\"")->errors ==
        "main.fx:1:2: error: cannot open include file 'missing.fxh'\n");
  // A header another collection ships: the error says which (reshade-shaders' DrawText.fxh,
  // included by FXShaders' Pong.fx).
  CHECK(preprocess_text("#include \"Shaders/drawtext.FXH\"")->errors ==
        "main.fx:1:2: error: cannot open include file 'Shaders/drawtext.FXH': it comes with crosire/reshade-shaders (its "
        "Shaders folder, with Textures/FontAtlas.png); add the folder that holds it to the shader folders\n");
  MemoryFiles chain;
  for (int i = 0; i < 100; ++i)
    chain.files["f" + std::to_string(i) + ".fxh"] = "#include \"f" + std::to_string(i + 1) + ".fxh\"\n";
  chain.files["f100.fxh"] = "end";
  auto deep = preprocess_files(chain, "f0.fxh");
  CHECK(deep->errors == "f63.fxh:1:2: error: #include nested deeper than 64 levels\n");
  CHECK(preprocess_files(files, "nothing.fx")->errors == "nothing.fx:1:1: error: cannot read file 'nothing.fx'\n");
}

TEST_CASE("preprocessor errors name the file, line and column", "[fx][preprocessor]") {
  CHECK(preprocess_text("#define F(a, b) a\nF(1)")->errors ==
        "main.fx:2:1: error: macro 'F' takes 2 argument(s), but 1 were given\n");
  CHECK(preprocess_text("#define F(a) a\nF(1, 2")->errors == "main.fx:2:1: error: unterminated argument list of macro 'F'\n");
  CHECK(preprocess_text("#if 1\nx")->errors == "main.fx:1:2: error: unterminated conditional directive\n");
  CHECK(preprocess_text("#endif")->errors == "main.fx:1:2: error: #endif without #if\n");
  CHECK(preprocess_text("#if 1\n#else\n#else\n#endif")->errors == "main.fx:3:2: error: #else after #else\n");
  CHECK(preprocess_text("#if 10 / 0\n#endif")->errors == "main.fx:1:8: error: division by zero in #if\n");
  CHECK(preprocess_text("#if 1 +\n#endif")->errors == "main.fx:1:2: error: #if expression ends early\n");
  CHECK(preprocess_text("#if 1.5\n#endif")->errors == "main.fx:1:5: error: floating-point literal in #if expression\n");
  CHECK(preprocess_text("#frobnicate")->errors == "main.fx:1:1: error: unknown preprocessor directive '#frobnicate'\n");
  CHECK(preprocess_text("#define S(x) #y")->errors == "main.fx:1:14: error: '#' is not followed by a macro parameter\n");
  CHECK(preprocess_text("#define P(x) ## x")->errors == "main.fx:1:2: error: '##' cannot be at either end of a macro\n");
  // Pasted text that does not lex at all: "/*" opens a comment that never ends.
  CHECK(preprocess_text("#define CAT(a, b) a ## b\nCAT(/, *)")->errors ==
        "main.fx:2:1: error: pasting \"/\" and \"*\" does not give a valid token\n");
}

TEST_CASE("runaway input hits a limit with its own message", "[fx][preprocessor][limits]") {
  std::string nested;
  for (int i = 0; i < 300; ++i) nested += "#if 1\n";
  CHECK(preprocess_text(nested)->errors.find("main.fx:257:2: error: conditional directives nested deeper than 256 levels") == 0);
  std::string skipped;
  for (int i = 0; i < 300; ++i) skipped += "#if 0\n";
  CHECK(preprocess_text(skipped)->errors.find("main.fx:257:2: error: conditional directives nested deeper than 256 levels") == 0);
  // Each macro doubles the one before: 2^40 tokens if nothing stopped it.
  std::string bomb = "#define M0 x x\n";
  for (int i = 1; i <= 40; ++i)
    bomb += "#define M" + std::to_string(i) + " M" + std::to_string(i - 1) + " M" + std::to_string(i - 1) + "\n";
  bomb += "M40";
  auto out = preprocess_text(bomb);
  CHECK(out->errors.find("main.fx:42:1: error: ") == 0);
  CHECK(out->errors.find("tokens") != std::string::npos);
  std::string arguments = "#define F(x) x\n";
  for (int i = 0; i < 10000; ++i) arguments += "F(";
  CHECK_FALSE(preprocess_text(arguments)->errors.empty());
}

// The GLSL form of libretro shaders: a .glsl file read as RetroArch's gl driver compiles it
// (glsl_source.hpp), and what its uniform names stand for (glsl_names.hpp), against RetroArch's
// rules written out by hand here.
#include <catch2/catch.hpp>

#include <sstream>

#include "glsl_names.hpp"
#include "glsl_source.hpp"
#include "memory_files.hpp"

using namespace pfx::libretro;
using pfx::test::MemoryFiles;

namespace {

SlangSource read_glsl_ok(const std::string& text) {
  MemoryFiles files;
  files.texts["/s/pass.glsl"] = text;
  SlangSource source;
  std::string error;
  INFO(error);
  REQUIRE(read_glsl("/s/pass.glsl", files.reader(), &source, &error));
  return source;
}

// The code after `#line 1`, as its lines.
std::vector<std::string> body_lines(const std::string& stage) {
  const std::size_t at = stage.find("#line 1\n");
  REQUIRE(at != std::string::npos);
  std::istringstream lines(stage.substr(at + 8));
  std::vector<std::string> out;
  for (std::string line; std::getline(lines, line);) out.push_back(line);
  return out;
}

std::string first_line(const std::string& stage) { return stage.substr(0, stage.find('\n')); }

}  // namespace

TEST_CASE(
    "GLSL form: each stage gets its define and PARAMETER_UNIFORM after a version a core context takes, the file's "
    "lines kept",
    "[libretro]") {
  const std::string text =
      "// a comment\n"
      "#pragma parameter gain \"Gain\" 0.5 0.0 2.0 0.05\n"
      "#if defined(VERTEX)\n"
      "void main() {}\n"
      "#endif\n";
  const SlangSource source = read_glsl_ok(text);
  CHECK(first_line(source.vertex) == "#version 330 core");  // no #version: 3.30 core
  CHECK(source.vertex.find("#define VERTEX\n#define PARAMETER_UNIFORM\n") != std::string::npos);
  CHECK(source.fragment.find("#define FRAGMENT\n#define PARAMETER_UNIFORM\n") != std::string::npos);
  CHECK(source.vertex.find("#define FRAGMENT") == std::string::npos);
  const auto lines = body_lines(source.fragment);
  REQUIRE(lines.size() == 5);  // line N of the file is line N after #line 1
  CHECK(lines[0] == "// a comment");
  CHECK(lines[1].empty());  // the parameter line is blanked: its quotes are not GLSL
  CHECK(lines[3] == "void main() {}");
  REQUIRE(source.parameters.size() == 1);
  CHECK(source.parameters[0].id == "gain");
  CHECK(source.parameters[0].label == "Gain");
  CHECK(source.parameters[0].initial == 0.5);
  CHECK(source.parameters[0].step == 0.05);
  CHECK(source.parameters[0].place.line == 2);
}

TEST_CASE("GLSL form: versions below 1.40 become 3.30 core, 1.40 and later are kept", "[libretro]") {
  CHECK(first_line(read_glsl_ok("#version 110\nvoid main() {}\n").vertex) == "#version 330 core");
  CHECK(first_line(read_glsl_ok("#version 130\nvoid main() {}\n").fragment) == "#version 330 core");
  CHECK(first_line(read_glsl_ok("  #version 150\nvoid main() {}\n").vertex) == "#version 150");
  CHECK(first_line(read_glsl_ok("/* x */\n#version 330 core\n").vertex) == "#version 330 core");
  // The #version line leaves the body (it comes first), its place kept.
  const auto lines = body_lines(read_glsl_ok("#version 150\nint x;\n").vertex);
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].empty());
  CHECK(lines[1] == "int x;");
}

TEST_CASE("GLSL form: a parameter declared twice keeps the first, a broken one names its line", "[libretro]") {
  const SlangSource source = read_glsl_ok(
      "#pragma parameter a \"A\" 1.0 0.0 2.0 0.1\n"
      "#pragma parameter a \"A again\" 0.0 0.0 1.0 0.1\n");
  REQUIRE(source.parameters.size() == 1);
  CHECK(source.parameters[0].label == "A");
  MemoryFiles files;
  files.texts["/s/bad.glsl"] = "int x;\n#pragma parameter b \"B\" 1.0\n";
  SlangSource out;
  std::string error;
  CHECK_FALSE(read_glsl("/s/bad.glsl", files.reader(), &out, &error));
  CHECK(error.find("/s/bad.glsl:2: ") == 0);
  CHECK_FALSE(read_glsl("/s/missing.glsl", files.reader(), &out, &error));
  CHECK(error.find("missing.glsl") != std::string::npos);
}

TEST_CASE("GLSL form names: pictures by Orig, PassN, PassPrevN, alias, Prev and Feedback, as RetroArch numbers them",
          "[libretro]") {
  SemanticContext context;
  context.aliases = {"first", "", "", ""};
  context.textures = {"palette"};
  context.parameters = {"gain"};
  context.pass = 2;  // the third pass (RetroArch's program 3)
  const auto is = [&](const std::string& name, SemanticKind kind, int index, bool texture, int feedback = -1) {
    const auto found = find_glsl_name(name, context, feedback);
    INFO(name);
    REQUIRE(found);
    CHECK(found->semantic.kind == kind);
    CHECK(found->semantic.index == index);
    CHECK(found->texture == texture);
  };
  is("Texture", SemanticKind::kSource, 0, true);
  is("InputSize", SemanticKind::kSourceSize, 0, false);
  is("TextureSize", SemanticKind::kSourceSize, 0, false);
  is("OutputSize", SemanticKind::kOutputSize, 0, false);
  is("MVPMatrix", SemanticKind::kMvp, 0, false);
  is("FrameCount", SemanticKind::kFrameCount, 0, false);
  is("OrigTexture", SemanticKind::kOriginal, 0, true);
  is("OrigInputSize", SemanticKind::kOriginalSize, 0, false);
  is("Pass1Texture", SemanticKind::kPassOutput, 0, true);  // counted from 1
  is("Pass2TextureSize", SemanticKind::kPassOutputSize, 1, false);
  is("PassPrev1Texture", SemanticKind::kPassOutput, 1, true);  // the pass before
  is("PassPrev2Texture", SemanticKind::kPassOutput, 0, true);
  is("PassPrev3Texture", SemanticKind::kOriginal, 0, true);  // one past the first pass
  is("firstTexture", SemanticKind::kPassOutput, 0, true);
  is("PrevTexture", SemanticKind::kOriginalHistory, 1, true);
  is("Prev6Texture", SemanticKind::kOriginalHistory, 7, true);
  is("FeedbackTexture", SemanticKind::kPassFeedback, 1, true, 1);
  is("palette", SemanticKind::kUser, 0, true);
  is("gain", SemanticKind::kParameter, 0, false);
  for (const char* none :
       {"Pass3Texture", "PassPrev4Texture", "Prev7Texture", "FeedbackTexture", "Unknown", "PassTexture", "Pass1"})
    CHECK_FALSE(find_glsl_name(none, context, -1));
  context.pass = 0;  // the first pass has no earlier pass; PassPrev1 is not Orig there
  CHECK_FALSE(find_glsl_name("PassPrev1Texture", context, -1));
  CHECK_FALSE(find_glsl_name("firstTexture", context, -1));  // its own alias
}

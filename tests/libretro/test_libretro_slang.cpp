// Slang shaders as RetroArch reads them before compiling (slang_source.hpp): includes, the two
// stages, and the pragmas that describe the pass; the stages compiled by glslangValidator.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include "memory_files.hpp"
#include "slang_source.hpp"

using namespace pfx::libretro;
using pfx::test::MemoryFiles;

namespace {

// A pass that darkens its source by the parameter `amount`, written the way the collections write them.
const char* const kDarken =
    "#version 450\n"
    "#include \"include/common.inc\"\n"
    "#pragma parameter amount \"Darken by\" 0.25 0.0 1.0 0.05\n"
    "#pragma parameter spread \"Spread\" 1.0 0.0 4.0\n"
    "#pragma name Darkened\n"
    "#pragma format R16G16B16A16_SFLOAT\n"
    "layout(std140, set = 0, binding = 0) uniform UBO { mat4 MVP; float amount; } global;\n"
    "#pragma stage vertex\n"
    "layout(location = 0) in vec4 Position;\n"
    "layout(location = 1) in vec2 TexCoord;\n"
    "layout(location = 0) out vec2 vTexCoord;\n"
    "void main() { gl_Position = global.MVP * Position; vTexCoord = TexCoord; }\n"
    "#pragma stage fragment\n"
    "layout(location = 0) in vec2 vTexCoord;\n"
    "layout(location = 0) out vec4 FragColor;\n"
    "layout(set = 0, binding = 2) uniform sampler2D Source;\n"
    "void main() { FragColor = scaled(texture(Source, vTexCoord), 1.0 - global.amount); }\n";

SlangSource read_slang_ok(MemoryFiles& files, const std::string& path) {
  SlangSource source;
  std::string error;
  const bool read = read_slang(path, files.reader(), &source, &error);
  INFO(error);
  REQUIRE(read);
  return source;
}

std::string read_slang_error(MemoryFiles& files, const std::string& path) {
  SlangSource source;
  std::string error;
  CHECK_FALSE(read_slang(path, files.reader(), &source, &error));
  return error;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Runs glslangValidator on `code` as a Vulkan shader of `stage` ("vert", "frag"); its output, or
// "" when it compiled.
std::string glslang_errors(const std::string& code, const std::string& stage) {
  char folder[] = "/tmp/pfx-libretro-slang-XXXXXX";
  REQUIRE(mkdtemp(folder));
  const std::string file = std::string(folder) + "/pass." + stage;
  std::ofstream(file) << code;
  const std::string log = std::string(folder) + "/log.txt";
  const std::string command = std::string(PFX_GLSLANG_VALIDATOR) + " -V --target-env vulkan1.0 -o " + folder +
                              "/pass.spv " + file + " > " + log + " 2>&1";
  const int status = std::system(command.c_str());
  std::stringstream output;
  output << std::ifstream(log).rdbuf();
  std::remove(log.c_str());
  std::remove(file.c_str());
  std::remove((std::string(folder) + "/pass.spv").c_str());
  rmdir(folder);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? "" : output.str() + "(status " + std::to_string(status) + ")";
}

}  // namespace

TEST_CASE("slang shaders: the two stages, the include spliced in, the pragmas read and out of the code", "[slang]") {
  MemoryFiles files;
  files.texts["/s/shaders/darken.slang"] = kDarken;
  files.texts["/s/shaders/include/common.inc"] = "vec4 scaled(vec4 c, float by) { return vec4(c.rgb * by, c.a); }\n";
  const SlangSource source = read_slang_ok(files, "/s/shaders/darken.slang");
  CHECK(source.name == "Darkened");
  CHECK(source.format == "R16G16B16A16_SFLOAT");
  REQUIRE(source.parameters.size() == 2);
  CHECK(source.parameters[0].id == "amount");
  CHECK(source.parameters[0].label == "Darken by");
  CHECK(source.parameters[0].initial == 0.25);
  CHECK(source.parameters[0].minimum == 0.0);
  CHECK(source.parameters[0].maximum == 1.0);
  CHECK(source.parameters[0].step == 0.05);
  CHECK(source.parameters[0].place.text() == "/s/shaders/darken.slang:3");
  // No step written: a tenth of the range, as RetroArch takes it.
  CHECK(source.parameters[1].step == Approx(0.4));
  CHECK(source.files == std::vector<std::string>{"/s/shaders/darken.slang", "/s/shaders/include/common.inc"});
  // What comes before the first stage is in both; each stage has only its own after that.
  for (const std::string* stage : {&source.vertex, &source.fragment}) {
    CHECK(stage->rfind("#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : require\n", 0) == 0);
    CHECK(contains(*stage, "vec4 scaled(vec4 c, float by)"));
    CHECK(contains(*stage, "uniform UBO"));
    CHECK_FALSE(contains(*stage, "#pragma"));
  }
  CHECK(contains(source.vertex, "gl_Position"));
  CHECK_FALSE(contains(source.vertex, "FragColor"));
  CHECK(contains(source.fragment, "FragColor"));
  CHECK_FALSE(contains(source.fragment, "gl_Position"));
  // Both stages compile as Vulkan GLSL, the line directives included.
  CHECK(glslang_errors(source.vertex, "vert").empty());
  CHECK(glslang_errors(source.fragment, "frag").empty());
}

TEST_CASE("slang shaders: the compiler's messages name the file and line the code was written at", "[slang]") {
  MemoryFiles files;
  std::string broken = kDarken;
  broken.replace(broken.find("1.0 - global.amount"), 19, "1.0 - undeclared_name");
  files.texts["/s/shaders/darken.slang"] = broken;
  files.texts["/s/shaders/include/common.inc"] =
      "// two lines\nvec4 scaled(vec4 c, float by) { return vec4(c.rgb * by, c.a); }\n";
  const SlangSource source = read_slang_ok(files, "/s/shaders/darken.slang");
  const std::string errors = glslang_errors(source.fragment, "frag");
  INFO(errors);
  CHECK(contains(errors, "/s/shaders/darken.slang:17"));
  CHECK(contains(errors, "undeclared_name"));
}

TEST_CASE("slang shaders: an optional include that is missing is skipped, a required one is an error", "[slang][bad]") {
  MemoryFiles files;
  std::string text = kDarken;
  text.replace(text.find("#include \"include/common.inc\""), 29,
               "#pragma include_optional \"nowhere.inc\"\nvec4 scaled(vec4 c, float by) { return c * by; }");
  files.texts["/s/opt.slang"] = text;
  CHECK(read_slang_ok(files, "/s/opt.slang").files == std::vector<std::string>{"/s/opt.slang"});
  files.texts["/s/req.slang"] = kDarken;
  CHECK(read_slang_error(files, "/s/req.slang") == "/s/req.slang:2: #include: /s/include/common.inc: no such file");
}

TEST_CASE("slang shaders: malformed files are errors naming the file and line", "[slang][bad]") {
  MemoryFiles files;
  const std::string stages = "#pragma stage vertex\nvoid main() {}\n#pragma stage fragment\nvoid main() {}\n";
  const std::map<std::string, std::string> cases = {
      {"void main() {}\n", "/s/x.slang:1: a slang shader starts with its #version line"},
      {"#version 450\nvoid main() {}\n", "/s/x.slang: needs both '#pragma stage vertex' and '#pragma stage fragment'"},
      {"#version 450\n#pragma stage vertex\nvoid main() {}\n",
       "/s/x.slang: needs both '#pragma stage vertex' and '#pragma stage fragment'"},
      {"#version 450\n#pragma stage geometry\n", "/s/x.slang:2: 'geometry' is not a stage (vertex, fragment)"},
      {"#version 450\n#pragma name A\n#pragma name B\n" + stages, "/s/x.slang:3: a second #pragma name"},
      {"#version 450\n#pragma format R8G8B8_UNORM\n" + stages,
       "/s/x.slang:2: 'R8G8B8_UNORM' is not a format #pragma format knows"},
      {"#version 450\n#pragma parameter p Label 0 0 1\n" + stages,
       "/s/x.slang:2: parameter 'p' needs its label in quotes"},
      {"#version 450\n#pragma parameter p \"P\" 0 1\n" + stages,
       "/s/x.slang:2: parameter 'p' needs an initial value, a minimum and a maximum (and may give a step)"},
      {"#version 450\n#pragma parameter p \"P\" 0 zero 1\n" + stages,
       "/s/x.slang:2: parameter 'p' needs an initial value, a minimum and a maximum (and may give a step)"},
      {"#version 450\n#pragma parameter p \"P\" 0 0 1\n#pragma parameter p \"P\" 0 0 2\n" + stages,
       "/s/x.slang:3: parameter 'p' was declared differently at /s/x.slang:2"},
      {"#version 450\n#include nowhere.inc\n" + stages, "/s/x.slang:2: #include needs a file in quotes"},
  };
  for (const auto& [text, expected] : cases) {
    files.texts["/s/x.slang"] = text;
    INFO(text);
    CHECK(read_slang_error(files, "/s/x.slang") == expected);
  }
  // Numbers read one after the other as RetroArch's sscanf reads them, what follows ignored.
  files.texts["/s/x.slang"] =
      "#version 450\n#pragma parameter a \"A\" 1.0 -3.0 3.0 1.0  // a note\n"
      "#pragma parameter b \"B\"  0  0 0.0.001 0.001\n#pragma parameter c \"C\" 0.5 0 1 ///note\n" +
      stages;
  const SlangSource read = read_slang_ok(files, "/s/x.slang");
  REQUIRE(read.parameters.size() == 3);
  CHECK(read.parameters[0].minimum == -3.0);
  CHECK(read.parameters[0].step == 1.0);
  CHECK(read.parameters[1].maximum == 0.0);
  CHECK(read.parameters[1].step == 0.001);
  CHECK(read.parameters[2].step == Approx(0.1));
  // The same parameter declared twice alike is one parameter (shaders share includes that declare them).
  files.texts["/s/x.slang"] = "#version 450\n#pragma parameter p \"P\" 0 0 1\n#pragma parameter p \"P\" 0 0 1\n" +
                              stages;
  CHECK(read_slang_ok(files, "/s/x.slang").parameters.size() == 1);
}

TEST_CASE("slang shaders: an include loop and includes that multiply stop with an error, not a hang", "[slang][bad]") {
  MemoryFiles files;
  files.texts["/s/loop.slang"] = "#version 450\n#include \"loop.inc\"\n";
  files.texts["/s/loop.inc"] = "// again\n#include \"loop.inc\"\n";
  CHECK(read_slang_error(files, "/s/loop.slang") ==
        "/s/loop.inc:2: includes nest more than 32 deep (does a file include itself?)");
  // Each level includes the next twice: 2^30 copies of the last without a bound.
  files.texts["/s/wide.slang"] = "#version 450\n#include \"w0.inc\"\n";
  for (int i = 0; i < 30; ++i)
    files.texts["/s/w" + std::to_string(i) + ".inc"] = "#include \"w" + std::to_string(i + 1) + ".inc\"\n#include \"w" +
                                                       std::to_string(i + 1) + ".inc\"\n";
  files.texts["/s/w30.inc"] = "// the last\n";
  CHECK(contains(read_slang_error(files, "/s/wide.slang"), ".inc:2: more than 4096 includes in one shader"));
  // Few includes of much code.
  files.texts["/s/big.slang"] =
      "#version 450\n#include \"big.inc\"\n#include \"big.inc\"\n#include \"big.inc\"\n#include \"big.inc\"\n";
  files.texts["/s/big.inc"] = std::string(5u << 20, ' ') + "\n";
  CHECK(read_slang_error(files, "/s/big.slang") ==
        "/s/big.inc:1: the shader grows past 16 MiB of code with its includes");
}

// Presets as RetroArch reads them (preset.hpp): per-pass settings and their defaults, scales,
// lookup textures, and presets built on others with #reference.
#include <catch2/catch.hpp>

#include <chrono>

#include "memory_files.hpp"
#include "preset.hpp"

using namespace pfx::libretro;
using pfx::test::MemoryFiles;

namespace {

Preset read_preset_ok(MemoryFiles& files, const std::string& path) {
  Preset preset;
  std::string error;
  const bool read = read_preset(path, files.reader(), &preset, &error);
  INFO(error);
  REQUIRE(read);
  return preset;
}

std::string read_preset_error(MemoryFiles& files, const std::string& path) {
  Preset preset;
  std::string error;
  CHECK_FALSE(read_preset(path, files.reader(), &preset, &error));
  return error;
}

}  // namespace

TEST_CASE("preset passes: a pass that says nothing more than its shader gets RetroArch's defaults", "[preset]") {
  MemoryFiles files;
  files.texts["/c/plain.slangp"] = "shaders = 1\nshader0 = shaders/plain.slang\n";
  const Preset preset = read_preset_ok(files, "/c/plain.slangp");
  CHECK(preset.format == PresetFormat::kSlang);
  CHECK(preset.root == "/c/plain.slangp");
  REQUIRE(preset.passes.size() == 1);
  const PresetPass& pass = preset.passes[0];
  CHECK(pass.shader == "/c/shaders/plain.slang");
  CHECK_FALSE(pass.filter_linear.has_value());
  CHECK(pass.wrap == WrapMode::kClampToBorder);
  CHECK_FALSE(pass.mipmap_input);
  CHECK(pass.alias.empty());
  CHECK_FALSE(pass.float_framebuffer);
  CHECK_FALSE(pass.srgb_framebuffer);
  CHECK_FALSE(pass.scaled);
  CHECK(pass.x.type == ScaleType::kSource);
  CHECK(pass.x.factor == 1.0);
  CHECK(pass.frame_count_mod == 0);
  CHECK(preset.textures.empty());
  CHECK(preset.warnings.empty());
}

TEST_CASE("preset passes: every per-pass key, quoted and bare, in a .glslp", "[preset]") {
  MemoryFiles files;
  files.texts["/c/all.glslp"] =
      "shaders = \"3\"\n"
      "shader0 = a.glsl\nfilter_linear0 = true\nwrap_mode0 = repeat\nmipmap_input0 = 1\nalias0 = \"First\"\n"
      "float_framebuffer0 = \"true\"\nsrgb_framebuffer0 = false\nscale_type0 = viewport\nscale0 = 0.5\n"
      "frame_count_mod0 = 0x10\n"
      "shader1 = b.glsl\nfilter_linear1 = 0\nwrap_mode1 = mirrored_repeat\nsrgb_framebuffer1 = true\n"
      "scale_type_x1 = absolute\nscale_x1 = 800.0\nscale_y1 = 2\nframe_count_mod1 = \"2\"\n"
      "shader2 = c.glsl\nwrap_mode2 = clamp_to_edge\nscale_type_y2 = viewport\nscale_x2 = 3\nscale_y2 = 1.5\n";
  const Preset preset = read_preset_ok(files, "/c/all.glslp");
  CHECK(preset.format == PresetFormat::kGlsl);
  REQUIRE(preset.passes.size() == 3);
  const PresetPass& a = preset.passes[0];
  CHECK(a.filter_linear == std::optional<bool>(true));
  CHECK(a.wrap == WrapMode::kRepeat);
  CHECK(a.mipmap_input);
  CHECK(a.alias == "First");
  CHECK(a.float_framebuffer);
  CHECK_FALSE(a.srgb_framebuffer);
  CHECK(a.scaled);
  // scale_typeN and scaleN set both axes.
  CHECK(a.x.type == ScaleType::kViewport);
  CHECK(a.y.type == ScaleType::kViewport);
  CHECK(a.x.factor == 0.5);
  CHECK(a.y.factor == 0.5);
  CHECK(a.frame_count_mod == 16);
  const PresetPass& b = preset.passes[1];
  CHECK(b.filter_linear == std::optional<bool>(false));
  CHECK(b.wrap == WrapMode::kMirroredRepeat);
  CHECK(b.srgb_framebuffer);
  // Only x given a type: y is the source's; an absolute size is an integer ("800.0" is 800).
  CHECK(b.x.type == ScaleType::kAbsolute);
  CHECK(b.x.pixels == 800);
  CHECK(b.y.type == ScaleType::kSource);
  CHECK(b.y.factor == 2.0);
  CHECK(b.frame_count_mod == 2);
  const PresetPass& c = preset.passes[2];
  CHECK(c.wrap == WrapMode::kClampToEdge);
  CHECK(c.x.type == ScaleType::kSource);
  CHECK(c.x.factor == 3.0);
  CHECK(c.y.type == ScaleType::kViewport);
  CHECK(c.y.factor == 1.5);
}

TEST_CASE("preset passes: what RetroArch ignores is a warning and the default", "[preset][bad]") {
  MemoryFiles files;
  files.texts["/c/w.slangp"] =
      "shaders = 1\nshader0 = a.slang\nfilter_linear0 = yes\nwrap_mode0 = clamp\nframe_count_mod0 = often\n";
  const Preset preset = read_preset_ok(files, "/c/w.slangp");
  const PresetPass& pass = preset.passes.at(0);
  CHECK_FALSE(pass.filter_linear.has_value());
  CHECK(pass.wrap == WrapMode::kClampToBorder);
  CHECK(pass.frame_count_mod == 0);
  REQUIRE(preset.warnings.size() == 3);
  CHECK(preset.warnings[0] ==
        "/c/w.slangp:3: 'filter_linear0 = yes' is not a boolean (true, false, 1, 0): the default applies");
  CHECK(preset.warnings[1].rfind("/c/w.slangp:4: 'wrap_mode0 = clamp' is not a wrap mode", 0) == 0);
  CHECK(preset.warnings[2] == "/c/w.slangp:5: 'often' is not a frame count modulus: FrameCount is not wrapped");
}

TEST_CASE("preset passes: what RetroArch refuses is an error naming the file and line", "[preset][bad]") {
  MemoryFiles files;
  const std::map<std::string, std::string> cases = {
      {"shader0 = a.slang\n", "/c/x.slangp: has no 'shaders' key"},
      {"shaders = many\nshader0 = a.slang\n", "/c/x.slangp:1: 'shaders' must give the number of passes"},
      {"shaders = 0\nshader0 = a.slang\n",
       "/c/x.slangp:1: 'shaders = 0': a preset has 1 to 64 passes (RetroArch's limit)"},
      {"shaders = 50000\nshader0 = a.slang\n",
       "/c/x.slangp:1: 'shaders = 50000': a preset has 1 to 64 passes (RetroArch's limit)"},
      {"shaders = 2\nshader0 = a.slang\n", "/c/x.slangp: pass 1 of 2 has no 'shader1 = FILE'"},
      {"shaders = 1\nshader0 = a.slang\nscale_type0 = stretch\n",
       "/c/x.slangp:3: 'stretch' is not a scale type (source, viewport, absolute)"},
      {"shaders = 1\nshader0 = a.slang\nscale_type0 = absolute\n",
       "/c/x.slangp:3: an absolute scale needs a size of 1 to 16384 pixels in 'scale0' or 'scale_x0'"},
      {"shaders = 1\nshader0 = a.slang\nscale_type0 = absolute\nscale0 = 0\n",
       "/c/x.slangp:4: an absolute scale needs a size of 1 to 16384 pixels in 'scale0' or 'scale_x0'"},
      {"shaders = 1\nshader0 = a.slang\nscale_type0 = source\nscale0 = -2\n",
       "/c/x.slangp:4: '-2' is not a positive scale factor"},
      {"shaders = 1\nshader0 = a.slang\nscale_type_y0 = source\nscale_y0 = nan\n",
       "/c/x.slangp:4: 'nan' is not a positive scale factor"},
      {"shaders = 1\nshader0 = a.slang\ntextures = lut\n",
       "/c/x.slangp:3: texture 'lut' is listed, but no 'lut = FILE' gives its file"},
  };
  for (const auto& [text, expected] : cases) {
    files.texts["/c/x.slangp"] = text;
    INFO(text);
    CHECK(read_preset_error(files, "/c/x.slangp") == expected);
  }
}

TEST_CASE("preset passes: 50,000 shader lines under 'shaders = 64' read in well under a second", "[preset][bad]") {
  MemoryFiles files;
  std::string text = "shaders = 64\n";
  for (int i = 0; i < 50000; ++i)
    text += "shader" + std::to_string(i) + " = pass.slang\nscale_type" + std::to_string(i) + " = source\n";
  files.texts["/c/long.slangp"] = text;
  const auto start = std::chrono::steady_clock::now();
  const Preset preset = read_preset_ok(files, "/c/long.slangp");
  CHECK(preset.passes.size() == 64);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
}

TEST_CASE("preset textures: ids from the list, files relative to the preset, their sampling settings", "[preset]") {
  MemoryFiles files;
  files.texts["/c/crt/lut.slangp"] =
      "shaders = 1\nshader0 = a.slang\n"
      "textures = \"mask; grain ;;palette\"\n"
      "mask = ../textures/mask.png\nmask_linear = true\nmask_wrap_mode = repeat\nmask_mipmap = \"true\"\n"
      "grain = grain.png\n"
      "palette = /abs/palette.png\npalette_linear = false\n";
  const Preset preset = read_preset_ok(files, "/c/crt/lut.slangp");
  REQUIRE(preset.textures.size() == 3);
  CHECK(preset.textures[0].id == "mask");
  CHECK(preset.textures[0].path == "/c/textures/mask.png");
  CHECK(preset.textures[0].linear == std::optional<bool>(true));
  CHECK(preset.textures[0].wrap == WrapMode::kRepeat);
  CHECK(preset.textures[0].mipmap);
  CHECK(preset.textures[1].id == "grain");
  CHECK(preset.textures[1].path == "/c/crt/grain.png");
  CHECK_FALSE(preset.textures[1].linear.has_value());
  CHECK(preset.textures[1].wrap == WrapMode::kClampToBorder);
  CHECK_FALSE(preset.textures[1].mipmap);
  CHECK(preset.textures[2].path == "/abs/palette.png");
  CHECK(preset.textures[2].linear == std::optional<bool>(false));
}

TEST_CASE("preset references: passes and textures from the root, values from every file, later files winning",
          "[preset]") {
  MemoryFiles files;
  // top: #reference mid (whose first reference is the root), then a values-only file.
  files.texts["/c/top.slangp"] =
      "#reference \"base/mid.slangp\"\n#reference \"values/more.params\"\n"
      "from_top = 1\nfilter_linear0 = true\nshaders = 5\n";
  files.texts
      ["/c/base/mid.slangp"] = "#reference \"../root/crt.slangp\"\nfrom_mid = 2\nshared = 20\nmask = mid-mask.png\n";
  files.texts["/c/root/crt.slangp"] =
      "shaders = 1\nshader0 = crt.slang\ntextures = mask\nmask = mask.png\n"
      "from_root = 3\nshared = 30\nlast = 300\n";
  files.texts["/c/values/more.params"] = "shared = 40\nlast = 400\nfrom_root = nan\n";
  const Preset preset = read_preset_ok(files, "/c/top.slangp");
  CHECK(preset.path == "/c/top.slangp");
  CHECK(preset.root == "/c/root/crt.slangp");
  REQUIRE(preset.passes.size() == 1);  // the root's passes; top's 'shaders' is not read
  CHECK(preset.passes[0].shader == "/c/root/crt.slang");
  // A per-pass key outside the root means nothing, as in RetroArch.
  CHECK_FALSE(preset.passes[0].filter_linear.has_value());
  // Values: root, then mid, then the values file, then top.
  REQUIRE(preset.layers.size() == 4);
  CHECK(preset.layers[0].path == "/c/root/crt.slangp");
  CHECK(preset.layers[1].path == "/c/base/mid.slangp");
  CHECK(preset.layers[2].path == "/c/values/more.params");
  CHECK(preset.layers[3].path == "/c/top.slangp");
  CHECK(preset.parameter_value("from_top") == std::optional<double>(1));
  CHECK(preset.parameter_value("from_mid") == std::optional<double>(2));
  CHECK(preset.parameter_value("from_root") == std::optional<double>(3));
  CHECK(preset.parameter_value("shared") == std::optional<double>(40));
  CHECK(preset.parameter_value("last") == std::optional<double>(400));
  CHECK_FALSE(preset.parameter_value("nothing").has_value());
  // A root's texture takes its file from the last file naming it, relative to that file.
  REQUIRE(preset.textures.size() == 1);
  CHECK(preset.textures[0].path == "/c/base/mid-mask.png");
}

TEST_CASE("preset references: cycles, missing files, a root without passes and a second chain of passes are errors",
          "[preset][bad]") {
  MemoryFiles files;
  files.texts["/c/self.slangp"] = "#reference self.slangp\nshaders = 1\nshader0 = a.slang\n";
  CHECK(read_preset_error(files, "/c/self.slangp") ==
        "/c/self.slangp:1: references go more than 16 deep (does a preset reference itself?)");
  files.texts["/c/a.slangp"] = "#reference b.slangp\n";
  files.texts["/c/b.slangp"] = "\n#reference a.slangp\n";
  CHECK(read_preset_error(files, "/c/a.slangp").find("references go more than 16 deep") != std::string::npos);
  files.texts["/c/lost.slangp"] = "#reference \"gone.slangp\"\n";
  CHECK(read_preset_error(files, "/c/lost.slangp") == "/c/lost.slangp:1: #reference: /c/gone.slangp: no such file");
  files.texts["/c/values.slangp"] = "x = 1\n";
  files.texts["/c/on-values.slangp"] = "#reference values.slangp\n";
  CHECK(
      read_preset_error(files, "/c/on-values.slangp") ==
      "/c/values.slangp: has no 'shaders' key, and the chain of first references from /c/on-values.slangp ends there");
  files.texts["/c/root.slangp"] = "shaders = 1\nshader0 = a.slang\n";
  // Values files that each reference the next twice: the list of files would double with each.
  files.texts["/c/w.params"] = "v = 1\n";
  for (int i = 0; i < 12; ++i)
    files.texts["/c/v" + std::to_string(i) + ".params"] = "#reference w.params\n#reference v" + std::to_string(i + 1) +
                                                          ".params\n#reference v" + std::to_string(i + 1) + ".params\n";
  files.texts["/c/v12.params"] = "v = 2\n";
  files.texts["/c/wide.slangp"] = "#reference root.slangp\n#reference v0.params\n";
  CHECK(read_preset_error(files, "/c/wide.slangp").find(": references reach files more than 256 times") !=
        std::string::npos);
  files.texts["/c/two.slangp"] = "#reference root.slangp\n#reference root.slangp\n";
  CHECK(read_preset_error(files, "/c/two.slangp") ==
        "/c/two.slangp:2: only the first #reference may lead to a preset with passes ('shaders'); this one leads to "
        "/c/root.slangp");
}

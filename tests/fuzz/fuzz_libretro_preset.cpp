// libFuzzer target for the readers of libretro presets and shaders, slang and GLSL
// (plugins/libretro/formats).
// The input is two files split at the first NUL byte: the preset (or shader) read, and what every
// other file it names (a #reference, an #include, a pass's shader) holds, so references and
// includes reach the second file and that file's own, itself included. Whatever the input, the
// readers end (no hang, no crash, no unbounded growth), a refusal says where, and an accepted
// preset's passes and textures stay within RetroArch's limits.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "glsl_source.hpp"
#include "preset.hpp"
#include "slang_source.hpp"

namespace {

void check(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find('\0');
  const std::string first = input.substr(0, split);
  const std::string others = split == std::string::npos ? first : input.substr(split + 1);
  const pfx::libretro::TextReader read = [&](const std::string& path, std::string*) -> std::optional<std::string> {
    return path == "/f/p.slangp" || path == "/f/p.slang" || path == "/f/p.glslp" || path == "/f/p.glsl" ? first
                                                                                                        : others;
  };
  std::string error;
  pfx::libretro::Preset preset;
  if (pfx::libretro::read_preset("/f/p.slangp", read, &preset, &error)) {
    check(!preset.passes.empty() && preset.passes.size() <= static_cast<std::size_t>(pfx::libretro::kMaxPasses));
    check(preset.textures.size() <= static_cast<std::size_t>(pfx::libretro::kMaxLookupTextures));
    for (const auto& pass : preset.passes) {
      for (const auto* axis : {&pass.x, &pass.y}) {
        if (axis->type == pfx::libretro::ScaleType::kAbsolute)
          check(axis->pixels >= 1 && axis->pixels <= 16384);
        else
          check(std::isfinite(axis->factor) && axis->factor > 0);
      }
      check(!pass.shader.empty());
    }
    for (const auto& texture : preset.textures) check(!texture.id.empty() && !texture.path.empty());
  } else {
    check(!error.empty());
  }
  error.clear();
  pfx::libretro::Preset glsl_preset;  // the same reader; a GLSL preset's feedback pass is one of its passes
  if (pfx::libretro::read_preset("/f/p.glslp", read, &glsl_preset, &error))
    check(glsl_preset.feedback_pass < static_cast<int>(glsl_preset.passes.size()));
  else
    check(!error.empty());
  error.clear();
  pfx::libretro::SlangSource glsl;
  if (pfx::libretro::read_glsl("/f/p.glsl", read, &glsl, &error)) {
    check(glsl.vertex.size() <= pfx::libretro::kMaxSlangSourceBytes + 65536);
    check(glsl.vertex.compare(0, 9, "#version ") == 0 && glsl.fragment.compare(0, 9, "#version ") == 0);
    for (const auto& parameter : glsl.parameters) check(!parameter.id.empty());
  } else {
    check(!error.empty());
  }
  error.clear();
  pfx::libretro::SlangSource source;
  if (pfx::libretro::read_slang("/f/p.slang", read, &source, &error)) {
    check(source.vertex.size() <= 2 * pfx::libretro::kMaxSlangSourceBytes + 65536);
    for (const auto& parameter : source.parameters) check(!parameter.id.empty());
  } else {
    check(!error.empty());
  }
  return 0;
}

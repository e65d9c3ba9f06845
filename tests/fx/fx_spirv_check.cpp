// The FX compiler's SPIR-V: runs the front end over each file named on the command line (include
// folders with -I), generates every pass of every technique in the Vulkan dialect, compiles each
// stage to SPIR-V and writes OUT_DIR/<file>.<technique>.<pass>.<vert|frag|comp>.spv beside the
// Vulkan GLSL it came from (.glsl). Exit status 1 when a file does not compile or a stage is
// refused; spirv/check_spirv.py then has spirv-val judge every module.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "codegen/glsl_generator.hpp"
#include "codegen/spirv_module.hpp"
#include "front_end.hpp"

namespace {

bool write(const std::string& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  return static_cast<bool>(out);
}

// One stage of one pass; false (with the reason printed) when it does not become SPIR-V.
bool stage(const std::string& glsl, pfx::fx::SpirvStage which, const std::string& base) {
  if (glsl.empty()) return true;
  const char* suffix = which == pfx::fx::SpirvStage::kVertex ? ".vert" : which == pfx::fx::SpirvStage::kFragment ? ".frag" : ".comp";
  std::vector<std::uint32_t> words;
  std::string log;
  write(base + suffix + ".glsl", glsl.data(), glsl.size());
  if (!pfx::fx::compile_spirv(glsl, which, words, log)) {
    std::printf("FAIL %s%s: glslang refused the Vulkan GLSL:\n%s\n", base.c_str(), suffix, log.c_str());
    return false;
  }
  return write(base + suffix + ".spv", words.data(), words.size() * sizeof(std::uint32_t));
}

}  // namespace

int main(int argc, char** argv) {
  pfx::fx::FrontEndOptions options;
  std::vector<std::string> files;
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    std::string argument = argv[i];
    if (argument.rfind("-I", 0) == 0) options.preprocessor.include_folders.push_back(argument.substr(2));
    else if (out_dir.empty()) out_dir = argument;
    else files.push_back(argument);
  }
  if (out_dir.empty() || files.empty()) {
    std::fprintf(stderr, "usage: fx_spirv_check [-IFOLDER...] OUT_DIR FILE.fx...\n");
    return 2;
  }
  bool ok = true;
  int modules = 0;
  for (const std::string& file : files) {
    auto result = pfx::fx::compile_front_end(file, options);
    if (!result->ok()) {
      std::printf("FAIL %s\n%s", file.c_str(), result->diagnostics.format_all().c_str());
      ok = false;
      continue;
    }
    pfx::fx::EffectModel model = pfx::fx::build_effect_model(result->unit, result->diagnostics);
    const std::string name = file.substr(file.find_last_of('/') + 1);
    for (const auto& technique : model.techniques)
      for (std::size_t p = 0; p < technique.passes.size(); ++p) {
        const auto& pass = technique.passes[p];
        pfx::fx::GeneratedPass generated =
            pfx::fx::generate_pass(result->unit, model, pass, result->diagnostics, nullptr, pfx::fx::GlslDialect::kVulkan);
        const std::string base = out_dir + "/" + name + "." + technique.name + "." + (pass.name.empty() ? "pass" + std::to_string(p) : pass.name);
        ok = stage(generated.vertex, pfx::fx::SpirvStage::kVertex, base) && ok;
        ok = stage(generated.fragment, pfx::fx::SpirvStage::kFragment, base) && ok;
        ok = stage(generated.compute, pfx::fx::SpirvStage::kCompute, base) && ok;
        modules += !generated.vertex.empty() + !generated.fragment.empty() + !generated.compute.empty();
      }
    if (result->diagnostics.error_count() > 0) {
      std::printf("FAIL %s\n%s", file.c_str(), result->diagnostics.format_all().c_str());
      ok = false;
    }
  }
  std::printf("%s: %d modules from %zu files in %s\n", ok ? "ok" : "FAIL", modules, files.size(), out_dir.c_str());
  return ok ? 0 : 1;
}

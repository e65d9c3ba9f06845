// A developer's tool: runs the FX front end over the files named on the command line (include
// folders with -I) and prints each file's diagnostics and a count of those that parse; --glsl
// also generates every pass of every technique and prints the GLSL (--vulkan: its Vulkan dialect). Used by hand on shader
// collections that must not be committed here, and by the golden tests (golden/check_golden.py).
#include <cstdio>
#include <string>
#include <vector>

#include "ast/ast_printer.hpp"
#include "codegen/glsl_generator.hpp"
#include "front_end.hpp"

int main(int argc, char** argv) {
  pfx::fx::FrontEndOptions options;
  std::vector<std::string> files;
  bool dump = false, glsl = false;
  pfx::fx::GlslDialect dialect = pfx::fx::GlslDialect::kOpenGL;
  for (int i = 1; i < argc; ++i) {
    std::string argument = argv[i];
    if (argument == "--dump") dump = true;
    else if (argument == "--glsl") glsl = true;
    else if (argument == "--vulkan") dialect = pfx::fx::GlslDialect::kVulkan;
    else if (argument.rfind("-I", 0) == 0) options.preprocessor.include_folders.push_back(argument.substr(2));
    else files.push_back(argument);
  }
  int parsed = 0;
  for (const std::string& file : files) {
    auto result = pfx::fx::compile_front_end(file, options);
    if (result->ok() && glsl) {
      pfx::fx::EffectModel model = pfx::fx::build_effect_model(result->unit, result->diagnostics);
      for (const auto& technique : model.techniques)
        for (const auto& pass : technique.passes) {
          pfx::fx::GeneratedPass generated = pfx::fx::generate_pass(result->unit, model, pass, result->diagnostics, nullptr, dialect);
          std::printf("// technique %s pass %s\n%s%s%s", technique.name.c_str(), pass.name.c_str(), generated.vertex.c_str(),
                      generated.fragment.c_str(), generated.compute.c_str());
        }
    }
    if (result->ok()) ++parsed;
    if (dump) std::printf("%s", pfx::fx::print_unit(result->unit).c_str());
    std::string text = result->diagnostics.format_all();
    std::printf("%s %s\n%s", result->ok() ? "OK  " : "FAIL", file.c_str(), text.c_str());
  }
  std::printf("%d of %zu files parse\n", parsed, files.size());
  return parsed == static_cast<int>(files.size()) ? 0 : 1;
}

// libretro_compile_check: every preset (.slangp) under the folders given, read and each of its
// passes compiled as the plugin will compile it (slang to SPIR-V by glslang, the reflection
// checked against the format's names, GLSL for GL by SPIRV-Cross), with a summary per top-level
// folder and each kind of failure once with an example. A developer's tool for measuring the
// readers and the compiler on a collection (libretro/slang-shaders); it draws nothing.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "preset.hpp"
#include "slang_gl.hpp"
#include "slang_reflection.hpp"
#include "slang_source.hpp"
#include "slang_spirv.hpp"

namespace fs = std::filesystem;
using namespace pfx::libretro;

namespace {

struct Stages {
  std::vector<std::uint32_t> vertex, fragment;
  std::string error;
};

// Compiled shaders by file: the collections use one shader in many presets.
std::map<std::string, Stages> compiled;

const Stages& stages_of(const std::string& path, const SlangSource& source) {
  auto it = compiled.find(path);
  if (it != compiled.end()) return it->second;
  Stages stages;
  if (!compile_slang_stage(source.vertex, SlangStage::kVertex, &stages.vertex, &stages.error) ||
      !compile_slang_stage(source.fragment, SlangStage::kFragment, &stages.fragment, &stages.error))
    stages.vertex.clear();
  return compiled.emplace(path, std::move(stages)).first->second;
}

// "" when every pass of the preset compiles; else "step: why".
std::string check_preset(const std::string& path) {
  Preset preset;
  std::string error;
  if (!read_preset(path, read_text_file, &preset, &error)) return "preset: " + error;
  std::vector<SlangSource> sources(preset.passes.size());
  SemanticContext context;
  for (std::size_t i = 0; i < preset.passes.size(); ++i) {
    if (!read_slang(preset.passes[i].shader, read_text_file, &sources[i], &error)) return "shader: " + error;
    context.aliases.push_back(preset.passes[i].alias.empty() ? sources[i].name : preset.passes[i].alias);
    for (const SlangParameter& parameter : sources[i].parameters)
      if (std::find(context.parameters.begin(), context.parameters.end(), parameter.id) == context.parameters.end())
        context.parameters.push_back(parameter.id);
  }
  for (const LookupTexture& texture : preset.textures) context.textures.push_back(texture.id);
  for (std::size_t i = 0; i < preset.passes.size(); ++i) {
    const Stages& stages = stages_of(preset.passes[i].shader, sources[i]);
    if (stages.vertex.empty()) return "glslang: " + stages.error;
    context.pass = static_cast<int>(i);
    PassInterface pass;
    GlPassCode code;
    if (!reflect_slang_pass(stages.vertex, stages.fragment, context, &pass, &error))
      return "reflection: " + preset.passes[i].shader + ": " + error;
    if (!slang_pass_for_gl(stages.vertex, stages.fragment, pass, &code, &error))
      return "GL code: " + preset.passes[i].shader + ": " + error;
  }
  return "";
}

// A failure's kind: its step and message without file names and lines.
std::string kind_of(const std::string& failure) {
  std::string kind = failure;
  for (std::size_t slash; (slash = kind.find('/')) != std::string::npos;) {
    // The whole path, from the start of its word: a relative one starts before its first '/'.
    const std::size_t space = slash == 0 ? std::string::npos : kind.rfind(' ', slash);
    const std::size_t at = space == std::string::npos ? 0 : space + 1;
    const std::size_t end = kind.find(": ", slash);
    kind.erase(at, end == std::string::npos ? std::string::npos : end + 2 - at);
  }
  return kind.substr(0, 160);
}

int usage(int status) {
  (status ? std::cerr : std::cout)
      << "usage: libretro_compile_check FOLDER...\n\n"
         "Reads every .slangp preset under each FOLDER and compiles each of its passes as pfx's libretro\n"
         "plugin does (glslang, the reflection checked against the slang format, GLSL for GL by\n"
         "SPIRV-Cross). Prints how many compiled per top-level folder and each kind of failure once, with\n"
         "an example. Exit status: 0 when every preset compiled, 1 otherwise, 2 for a usage error.\n";
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(2);
  if (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") return usage(0);
  std::map<std::string, std::pair<int, int>> folders;  // compiled, presets
  std::map<std::string, std::pair<int, std::string>> kinds;
  int presets = 0, passed = 0;
  for (int a = 1; a < argc; ++a) {
    std::error_code error;
    if (!fs::is_directory(argv[a], error))
      return std::cerr << "libretro_compile_check: " << argv[a] << " is not a folder\n", 2;
    std::vector<fs::path> files;
    for (const auto& entry :
         fs::recursive_directory_iterator(argv[a], fs::directory_options::skip_permission_denied, error))
      if (entry.path().extension() == ".slangp") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      const std::string relative = fs::relative(file, argv[a]).string();
      const std::string folder = relative.find('/') == std::string::npos ? "." : relative.substr(0, relative.find('/'));
      const std::string failure = check_preset(file.string());
      ++presets, ++folders[folder].second;
      if (failure.empty()) {
        ++passed, ++folders[folder].first;
        continue;
      }
      auto& kind = kinds[kind_of(failure)];
      if (kind.first++ == 0) kind.second = relative + ": " + failure.substr(0, 400);
    }
  }
  std::printf("%d presets, %d compiled (%d shader files)\n\n| folder | compiled | presets |\n|---|---:|---:|\n",
              presets, passed, static_cast<int>(compiled.size()));
  for (const auto& [folder, counts] : folders)
    std::printf("| %s | %d | %d |\n", folder.c_str(), counts.first, counts.second);
  std::vector<std::pair<int, std::string>> order;
  for (const auto& [kind, seen] : kinds) order.push_back({seen.first, kind});
  std::sort(order.rbegin(), order.rend());
  if (!order.empty()) std::printf("\nfailures, by kind:\n");
  for (const auto& [count, kind] : order)
    std::printf("%5d  %s\n       e.g. %s\n", count, kind.c_str(), kinds[kind].second.c_str());
  release_slang_compiler();
  return passed == presets ? 0 : 1;
}

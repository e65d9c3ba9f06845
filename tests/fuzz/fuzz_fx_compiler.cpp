// libFuzzer target for the FX compiler (plugins/fx/compiler): any bytes as an effect file, with one
// header it may include. An input may carry more files of its own, so that include chains are
// explored too: a line "//@file NAME" starts the file NAME (also found as inc/NAME), and
// what comes before the first such line is main.fx. Whatever the input, the compiler returns (no crash, no hang: every
// recursion is bounded by plugins/fx/compiler/limits.hpp), every error has a location in a known
// file, an accepted effect's whole tree can be walked, and its model and the GLSL of every pass
// are generated.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>

#include "ast/ast_printer.hpp"
#include "effect_compiler.hpp"

namespace {

const char kHeader[] =
    "#pragma once\n#define CAT(a, b) a##b\n#define STR(x) #x\n"
    "namespace H { texture2D Color : COLOR; sampler2D Back { Texture = Color; }; }\n"
    "void VS(uint id : SV_VertexID, out float4 p : SV_Position, out float2 uv : TEXCOORD)\n"
    "{ uv = float2(id == 2 ? 2 : 0, id == 1 ? 2 : 0); p = float4(uv * float2(2, -2) + float2(-1, 1), 0, 1); }\n";

const char kFileMarker[] = "//@file ";

// main.fx and the files the input carries, by name.
std::map<std::string, std::string> split_files(const std::string& input) {
  std::map<std::string, std::string> files;
  std::string name = "main.fx";
  size_t start = 0;
  for (;;) {
    size_t marker = input.find(kFileMarker, start);
    while (marker != std::string::npos && marker > 0 && input[marker - 1] != '\n')
      marker = input.find(kFileMarker, marker + 1);
    files[name] = input.substr(start, marker == std::string::npos ? std::string::npos : marker - start);
    if (marker == std::string::npos) return files;
    const size_t name_start = marker + sizeof kFileMarker - 1;
    const size_t end = input.find('\n', name_start);
    name = input.substr(name_start, end == std::string::npos ? std::string::npos : end - name_start);
    if (end == std::string::npos) return files;
    start = end + 1;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::map<std::string, std::string> files = split_files(std::string(reinterpret_cast<const char*>(data), size));
  auto reader = [&files](const std::string& path, std::string& contents) {
    auto found = files.find(path);
    if (found == files.end() && path.rfind("inc/", 0) == 0) found = files.find(path.substr(4));
    if (found != files.end()) return contents = found->second, true;
    if (path == "common.fxh" || path == "inc/common.fxh") return contents = kHeader, true;
    return false;
  };
  pfx::fx::FrontEndOptions options;
  options.preprocessor.include_folders = {"inc"};
  auto compiled = pfx::fx::compile_effect("main.fx", options, true, reader);
  const pfx::fx::FrontEndResult& result = *compiled->front;
  for (const pfx::fx::Diagnostic& d : result.diagnostics.all()) {
    if (d.location.file >= result.names.size()) std::abort();  // a location must name a known file
    if (result.diagnostics.format(d).empty()) std::abort();
  }
  if (result.ok()) (void)pfx::fx::print_unit(result.unit);  // the whole tree is well-formed
  // Every pass that generated has its program's stages.
  for (const auto& technique : compiled->passes)
    for (const auto& pass : technique)
      if (pass.compute.empty() && (pass.vertex.empty() != pass.fragment.empty())) std::abort();
  return 0;
}

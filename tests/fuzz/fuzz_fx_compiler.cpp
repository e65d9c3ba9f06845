// libFuzzer target for the FX compiler (plugins/fx/compiler): any bytes as an effect file, with one
// header it may include. Whatever the input, the compiler returns (no crash, no hang: every
// recursion is bounded by plugins/fx/compiler/limits.hpp), every error has a location in a known
// file, an accepted effect's whole tree can be walked, and its model and the GLSL of every pass
// are generated.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "ast/ast_printer.hpp"
#include "effect_compiler.hpp"

namespace {

const char kHeader[] =
    "#pragma once\n#define CAT(a, b) a##b\n#define STR(x) #x\n"
    "namespace H { texture2D Color : COLOR; sampler2D Back { Texture = Color; }; }\n"
    "void VS(uint id : SV_VertexID, out float4 p : SV_Position, out float2 uv : TEXCOORD)\n"
    "{ uv = float2(id == 2 ? 2 : 0, id == 1 ? 2 : 0); p = float4(uv * float2(2, -2) + float2(-1, 1), 0, 1); }\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string source(reinterpret_cast<const char*>(data), size);
  auto reader = [&source](const std::string& path, std::string& contents) {
    if (path == "main.fx") return contents = source, true;
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

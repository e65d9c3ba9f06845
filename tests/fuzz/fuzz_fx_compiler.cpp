// libFuzzer target for the FX compiler's front end (plugins/fx/compiler): any bytes as an effect
// file, with one header it may include. Whatever the input, the front end returns (no crash, no
// hang: every recursion is bounded by plugins/fx/compiler/limits.hpp), every error has a
// location in a known file, and an accepted effect's whole tree can be walked.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "ast/ast_printer.hpp"
#include "front_end.hpp"

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
  auto result = pfx::fx::compile_front_end("main.fx", options, reader);
  for (const pfx::fx::Diagnostic& d : result->diagnostics.all()) {
    if (d.location.file >= result->names.size()) std::abort();  // a location must name a known file
    if (result->diagnostics.format(d).empty()) std::abort();
  }
  if (result->ok()) (void)pfx::fx::print_unit(result->unit);  // the whole tree is well-formed
  return 0;
}

#include "state_tables.hpp"

#include <map>

namespace pfx::fx {
namespace {

using Kind = StateRule::Kind;
using Values = std::vector<std::string>;

const Values kFormats = {"R8", "R16", "R16F", "R32F", "R32I", "R32U", "RG8", "RG16", "RG16F", "RG32F",
                         "RGBA8", "RGBA16", "RGBA16F", "RGBA32F", "RGB10A2"};
const Values kAddress = {"CLAMP", "MIRROR", "WRAP", "REPEAT", "BORDER"};
const Values kFilters = {"POINT", "LINEAR", "ANISOTROPIC"};
const Values kBlendOps = {"ADD", "SUBTRACT", "REVSUBTRACT", "MIN", "MAX"};
const Values kBlendFactors = {"ZERO", "ONE", "SRCCOLOR", "SRCALPHA", "INVSRCCOLOR", "INVSRCALPHA",
                              "DESTCOLOR", "DESTALPHA", "INVDESTCOLOR", "INVDESTALPHA"};
const Values kCompare = {"NEVER", "ALWAYS", "EQUAL", "NEQUAL", "NOTEQUAL", "LESS", "GREATER",
                         "LEQUAL", "LESSEQUAL", "GEQUAL", "GREATEREQUAL"};
const Values kStencilOps = {"KEEP", "ZERO", "REPLACE", "INCR", "INCRSAT", "DECR", "DECRSAT", "INVERT"};
const Values kTopologies = {"POINTLIST", "LINELIST", "LINESTRIP", "TRIANGLELIST", "TRIANGLESTRIP"};

using Table = std::map<std::string, StateRule>;

const Table& table(StateOwner owner) {
  static const Table texture = {{"Width", {Kind::kSize}}, {"Height", {Kind::kSize}}, {"Depth", {Kind::kSize}},
                                {"MipLevels", {Kind::kSize}}, {"Format", {Kind::kEnum, &kFormats}}};
  static const Table sampler = {
      {"Texture", {Kind::kTexture}},          {"AddressU", {Kind::kEnum, &kAddress}},
      {"AddressV", {Kind::kEnum, &kAddress}}, {"AddressW", {Kind::kEnum, &kAddress}},
      {"MagFilter", {Kind::kEnum, &kFilters}}, {"MinFilter", {Kind::kEnum, &kFilters}},
      {"MipFilter", {Kind::kEnum, &kFilters}}, {"MinLOD", {Kind::kNumber}},
      {"MaxLOD", {Kind::kNumber}},            {"MipLODBias", {Kind::kNumber}},
      {"SRGBTexture", {Kind::kBool}}};
  static const Table storage = {{"Texture", {Kind::kTexture}}, {"MipLevel", {Kind::kNumber}}};
  // Per-target states take an index suffix 0..7 (find_state strips it).
  static const Table pass = {
      {"VertexShader", {Kind::kFunction}},      {"PixelShader", {Kind::kFunction}},
      {"ComputeShader", {Kind::kFunction}},     {"DispatchSizeX", {Kind::kSize}},
      {"DispatchSizeY", {Kind::kSize}},         {"DispatchSizeZ", {Kind::kSize}},
      {"RenderTarget", {Kind::kTexture}},       {"ClearRenderTargets", {Kind::kBool}},
      {"GenerateMipMaps", {Kind::kBool}},       {"SRGBWriteEnable", {Kind::kBool}},
      {"RenderTargetWriteMask", {Kind::kMask}}, {"ColorWriteEnable", {Kind::kMask}},
      {"ColorWriteMask", {Kind::kMask}},        {"BlendEnable", {Kind::kBool}},
      {"BlendOp", {Kind::kEnum, &kBlendOps}},   {"BlendOpAlpha", {Kind::kEnum, &kBlendOps}},
      {"SrcBlend", {Kind::kEnum, &kBlendFactors}}, {"SrcBlendAlpha", {Kind::kEnum, &kBlendFactors}},
      {"DestBlend", {Kind::kEnum, &kBlendFactors}}, {"DestBlendAlpha", {Kind::kEnum, &kBlendFactors}},
      {"StencilEnable", {Kind::kBool}},         {"StencilReadMask", {Kind::kMask}},
      {"StencilMask", {Kind::kMask}},           {"StencilWriteMask", {Kind::kMask}},
      {"StencilFunc", {Kind::kEnum, &kCompare}}, {"StencilRef", {Kind::kMask}},
      {"StencilPassOp", {Kind::kEnum, &kStencilOps}}, {"StencilPass", {Kind::kEnum, &kStencilOps}},
      {"StencilFailOp", {Kind::kEnum, &kStencilOps}}, {"StencilFail", {Kind::kEnum, &kStencilOps}},
      {"StencilDepthFailOp", {Kind::kEnum, &kStencilOps}}, {"StencilZFail", {Kind::kEnum, &kStencilOps}},
      {"PrimitiveTopology", {Kind::kEnum, &kTopologies}}, {"PrimitiveType", {Kind::kEnum, &kTopologies}},
      {"VertexCount", {Kind::kSize}}};
  switch (owner) {
    case StateOwner::kTexture: return texture;
    case StateOwner::kSampler: return sampler;
    case StateOwner::kStorage: return storage;
    case StateOwner::kPass: break;
  }
  return pass;
}

bool per_target(const std::string& name) {
  return name == "RenderTarget" || name == "RenderTargetWriteMask" || name == "ColorWriteEnable" ||
         name == "ColorWriteMask" || name == "BlendEnable" || name.compare(0, 7, "BlendOp") == 0 ||
         name.compare(0, 8, "SrcBlend") == 0 || name.compare(0, 9, "DestBlend") == 0;
}

}  // namespace

const StateRule* find_state(StateOwner owner, const std::string& name) {
  const Table& states = table(owner);
  auto it = states.find(name);
  if (it != states.end()) return &it->second;
  if (owner != StateOwner::kPass || name.size() < 2 || name.back() < '0' || name.back() > '7') return nullptr;
  std::string base = name.substr(0, name.size() - 1);
  it = states.find(base);
  return it != states.end() && per_target(base) ? &it->second : nullptr;
}

const char* owner_name(StateOwner owner) {
  switch (owner) {
    case StateOwner::kTexture: return "texture";
    case StateOwner::kSampler: return "sampler";
    case StateOwner::kStorage: return "storage";
    case StateOwner::kPass: break;
  }
  return "pass";
}

}  // namespace pfx::fx

#pragma once
// What an effect declares, read from the checked tree into plain data the code generator and the
// runtime share: textures with their sizes and formats, samplers with their states, storages,
// uniforms with their annotations and initial values, techniques with the states of each pass,
// and the GLSL-safe name of every global, struct and function. No GL here.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../ast/ast.hpp"
#include "../diagnostics.hpp"
#include "../sema/constant_value.hpp"

namespace pfx::fx {

enum class TextureFormat { kR8, kR16, kR16F, kR32F, kR32I, kR32U, kRG8, kRG16, kRG16F, kRG32F, kRGBA8, kRGBA16, kRGBA16F, kRGBA32F, kRGB10A2 };
enum class TextureSemantic { kNone, kColor, kDepth };
enum class AddressMode { kClamp, kMirror, kWrap, kBorder };
enum class FilterMode { kPoint, kLinear };
enum class BlendOp { kAdd, kSubtract, kRevSubtract, kMin, kMax };
enum class BlendFactor { kZero, kOne, kSrcColor, kSrcAlpha, kInvSrcColor, kInvSrcAlpha, kDestColor, kDestAlpha, kInvDestColor, kInvDestAlpha };
enum class Topology { kPointList, kLineList, kLineStrip, kTriangleList, kTriangleStrip };
enum class CompareFunc { kNever, kLess, kEqual, kLessEqual, kGreater, kNotEqual, kGreaterEqual, kAlways };
// As ReShade (and Direct3D) name them: INCR and DECR wrap around, INCRSAT and DECRSAT saturate.
enum class StencilOp { kKeep, kZero, kReplace, kIncrSat, kDecrSat, kInvert, kIncr, kDecr };

// The GLSL image format qualifier of a storage of this format ("rgba8").
const char* glsl_image_format(TextureFormat format);
// Whether texels of the format are integers: 1 signed, 2 unsigned, 0 floating or normalised.
int integer_class(TextureFormat format);
const char* format_name(TextureFormat format);

using Annotations = std::map<std::string, ConstantValue>;

struct TextureInfo {
  const VariableDecl* decl = nullptr;
  std::string name;  // qualified, as the source names it
  int dimension = 2;
  int width = 1, height = 1, depth = 1;
  int mip_levels = 1;
  TextureFormat format = TextureFormat::kRGBA8;
  TextureSemantic semantic = TextureSemantic::kNone;
  std::string source;  // an image file, from the "source" annotation
  bool pooled = false;
  Annotations annotations;
};

struct SamplerInfo {
  const VariableDecl* decl = nullptr;
  std::string name;
  int texture = -1;  // index into EffectModel::textures
  AddressMode address[3] = {AddressMode::kClamp, AddressMode::kClamp, AddressMode::kClamp};
  FilterMode min_filter = FilterMode::kLinear, mag_filter = FilterMode::kLinear, mip_filter = FilterMode::kLinear;
  float min_lod = 0.0f, max_lod = 3.402823466e38f, lod_bias = 0.0f;
  bool srgb = false;
};

struct StorageInfo {
  const VariableDecl* decl = nullptr;
  std::string name;
  int texture = -1;
  int mip_level = 0;
};

struct UniformInfo {
  const VariableDecl* decl = nullptr;
  std::string name;  // qualified
  Type type;
  Annotations annotations;
  std::vector<double> initial;  // every component (arrays flattened); zeros without an initialiser
  std::string source;           // "timer", "frametime", ... or "" for a value the user sets
};

struct BlendTarget {
  bool enable = false;
  BlendOp color_op = BlendOp::kAdd, alpha_op = BlendOp::kAdd;
  BlendFactor src = BlendFactor::kOne, dest = BlendFactor::kZero;
  BlendFactor src_alpha = BlendFactor::kOne, dest_alpha = BlendFactor::kZero;
  unsigned write_mask = 0xF;
};

// A pass's stencil states, with ReShade's defaults. The test compares (ref & read_mask) with
// (stencil & read_mask); the same states apply to front and back faces.
struct StencilState {
  bool enable = false;
  unsigned read_mask = 0xFF, write_mask = 0xFF;
  CompareFunc func = CompareFunc::kAlways;
  unsigned ref = 0;
  StencilOp pass_op = StencilOp::kKeep, fail_op = StencilOp::kKeep, depth_fail_op = StencilOp::kKeep;
};

constexpr int kMaxRenderTargets = 8;

struct PassInfo {
  SourceLocation location;
  std::string name;
  const FunctionDecl* vertex_shader = nullptr;
  const FunctionDecl* pixel_shader = nullptr;
  const FunctionDecl* compute_shader = nullptr;
  int thread_group[3] = {1, 1, 1};
  int dispatch[3] = {1, 1, 1};
  int render_targets[kMaxRenderTargets] = {-1, -1, -1, -1, -1, -1, -1, -1};  // texture indices
  int render_target_count = 0;  // 0: the pass writes the back buffer
  bool clear_render_targets = false;
  bool generate_mipmaps = true;
  bool srgb_write = false;
  BlendTarget blend[kMaxRenderTargets];
  StencilState stencil;
  Topology topology = Topology::kTriangleList;
  int vertex_count = 3;
};

struct TechniqueInfo {
  SourceLocation location;
  std::string name;
  Annotations annotations;
  std::vector<PassInfo> passes;
};

struct EffectModel {
  std::vector<TextureInfo> textures;
  std::vector<SamplerInfo> samplers;
  std::vector<StorageInfo> storages;
  std::vector<UniformInfo> uniforms;
  std::vector<TechniqueInfo> techniques;

  std::map<const VariableDecl*, int> texture_of, sampler_of, storage_of, uniform_of;
  // Every global variable (a function's statics among them), struct and function with its FX
  // name qualified by its namespaces ("ReShade::BackBuffer"; a function's static "Function_name"),
  // in the order the file declares them; overloads and prototypes share a name. Back ends make
  // their own identifiers from these (codegen/glsl_names for GLSL).
  struct Declared {
    const VariableDecl* variable = nullptr;
    const StructDecl* structure = nullptr;
    const FunctionDecl* function = nullptr;
    std::string qualified;
  };
  std::vector<Declared> declared;
  std::set<const VariableDecl*> globals;  // every global variable, a function's statics too
  std::vector<const StructDecl*> structs;          // in source order
  std::vector<const FunctionDecl*> functions;      // in source order (prototypes too)
  std::vector<const VariableDecl*> static_globals;  // static variables and constants, in source order
  std::vector<const VariableDecl*> shared_globals;  // groupshared
};

// Reads the model of a checked unit. Problems (a sampler without a texture, a pass without a
// shader, a size out of range) are errors in `diagnostics`.
EffectModel build_effect_model(const TranslationUnit& unit, Diagnostics& diagnostics);

// The annotation as a string, number or default.
std::string annotation_string(const Annotations& annotations, const std::string& name, const std::string& fallback = "");
double annotation_number(const Annotations& annotations, const std::string& name, double fallback);
bool has_annotation(const Annotations& annotations, const std::string& name);

}  // namespace pfx::fx

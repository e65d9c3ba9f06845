#include "effect_model.hpp"

#include <set>

#include "../sema/constant_eval.hpp"
#include "../text_lists.hpp"

namespace pfx::fx {
namespace {

// The index of an enum state's value among `names` (case-insensitive), or -1.
int enum_index(const Expr& value, std::initializer_list<const char*> names) {
  if (value.kind != ExprKind::kName) {
    auto n = evaluate_integer_constant(value);
    return n ? static_cast<int>(*n) : -1;
  }
  int i = 0;
  for (const char* n : names) {
    if (same_ignoring_case(value.text, n)) return i;
    ++i;
  }
  return -1;
}

long long integer_state(const Expr& value, long long fallback) {
  if (auto n = evaluate_integer_constant(value)) return *n;
  if (auto c = evaluate_constant(value))
    if (c->components.size() == 1) return static_cast<long long>(c->components[0]);
  return fallback;
}

bool bool_state(const Expr& value) { return integer_state(value, 0) != 0; }

double number_state(const Expr& value, double fallback) {
  auto c = evaluate_constant(value);
  return c && c->components.size() == 1 ? c->components[0] : fallback;
}

TextureFormat format_of(const Expr& value) {
  static const std::pair<const char*, TextureFormat> names[] = {
      {"R8", TextureFormat::kR8},         {"R16", TextureFormat::kR16},       {"R16F", TextureFormat::kR16F},
      {"R32F", TextureFormat::kR32F},     {"R32I", TextureFormat::kR32I},     {"R32U", TextureFormat::kR32U},
      {"RG8", TextureFormat::kRG8},       {"RG16", TextureFormat::kRG16},     {"RG16F", TextureFormat::kRG16F},
      {"RG32F", TextureFormat::kRG32F},   {"RGBA8", TextureFormat::kRGBA8},   {"RGBA16", TextureFormat::kRGBA16},
      {"RGBA16F", TextureFormat::kRGBA16F}, {"RGBA32F", TextureFormat::kRGBA32F}, {"RGB10A2", TextureFormat::kRGB10A2}};
  for (const auto& [name, format] : names)
    if (same_ignoring_case(value.text, name)) return format;
  return TextureFormat::kRGBA8;
}

AddressMode address_of(const Expr& value) {
  switch (enum_index(value, {"CLAMP", "MIRROR", "WRAP", "REPEAT", "BORDER"})) {
    case 1: return AddressMode::kMirror;
    case 2:
    case 3: return AddressMode::kWrap;
    case 4: return AddressMode::kBorder;
    default: return AddressMode::kClamp;
  }
}

FilterMode filter_of(const Expr& value) {
  return enum_index(value, {"POINT", "LINEAR", "ANISOTROPIC"}) == 0 ? FilterMode::kPoint : FilterMode::kLinear;
}

BlendOp blend_op_of(const Expr& value) {
  int i = enum_index(value, {"ADD", "SUBTRACT", "REVSUBTRACT", "MIN", "MAX"});
  return i < 0 ? BlendOp::kAdd : static_cast<BlendOp>(i);
}

BlendFactor blend_factor_of(const Expr& value) {
  int i = enum_index(value, {"ZERO", "ONE", "SRCCOLOR", "SRCALPHA", "INVSRCCOLOR", "INVSRCALPHA", "DESTCOLOR", "DESTALPHA",
                             "INVDESTCOLOR", "INVDESTALPHA"});
  if (value.kind != ExprKind::kName) return integer_state(value, 1) == 0 ? BlendFactor::kZero : BlendFactor::kOne;
  return i < 0 ? BlendFactor::kOne : static_cast<BlendFactor>(i);
}

CompareFunc compare_func_of(const Expr& value) {
  int i = enum_index(value, {"NEVER", "LESS", "EQUAL", "LEQUAL", "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS", "LESSEQUAL", "NEQUAL",
                             "GREATEREQUAL"});
  if (value.kind != ExprKind::kName) return CompareFunc::kAlways;
  switch (i) {
    case 8: return CompareFunc::kLessEqual;
    case 9: return CompareFunc::kNotEqual;
    case 10: return CompareFunc::kGreaterEqual;
    default: return i < 0 ? CompareFunc::kAlways : static_cast<CompareFunc>(i);
  }
}

StencilOp stencil_op_of(const Expr& value) {
  int i = enum_index(value, {"KEEP", "ZERO", "REPLACE", "INCRSAT", "DECRSAT", "INVERT", "INCR", "DECR"});
  if (value.kind != ExprKind::kName) return StencilOp::kKeep;
  return i < 0 ? StencilOp::kKeep : static_cast<StencilOp>(i);
}

unsigned stencil_byte(const Expr& value, unsigned fallback) {
  return static_cast<unsigned>(integer_state(value, fallback)) & 0xFFu;
}

Annotations read_annotations(const std::vector<Annotation>& list) {
  Annotations out;
  for (const Annotation& a : list)
    if (a.value)
      if (auto v = evaluate_constant(*a.value)) out[a.name] = *v;
  return out;
}

// The state's target index ("RenderTarget3" -> 3; "RenderTarget" -> 0) and its name without it.
int split_target_index(const std::string& name, std::string& base) {
  base = name;
  if (!name.empty() && name.back() >= '0' && name.back() <= '7' && name != "RenderTarget" &&
      (name.compare(0, 12, "RenderTarget") == 0 || name.compare(0, 5, "Blend") == 0 || name.compare(0, 8, "SrcBlend") == 0 ||
       name.compare(0, 9, "DestBlend") == 0 || name.compare(0, 10, "ColorWrite") == 0)) {
    base = name.substr(0, name.size() - 1);
    return name.back() - '0';
  }
  return 0;
}

class ModelBuilder {
 public:
  ModelBuilder(EffectModel& model, Diagnostics& diagnostics) : m_(model), diagnostics_(diagnostics) {}

  void walk(const std::vector<DeclPtr>& declarations, const std::string& prefix) {
    for (const DeclPtr& d : declarations) {
      switch (d->kind) {
        case DeclKind::kNamespace: walk(d->members, prefix + d->namespace_name + "::"); break;
        case DeclKind::kStruct:
          m_.structs.push_back(d->structure.get());
          m_.declared.push_back({nullptr, d->structure.get(), nullptr, prefix + d->structure->name});
          break;
        case DeclKind::kFunction: {
          const FunctionDecl* f = d->function.get();
          m_.functions.push_back(f);
          std::string qualified = prefix + f->name;
          m_.declared.push_back({nullptr, nullptr, f, qualified});
          if (f->body) function_statics(*f->body, qualified + "_");
          break;
        }
        case DeclKind::kVariables:
          for (const VariableDecl& v : d->variables) variable(v, prefix);
          break;
        case DeclKind::kTechnique: techniques_.push_back(d->technique.get()); break;
      }
    }
  }

  void finish() {
    for (const auto& [decl, index] : samplers_pending_) link_sampler(*decl, m_.samplers[static_cast<std::size_t>(index)]);
    for (const auto& [decl, index] : storages_pending_) link_storage(*decl, m_.storages[static_cast<std::size_t>(index)]);
    for (const TechniqueDecl* t : techniques_) technique(*t);
  }

 private:
  void variable(const VariableDecl& v, const std::string& prefix) {
    std::string qualified = prefix + v.name;
    const Type& t = v.resolved;
    m_.declared.push_back({&v, nullptr, nullptr, qualified});
    m_.globals.insert(&v);
    if (t.is_array() && t.base >= BaseType::kTexture) {
      diagnostics_.error(v.location, "arrays of textures, samplers or storages are not supported");
      return;
    }
    if (t.base == BaseType::kTexture) return texture(v, qualified);
    if (t.base == BaseType::kSampler) {
      m_.sampler_of[&v] = static_cast<int>(m_.samplers.size());
      samplers_pending_.emplace_back(&v, static_cast<int>(m_.samplers.size()));
      m_.samplers.push_back({&v, qualified});
      return;
    }
    if (t.base == BaseType::kStorage) {
      m_.storage_of[&v] = static_cast<int>(m_.storages.size());
      storages_pending_.emplace_back(&v, static_cast<int>(m_.storages.size()));
      m_.storages.push_back({&v, qualified});
      return;
    }
    if (v.qualifiers & kQualGroupShared) return m_.shared_globals.push_back(&v);
    if (v.qualifiers & kQualStatic) return m_.static_globals.push_back(&v);
    uniform(v, qualified);
  }

  // A function's `static` variable keeps its value from one call to the next (a `static const`
  // cannot change, so it stays a local): it becomes a static of the program, named after the
  // function (prefix) and started with the others, so its initialiser may use only globals and constants.
  void function_statics(const Stmt& s, const std::string& prefix) {
    if (s.kind == StmtKind::kDeclaration)
      for (const VariableDecl& v : s.variables) {
        if (!(v.qualifiers & kQualStatic) || (v.qualifiers & kQualConst)) continue;
        if (const VariableDecl* local = v.initializer ? first_local(*v.initializer) : nullptr)
          diagnostics_.error(v.location, "the initialiser of the static '" + v.name + "' uses '" + local->name +
                                             "', a local of the function; a static starts before any call, so it may use only globals and literals");
        m_.declared.push_back({&v, nullptr, nullptr, prefix + v.name});
        m_.globals.insert(&v);
        m_.static_globals.push_back(&v);
      }
    for (const Stmt* child : {s.init.get(), s.body.get(), s.else_body.get()})
      if (child) function_statics(*child, prefix);
    for (const StmtPtr& child : s.statements) function_statics(*child, prefix);
    for (const SwitchCase& c : s.cases)
      for (const StmtPtr& child : c.body) function_statics(*child, prefix);
  }

  const VariableDecl* first_local(const Expr& e) const {
    if (e.variable && !m_.globals.count(e.variable)) return e.variable;
    for (const ExprPtr& operand : e.operands)
      if (const VariableDecl* local = first_local(*operand)) return local;
    return nullptr;
  }

  void texture(const VariableDecl& v, const std::string& qualified) {
    TextureInfo info;
    info.decl = &v;
    info.name = qualified;
    info.dimension = v.resolved.dimension;
    info.annotations = read_annotations(v.annotations);
    info.source = annotation_string(info.annotations, "source");
    info.pooled = annotation_number(info.annotations, "pooled", 0) != 0;
    if (same_ignoring_case(v.semantic, "COLOR") || same_ignoring_case(v.semantic, "SV_TARGET")) info.semantic = TextureSemantic::kColor;
    if (same_ignoring_case(v.semantic, "DEPTH")) info.semantic = TextureSemantic::kDepth;
    for (const StateAssignment& s : v.states) {
      if (s.name == "Width") info.width = static_cast<int>(integer_state(*s.value, 1));
      else if (s.name == "Height") info.height = static_cast<int>(integer_state(*s.value, 1));
      else if (s.name == "Depth") info.depth = static_cast<int>(integer_state(*s.value, 1));
      else if (s.name == "MipLevels") info.mip_levels = static_cast<int>(integer_state(*s.value, 1));
      else if (s.name == "Format") info.format = format_of(*s.value);
    }
    if (info.dimension < 3) info.depth = 1;
    if (info.dimension < 2) info.height = 1;
    // A chain of mips ends at 1x1: more levels than that are not an error in ReShade, just clamped.
    int largest = std::max(info.width, std::max(info.height, info.depth)), levels = 1;
    while (largest > 1) largest /= 2, ++levels;
    info.mip_levels = std::max(1, std::min(info.mip_levels, levels));
    m_.texture_of[&v] = static_cast<int>(m_.textures.size());
    m_.textures.push_back(info);
  }

  int texture_named(const StateAssignment& s) {
    auto it = s.value->variable ? m_.texture_of.find(s.value->variable) : m_.texture_of.end();
    if (it == m_.texture_of.end()) {
      diagnostics_.error(s.location, "'" + s.name + "' does not name a texture");
      return -1;
    }
    return it->second;
  }

  void link_sampler(const VariableDecl& v, SamplerInfo& info) {
    for (const StateAssignment& s : v.states) {
      const Expr& value = *s.value;
      if (s.name == "Texture") info.texture = texture_named(s);
      else if (s.name == "AddressU") info.address[0] = address_of(value);
      else if (s.name == "AddressV") info.address[1] = address_of(value);
      else if (s.name == "AddressW") info.address[2] = address_of(value);
      else if (s.name == "MinFilter") info.min_filter = filter_of(value);
      else if (s.name == "MagFilter") info.mag_filter = filter_of(value);
      else if (s.name == "MipFilter") info.mip_filter = filter_of(value);
      else if (s.name == "MinLOD") info.min_lod = static_cast<float>(number_state(value, 0));
      else if (s.name == "MaxLOD") info.max_lod = static_cast<float>(number_state(value, 3.402823466e38));
      else if (s.name == "MipLODBias") info.lod_bias = static_cast<float>(number_state(value, 0));
      else if (s.name == "SRGBTexture") info.srgb = bool_state(value);
    }
    if (info.texture < 0) return;
    const TextureInfo& texture = m_.textures[static_cast<std::size_t>(info.texture)];
    if (texture.dimension != v.resolved.dimension)
      diagnostics_.error(v.location, "sampler '" + v.name + "' is " + std::to_string(v.resolved.dimension) + "D but its texture '" +
                                         texture.name + "' is " + std::to_string(texture.dimension) + "D");
  }

  void link_storage(const VariableDecl& v, StorageInfo& info) {
    for (const StateAssignment& s : v.states) {
      if (s.name == "Texture") info.texture = texture_named(s);
      else if (s.name == "MipLevel") info.mip_level = static_cast<int>(integer_state(*s.value, 0));
    }
    if (info.texture >= 0 && m_.textures[static_cast<std::size_t>(info.texture)].semantic != TextureSemantic::kNone)
      diagnostics_.error(v.location, "storage '" + v.name + "' cannot write the back buffer or the depth buffer");
  }

  void uniform(const VariableDecl& v, const std::string& qualified) {
    UniformInfo info;
    info.decl = &v;
    info.name = qualified;
    info.type = v.resolved;
    info.annotations = read_annotations(v.annotations);
    info.source = annotation_string(info.annotations, "source");
    long long count = v.resolved.components();
    for (int size : v.resolved.array) count *= size;
    if (!v.resolved.is_numeric() && !(v.resolved.is_array() && v.resolved.element().base <= BaseType::kDouble)) {
      diagnostics_.error(v.location, "uniform '" + v.name + "' must be numeric (a struct uniform is not supported)");
      return;
    }
    info.initial.assign(static_cast<std::size_t>(count), 0.0);
    if (v.initializer)
      if (auto c = evaluate_constant(*v.initializer))
        for (std::size_t i = 0; i < info.initial.size() && i < c->components.size(); ++i) info.initial[i] = c->components[i];
    m_.uniform_of[&v] = static_cast<int>(m_.uniforms.size());
    m_.uniforms.push_back(std::move(info));
  }

  void technique(const TechniqueDecl& t) {
    TechniqueInfo info;
    info.location = t.location;
    info.name = t.name;
    info.annotations = read_annotations(t.annotations);
    for (const PassDecl& p : t.passes) info.passes.push_back(pass(p));
    m_.techniques.push_back(std::move(info));
  }

  PassInfo pass(const PassDecl& p) {
    PassInfo info;
    info.location = p.location;
    info.name = p.name;
    bool any_target = false;
    for (const StateAssignment& s : p.states) {
      std::string base;
      int index = split_target_index(s.name, base);
      const Expr& value = *s.value;
      BlendTarget& blend = info.blend[index];
      if (base == "VertexShader") info.vertex_shader = value.function;
      else if (base == "PixelShader") info.pixel_shader = value.function;
      else if (base == "ComputeShader") {
        info.compute_shader = value.function;
        for (std::size_t i = 0; i < s.thread_group.size() && i < 3; ++i)
          info.thread_group[i] = static_cast<int>(integer_state(*s.thread_group[i], 1));
      } else if (base == "DispatchSizeX") info.dispatch[0] = static_cast<int>(integer_state(value, 1));
      else if (base == "DispatchSizeY") info.dispatch[1] = static_cast<int>(integer_state(value, 1));
      else if (base == "DispatchSizeZ") info.dispatch[2] = static_cast<int>(integer_state(value, 1));
      else if (base == "RenderTarget") {
        info.render_targets[index] = texture_named(s);
        any_target = true;
      } else if (base == "ClearRenderTargets") info.clear_render_targets = bool_state(value);
      else if (base == "GenerateMipMaps") info.generate_mipmaps = bool_state(value);
      else if (base == "SRGBWriteEnable") info.srgb_write = bool_state(value);
      else if (base == "BlendEnable") blend.enable = bool_state(value);
      else if (base == "BlendOp") blend.color_op = blend_op_of(value);
      else if (base == "BlendOpAlpha") blend.alpha_op = blend_op_of(value);
      else if (base == "SrcBlend") blend.src = blend_factor_of(value);
      else if (base == "DestBlend") blend.dest = blend_factor_of(value);
      else if (base == "SrcBlendAlpha") blend.src_alpha = blend_factor_of(value);
      else if (base == "DestBlendAlpha") blend.dest_alpha = blend_factor_of(value);
      else if (base == "RenderTargetWriteMask" || base == "ColorWriteEnable" || base == "ColorWriteMask")
        blend.write_mask = static_cast<unsigned>(integer_state(value, 0xF)) & 0xFu;
      else if (base == "StencilEnable") info.stencil.enable = bool_state(value);
      else if (base == "StencilReadMask" || base == "StencilMask") info.stencil.read_mask = stencil_byte(value, 0xFF);
      else if (base == "StencilWriteMask") info.stencil.write_mask = stencil_byte(value, 0xFF);
      else if (base == "StencilFunc") info.stencil.func = compare_func_of(value);
      else if (base == "StencilRef") info.stencil.ref = stencil_byte(value, 0);
      else if (base == "StencilPassOp" || base == "StencilPass") info.stencil.pass_op = stencil_op_of(value);
      else if (base == "StencilFailOp" || base == "StencilFail") info.stencil.fail_op = stencil_op_of(value);
      else if (base == "StencilDepthFailOp" || base == "StencilZFail") info.stencil.depth_fail_op = stencil_op_of(value);
      else if (base == "PrimitiveTopology" || base == "PrimitiveType") {
        int i = enum_index(value, {"POINTLIST", "LINELIST", "LINESTRIP", "TRIANGLELIST", "TRIANGLESTRIP"});
        info.topology = i < 0 ? Topology::kTriangleList : static_cast<Topology>(i);
      } else if (base == "VertexCount") info.vertex_count = static_cast<int>(integer_state(value, 3));
    }
    // A blend state set without an index applies to every target (ReShade: BlendEnable = all).
    for (int i = 1; i < kMaxRenderTargets; ++i) {
      bool set_for_i = false;
      for (const StateAssignment& s : p.states) {
        std::string base;
        set_for_i = set_for_i || (split_target_index(s.name, base) == i && base != s.name);
      }
      if (!set_for_i) info.blend[i] = info.blend[0];
    }
    if (any_target) {
      for (int i = 0; i < kMaxRenderTargets; ++i)
        if (info.render_targets[i] >= 0) info.render_target_count = i + 1;
      for (int i = 0; i < info.render_target_count; ++i)
        if (info.render_targets[i] < 0) diagnostics_.error(p.location, "RenderTarget" + std::to_string(i) + " is missing between targets");
      for (int i = 0; i < info.render_target_count; ++i) {
        int t = info.render_targets[i];
        const TextureInfo* first = info.render_targets[0] >= 0 ? &m_.textures[static_cast<std::size_t>(info.render_targets[0])] : nullptr;
        if (t >= 0 && first && (m_.textures[static_cast<std::size_t>(t)].width != first->width || m_.textures[static_cast<std::size_t>(t)].height != first->height))
          diagnostics_.error(p.location, "the render targets of one pass must have one size ('" + m_.textures[static_cast<std::size_t>(t)].name +
                                             "' differs from '" + first->name + "')");
        if (t >= 0 && m_.textures[static_cast<std::size_t>(t)].semantic == TextureSemantic::kDepth)
          diagnostics_.error(p.location, "a pass cannot render to the depth buffer");
        if (t >= 0 && m_.textures[static_cast<std::size_t>(t)].semantic == TextureSemantic::kColor) info.render_target_count = 0;
      }
    }
    if (info.compute_shader) {
      if (info.pixel_shader || info.vertex_shader) diagnostics_.error(p.location, "a pass has either a compute shader or vertex and pixel shaders");
    } else if (!info.pixel_shader || !info.vertex_shader) {
      diagnostics_.error(p.location, "pass '" + p.name + "' needs a VertexShader and a PixelShader (or a ComputeShader)");
    }
    return info;
  }

  EffectModel& m_;
  Diagnostics& diagnostics_;
  std::vector<std::pair<const VariableDecl*, int>> samplers_pending_, storages_pending_;
  std::vector<const TechniqueDecl*> techniques_;
};

}  // namespace

const char* glsl_image_format(TextureFormat format) {
  switch (format) {
    case TextureFormat::kR8: return "r8";
    case TextureFormat::kR16: return "r16";
    case TextureFormat::kR16F: return "r16f";
    case TextureFormat::kR32F: return "r32f";
    case TextureFormat::kR32I: return "r32i";
    case TextureFormat::kR32U: return "r32ui";
    case TextureFormat::kRG8: return "rg8";
    case TextureFormat::kRG16: return "rg16";
    case TextureFormat::kRG16F: return "rg16f";
    case TextureFormat::kRG32F: return "rg32f";
    case TextureFormat::kRGBA8: return "rgba8";
    case TextureFormat::kRGBA16: return "rgba16";
    case TextureFormat::kRGBA16F: return "rgba16f";
    case TextureFormat::kRGBA32F: return "rgba32f";
    case TextureFormat::kRGB10A2: return "rgb10_a2";
  }
  return "rgba8";
}

const char* format_name(TextureFormat format) {
  static const char* names[] = {"R8",    "R16",  "R16F",  "R32F",   "R32I",    "R32U",    "RG8",    "RG16",
                                "RG16F", "RG32F", "RGBA8", "RGBA16", "RGBA16F", "RGBA32F", "RGB10A2"};
  return names[static_cast<int>(format)];
}

int integer_class(TextureFormat format) {
  return format == TextureFormat::kR32I ? 1 : format == TextureFormat::kR32U ? 2 : 0;
}

EffectModel build_effect_model(const TranslationUnit& unit, Diagnostics& diagnostics) {
  EffectModel model;
  ModelBuilder builder(model, diagnostics);
  builder.walk(unit.declarations, "");
  builder.finish();
  return model;
}

std::string annotation_string(const Annotations& annotations, const std::string& name, const std::string& fallback) {
  auto it = annotations.find(name);
  return it != annotations.end() && it->second.is_string ? it->second.text : fallback;
}

double annotation_number(const Annotations& annotations, const std::string& name, double fallback) {
  auto it = annotations.find(name);
  return it != annotations.end() && !it->second.is_string && !it->second.components.empty() ? it->second.components[0] : fallback;
}

bool has_annotation(const Annotations& annotations, const std::string& name) { return annotations.count(name) > 0; }

}  // namespace pfx::fx

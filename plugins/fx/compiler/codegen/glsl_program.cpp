// One GLSL program per pass: which functions and globals the entry points reach, the
// declarations they need, and main() — HLSL semantics mapped onto GLSL's built-ins and
// interface variables.
#include <algorithm>
#include <cctype>
#include <functional>
#include <map>

#include "glsl_identifiers.hpp"
#include "glsl_generator.hpp"
#include "glsl_writer.hpp"

namespace pfx::fx {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// "TEXCOORD" and "TEXCOORD0" are one semantic, as are "SV_Target" and "SV_TARGET0".
std::string normalized(const std::string& semantic) {
  std::string s = upper(semantic);
  if (!s.empty() && !std::isdigit(static_cast<unsigned char>(s.back())) && s.compare(0, 3, "SV_") != 0) s += "0";
  if (s == "SV_TARGET") s = "SV_TARGET0";
  return s;
}

// Output target index of a pixel shader semantic ("SV_TARGET2", "COLOR1"), or -1.
int target_index(const std::string& semantic) {
  for (const char* prefix : {"SV_TARGET", "COLOR"}) {
    std::size_t n = std::char_traits<char>::length(prefix);
    if (semantic.compare(0, n, prefix) == 0 && semantic.size() == n + 1 && std::isdigit(static_cast<unsigned char>(semantic[n])))
      return semantic[n] - '0';
  }
  return -1;
}

bool is_position(const std::string& s) { return s == "SV_POSITION" || s == "POSITION0" || s == "VPOS0" || s == "SV_POSITION0"; }

struct Slot {  // one value with a semantic: a parameter, a struct member of one, or the return
  std::string access;  // "p0", "p0.m_uv", "r"
  Type type;
  std::string semantic;  // normalized
  SourceLocation location;
};

std::vector<Slot> slots(const std::string& access, const Type& type, const std::string& semantic, SourceLocation where) {
  if (type.base == BaseType::kStruct && type.structure && !type.is_array()) {
    std::vector<Slot> out;
    for (const VariableDecl& field : type.structure->fields) {
      auto inner = slots(access + "." + glsl_safe("m_" + field.name), field.resolved, field.semantic, field.location);
      out.insert(out.end(), inner.begin(), inner.end());
    }
    return out;
  }
  std::string name = normalized(semantic);
  if (type.is_array() && type.array.size() == 1) {
    // An array takes as many semantic indices as it has elements: TEXCOORD1, TEXCOORD2, ...
    std::size_t digits = name.find_last_not_of("0123456789") + 1;
    int first = digits < name.size() ? std::stoi(name.substr(digits)) : 0;
    std::vector<Slot> out;
    for (int k = 0; k < type.array[0]; ++k)
      out.push_back({access + "[" + std::to_string(k) + "]", type.element(), name.substr(0, digits) + std::to_string(first + k), where});
    return out;
  }
  return {{access, type, name, where}};
}

// Every slot an entry point reads (inputs) or writes (outputs).
std::vector<Slot> entry_slots(const FunctionDecl& f, bool inputs) {
  std::vector<Slot> out;
  for (std::size_t i = 0; i < f.parameters.size(); ++i) {
    const VariableDecl& p = f.parameters[i];
    bool is_out = (p.qualifiers & kQualOut) != 0, is_in = !is_out || (p.qualifiers & kQualIn) != 0;
    if (inputs ? !is_in : !is_out) continue;
    auto s = slots("p" + std::to_string(i), p.resolved, p.semantic, p.location);
    out.insert(out.end(), s.begin(), s.end());
  }
  if (!inputs && !f.resolved.is_void()) {
    auto s = slots("r", f.resolved, f.return_semantic, f.location);
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

// Calls and global variables an expression tree uses.
struct Uses {
  std::vector<const FunctionDecl*> functions;
  std::vector<const VariableDecl*> variables;
};

void collect(const Expr& e, Uses& uses) {
  if (e.function) uses.functions.push_back(e.function);
  if (e.variable) uses.variables.push_back(e.variable);
  for (const ExprPtr& operand : e.operands) collect(*operand, uses);
}

void collect(const Stmt& s, Uses& uses) {
  if (s.expression) collect(*s.expression, uses);
  if (s.increment) collect(*s.increment, uses);
  if (s.init) collect(*s.init, uses);
  if (s.body) collect(*s.body, uses);
  if (s.else_body) collect(*s.else_body, uses);
  for (const StmtPtr& child : s.statements) collect(*child, uses);
  for (const VariableDecl& v : s.variables)
    if (v.initializer) collect(*v.initializer, uses);
  for (const SwitchCase& c : s.cases)
    for (const StmtPtr& child : c.body) collect(*child, uses);
}

class ProgramBuilder {
 public:
  ProgramBuilder(const EffectModel& model, const PassInfo& pass, Diagnostics& diagnostics,
                 const UniformConstants* constants, GlslDialect dialect)
      : model_(model), names_(model), pass_(pass), diagnostics_(diagnostics), constants_(constants), dialect_(dialect) {}

  GeneratedPass build() {
    if (pass_.compute_shader) {
      result_.compute = stage(Stage::kCompute, *pass_.compute_shader);
    } else if (pass_.vertex_shader && pass_.pixel_shader) {
      // Interface variables: what the pixel shader reads besides built-ins, at one location each.
      for (const Slot& s : entry_slots(*pass_.pixel_shader, true))
        if (!is_position(s.semantic) && s.semantic.compare(0, 3, "SV_") != 0) varyings_.emplace(s.semantic, s.type.base);
      result_.vertex = stage(Stage::kVertex, *pass_.vertex_shader);
      result_.fragment = stage(Stage::kPixel, *pass_.pixel_shader);
    }
    std::sort(result_.uniforms.begin(), result_.uniforms.end());
    result_.uniforms.erase(std::unique(result_.uniforms.begin(), result_.uniforms.end()), result_.uniforms.end());
    return result_;
  }

 private:
  // The definition of a function the tree may name by its prototype.
  const FunctionDecl* definition(const FunctionDecl* f) const {
    if (f->body) return f;
    const std::string* name = names_.of(f);
    for (const FunctionDecl* candidate : model_.functions) {
      if (!candidate->body || candidate->parameters.size() != f->parameters.size()) continue;
      const std::string* other = names_.of(candidate);
      if (!other || !name || *other != *name) continue;
      bool same = true;
      for (std::size_t i = 0; i < f->parameters.size(); ++i) same = same && f->parameters[i].resolved == candidate->parameters[i].resolved;
      if (same) return candidate;
    }
    return f;
  }

  // Functions and globals reachable from `entry`.
  void reach(const FunctionDecl* entry, std::set<const FunctionDecl*>& functions, std::set<const VariableDecl*>& globals) {
    std::vector<const FunctionDecl*> pending{definition(entry)};
    std::vector<const VariableDecl*> pending_globals;
    while (!pending.empty() || !pending_globals.empty()) {
      Uses uses;
      if (!pending.empty()) {
        const FunctionDecl* f = pending.back();
        pending.pop_back();
        if (!functions.insert(f).second) continue;
        if (f->body) collect(*f->body, uses);
        for (const VariableDecl& p : f->parameters)
          if (p.initializer) collect(*p.initializer, uses);
      } else {
        const VariableDecl* g = pending_globals.back();
        pending_globals.pop_back();
        if (g->initializer) collect(*g->initializer, uses);
      }
      for (const FunctionDecl* called : uses.functions) pending.push_back(definition(called));
      for (const VariableDecl* v : uses.variables)
        if (model_.globals.count(v) && globals.insert(v).second) pending_globals.push_back(v);
    }
  }

  std::string stage(Stage which, const FunctionDecl& entry) {
    GlslWriter w(model_, names_, diagnostics_, which, dialect_);
    std::set<const FunctionDecl*> reached;
    std::set<const VariableDecl*> globals;
    reach(&entry, reached, globals);

    std::string functions;
    for (const FunctionDecl* f : model_.functions)
      if (reached.count(f)) w.function(*f, functions);
    std::string main = entry_point(w, which, *definition(&entry), globals);

    std::string out = "#version 450\n";
    if (which == Stage::kCompute)
      out += "layout(local_size_x = " + std::to_string(pass_.thread_group[0]) + ", local_size_y = " + std::to_string(pass_.thread_group[1]) +
             ", local_size_z = " + std::to_string(pass_.thread_group[2]) + ") in;\n";
    for (const StructDecl* s : model_.structs) {
      out += "struct " + *names_.of(s) + " {\n";
      for (const VariableDecl& field : s->fields)
        out += "  " + w.type(field.resolved) + " " + glsl_safe("m_" + field.name) + w.array_suffix(field.resolved) + ";\n";
      out += "};\n";
    }
    out += declarations(w, which, globals);
    out += interface(which);
    out += prelude(w.helpers, dialect_);
    out += functions;
    out += main;
    if (which == Stage::kPixel) result_.may_discard = result_.may_discard || w.uses_discard;
    return out;
  }

  std::string declarations(GlslWriter& w, Stage which, const std::set<const VariableDecl*>& globals) {
    std::string out, block;  // block: the effect's uniforms (uniform_block.hpp)
    // In the model's order, never a pointer's: the same source gives the same GLSL on every run
    // (the program cache's key).
    // The block holds every uniform of the effect, used here or not, so that each stage of each
    // pass, live or specialised, reads one buffer with one layout: a uniform compiled in as a
    // constant keeps its place in the block under a name nothing reads.
    for (std::size_t index = 0; index < model_.uniforms.size(); ++index) {
      const VariableDecl* decl = model_.uniforms[index].decl;
      const bool used = globals.count(decl) > 0;
      const std::string name = names_.global(decl) + w.array_suffix(decl->resolved);
      const std::vector<double>* value = constants_ && index < constants_->size() ? &(*constants_)[index] : nullptr;
      if (value && !value->empty() && can_be_constant(decl->resolved, *value)) {
        if (used) out += "const " + w.type(decl->resolved) + " " + name + " = " + constant_initialiser(w, decl->resolved, *value) + ";\n";
        block += "  " + w.type(decl->resolved) + " pfx_held_" + std::to_string(index) + w.array_suffix(decl->resolved) + ";\n";
        continue;
      }
      block += "  " + w.type(decl->resolved) + " " + name + ";\n";
      if (used) result_.uniforms.push_back(static_cast<int>(index));
    }
    for (std::size_t i = 0; i < model_.samplers.size(); ++i) {
      const SamplerInfo& s = model_.samplers[i];
      if (!globals.count(s.decl)) continue;
      out += binding(unit(result_.sampler_units, static_cast<int>(i)), kVulkanFirstSamplerBinding) + ") uniform " + w.type(s.decl->resolved) +
             " " + names_.global(s.decl) + ";\n";
    }
    for (std::size_t i = 0; i < model_.storages.size(); ++i) {
      const StorageInfo& s = model_.storages[i];
      if (!globals.count(s.decl) || s.texture < 0) continue;
      const TextureInfo& t = model_.textures[static_cast<std::size_t>(s.texture)];
      Type image = s.decl->resolved;
      image.element_base = integer_class(t.format) == 1 ? BaseType::kInt : integer_class(t.format) == 2 ? BaseType::kUint : BaseType::kFloat;
      out += binding(unit(result_.image_units, static_cast<int>(i)), kVulkanFirstStorageBinding) + ", " + glsl_image_format(t.format) +
             ") uniform coherent " + w.type(image) + " " + names_.global(s.decl) + ";\n";
    }
    for (const VariableDecl* v : model_.shared_globals)
      if (globals.count(v)) {
        if (which != Stage::kCompute) diagnostics_.error(v->location, "groupshared '" + v->name + "' is only allowed in a compute shader");
        out += "shared " + w.type(v->resolved) + " " + names_.global(v) + w.array_suffix(v->resolved) + ";\n";
      }
    for (const VariableDecl* v : model_.static_globals)
      if (globals.count(v)) out += w.type(v->resolved) + " " + names_.global(v) + w.array_suffix(v->resolved) + ";\n";
    if (!block.empty()) out += binding(kUniformBlockBinding, 0) + ", std140) uniform pfx_uniforms {\n" + block + "};\n";
    return out;
  }

  // "layout(binding = N" for the GL unit; in Vulkan, set 0 and the unit after `first`.
  std::string binding(int unit, int first) const {
    if (dialect_ == GlslDialect::kVulkan) return "layout(set = 0, binding = " + std::to_string(first + unit);
    return "layout(binding = " + std::to_string(unit);
  }

  static int unit(std::vector<int>& units, int index) {
    auto it = std::find(units.begin(), units.end(), index);
    if (it != units.end()) return static_cast<int>(it - units.begin());
    units.push_back(index);
    return static_cast<int>(units.size() - 1);
  }

  int location(const std::string& semantic) const {
    int i = 0;
    for (const auto& entry : varyings_) {
      if (entry.first == semantic) return i;
      ++i;
    }
    return -1;
  }

  static std::string interface_type(BaseType base) {
    return base == BaseType::kInt ? "ivec4" : base == BaseType::kUint ? "uvec4" : base == BaseType::kBool ? "ivec4" : "vec4";
  }

  std::string interface(Stage which) {
    std::string out;
    if (which == Stage::kVertex || which == Stage::kPixel)
      for (const auto& [semantic, base] : varyings_) {
        bool integral = base == BaseType::kInt || base == BaseType::kUint || base == BaseType::kBool;
        out += "layout(location = " + std::to_string(location(semantic)) + ") " + (integral && which == Stage::kPixel ? "flat " : "") +
               (integral && which == Stage::kVertex ? "flat " : "") + (which == Stage::kVertex ? "out " : "in ") + interface_type(base) +
               " pfx_v_" + semantic + ";\n";
      }
    if (which == Stage::kPixel) {
      if (dialect_ == GlslDialect::kOpenGL) out += std::string("uniform float ") + GeneratedPass::kTargetHeightUniform + ";\n";
      int targets = std::max(1, pass_.render_target_count);
      for (int i = 0; i < targets; ++i) {
        int texture = pass_.render_target_count > 0 ? pass_.render_targets[i] : -1;
        int integral = texture >= 0 ? integer_class(model_.textures[static_cast<std::size_t>(texture)].format) : 0;
        out += "layout(location = " + std::to_string(i) + ") out " + (integral == 1 ? "ivec4" : integral == 2 ? "uvec4" : "vec4") +
               " pfx_target_" + std::to_string(i) + ";\n";
      }
    }
    return out;
  }

  // A value of `type` from a semantic the stage provides.
  std::string source(GlslWriter& w, Stage which, const Slot& s) {
    const std::string& sem = s.semantic;
    Type u = Type::scalar(BaseType::kUint), u3 = Type::vector(BaseType::kUint, 3);
    if (which == Stage::kVertex) {
      if (sem == "SV_VERTEXID" || sem == "VERTEXID0") return w.cast(w.vulkan() ? "uint(gl_VertexIndex)" : "uint(gl_VertexID)", u, s.type);
      if (sem == "SV_INSTANCEID") return w.cast(w.vulkan() ? "uint(gl_InstanceIndex)" : "uint(gl_InstanceID)", u, s.type);
      return w.cast("0", Type::scalar(BaseType::kInt), s.type);  // no vertex buffers in a post effect
    }
    if (which == Stage::kCompute) {
      if (sem == "SV_DISPATCHTHREADID") return w.cast("gl_GlobalInvocationID", u3, s.type);
      if (sem == "SV_GROUPTHREADID") return w.cast("gl_LocalInvocationID", u3, s.type);
      if (sem == "SV_GROUPID") return w.cast("gl_WorkGroupID", u3, s.type);
      if (sem == "SV_GROUPINDEX") return w.cast("gl_LocalInvocationIndex", u, s.type);
      diagnostics_.error(s.location, "semantic '" + sem + "' is not a compute shader input");
      return w.cast("0", Type::scalar(BaseType::kInt), s.type);
    }
    if (is_position(sem)) {
      // FX's pixel rows count from the top of the target, as Vulkan's do and GL's do not.
      std::string y = w.vulkan() ? "gl_FragCoord.y" : std::string(GeneratedPass::kTargetHeightUniform) + " - gl_FragCoord.y";
      return w.cast("vec4(gl_FragCoord.x, " + y + ", gl_FragCoord.z, 1.0 / gl_FragCoord.w)", Type::vector(BaseType::kFloat, 4), s.type);
    }
    if (sem == "SV_ISFRONTFACE") return w.cast("gl_FrontFacing", Type::scalar(BaseType::kBool), s.type);
    auto it = varyings_.find(sem);
    BaseType base = it != varyings_.end() ? it->second : BaseType::kFloat;
    BaseType carried = base == BaseType::kBool ? BaseType::kInt : base;
    return w.cast("pfx_v_" + sem, Type::vector(carried == BaseType::kHalf || carried == BaseType::kDouble ? BaseType::kFloat : carried, 4), s.type);
  }

  // `value` of `type` padded to a four-component vector of `base` (missing components 0, alpha 1).
  static std::string padded(GlslWriter& w, const std::string& value, const Type& type, BaseType base) {
    Type four = Type::vector(base, 4);
    int n = type.components();
    if (!type.is_numeric() || type.is_matrix() || n >= 4) return w.cast(value, type, four);
    std::string text = w.type(four) + "(" + w.cast(value, type, Type::vector(base, n));
    for (int i = n; i < 4; ++i) text += i == 3 ? ", 1" : ", 0";
    return text + ")";
  }

  std::string sink(GlslWriter& w, Stage which, const Slot& s) {
    const std::string& sem = s.semantic;
    if (which == Stage::kVertex) {
      if (is_position(sem)) {
        std::string out = "  gl_Position = " + padded(w, s.access, s.type, BaseType::kFloat) + ";\n";
        if (!w.vulkan()) return out;
        out += "  gl_Position.y = -gl_Position.y;\n";  // Vulkan's clip space points y down
        // A point's size is the shader's to give in Vulkan (GL's is 1 unless a program asks).
        return pass_.topology == Topology::kPointList ? out + "  gl_PointSize = 1.0;\n" : out;
      }
      auto it = varyings_.find(sem);
      if (it == varyings_.end()) return "";  // nothing reads it
      BaseType base = it->second == BaseType::kBool ? BaseType::kInt : it->second;
      if (base == BaseType::kHalf || base == BaseType::kDouble) base = BaseType::kFloat;
      return "  pfx_v_" + sem + " = " + padded(w, s.access, s.type, base) + ";\n";
    }
    if (which == Stage::kPixel) {
      if (sem == "SV_DEPTH") return "  gl_FragDepth = " + w.cast(s.access, s.type, Type::scalar(BaseType::kFloat)) + ";\n";
      int index = target_index(sem);
      if (index < 0 || index >= std::max(1, pass_.render_target_count)) {
        if (index < 0) diagnostics_.error(s.location, "semantic '" + sem + "' is not a pixel shader output");
        return "";
      }
      int texture = pass_.render_target_count > 0 ? pass_.render_targets[index] : -1;
      int integral = texture >= 0 ? integer_class(model_.textures[static_cast<std::size_t>(texture)].format) : 0;
      BaseType base = integral == 1 ? BaseType::kInt : integral == 2 ? BaseType::kUint : BaseType::kFloat;
      return "  pfx_target_" + std::to_string(index) + " = " + padded(w, s.access, s.type, base) + ";\n";
    }
    return "";
  }

  std::string entry_point(GlslWriter& w, Stage which, const FunctionDecl& f, const std::set<const VariableDecl*>& globals) {
    std::string out;
    w.line_directive(f.location, out);
    out += "void main() {\n";
    if (which == Stage::kVertex)
      for (const auto& [semantic, base] : varyings_) out += "  pfx_v_" + semantic + " = " + interface_type(base) + "(0);\n";
    // Statics start as HLSL's do: their initialiser, or zero.
    for (const VariableDecl* v : model_.static_globals) {
      if (!globals.count(v)) continue;
      std::string value;
      if (v->initializer) value = v->initializer->kind == ExprKind::kInitList ? w.init_list(*v->initializer, v->resolved) : w.expr(*v->initializer);
      else value = zero(w, v->resolved);
      out += "  " + names_.global(v) + " = " + value + ";\n";
    }
    std::string arguments;
    for (std::size_t i = 0; i < f.parameters.size(); ++i) {
      const VariableDecl& p = f.parameters[i];
      out += "  " + w.type(p.resolved) + " p" + std::to_string(i) + w.array_suffix(p.resolved) + ";\n";
      arguments += (i ? ", " : "") + std::string("p") + std::to_string(i);
    }
    for (const Slot& s : entry_slots(f, true)) out += "  " + s.access + " = " + source(w, which, s) + ";\n";
    const std::string* name = names_.of(&f);
    std::string call = (name ? *name : f.name) + "(" + arguments + ")";
    out += f.resolved.is_void() ? "  " + call + ";\n" : "  " + w.type(f.resolved) + " r = " + call + ";\n";
    for (const Slot& s : entry_slots(f, false)) out += sink(w, which, s);
    // Temporaries the statics' initialisers needed come first.
    out.insert(out.find("void main() {\n") + 14, w.take_temporaries(1));
    return out + "}\n";
  }

  std::string zero(GlslWriter& w, const Type& t) {
    if (t.is_array()) {
      std::string text = w.full_type(t) + "(";
      for (int i = 0; i < t.array[0]; ++i) text += (i ? ", " : "") + zero(w, t.element());
      return text + ")";
    }
    if (t.base == BaseType::kStruct && t.structure) {
      std::string text = w.type(t) + "(";
      for (std::size_t i = 0; i < t.structure->fields.size(); ++i) text += (i ? ", " : "") + zero(w, t.structure->fields[i].resolved);
      return text + ")";
    }
    return w.splat("0", t);
  }

  const EffectModel& model_;
  const GlslNames names_;
  const PassInfo& pass_;
  Diagnostics& diagnostics_;
  const UniformConstants* constants_;  // null: every uniform live
  const GlslDialect dialect_;
  std::map<std::string, BaseType> varyings_;
  GeneratedPass result_;
};

}  // namespace

GeneratedPass generate_pass(const TranslationUnit& unit, const EffectModel& model, const PassInfo& pass, Diagnostics& diagnostics,
                            const UniformConstants* constants, GlslDialect dialect) {
  (void)unit;  // the model points into it; the signature says what the result depends on
  return ProgramBuilder(model, pass, diagnostics, constants, dialect).build();
}

}  // namespace pfx::fx

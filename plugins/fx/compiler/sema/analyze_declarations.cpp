// Declarations, name lookup through namespaces, array sizes, techniques and pass states.
#include "../limits.hpp"
#include "analyzer.hpp"
#include "constant_eval.hpp"

namespace pfx::fx {

Type error_type() {
  Type t;
  t.rows = -1;
  return t;
}

bool is_error(const Type& type) { return type.base == BaseType::kVoid && type.rows == -1; }

void analyze(TranslationUnit& unit, Diagnostics& diagnostics) { Analyzer(diagnostics).run(unit); }

void Analyzer::run(TranslationUnit& unit) {
  declare_all(unit.declarations);
  check_recursion();
}

void Analyzer::declare_all(std::vector<DeclPtr>& declarations) {
  for (DeclPtr& d : declarations) {
    if (diagnostics_.too_many_errors()) return;
    switch (d->kind) {
      case DeclKind::kVariables: declare_variables(d->variables, true); break;
      case DeclKind::kStruct: declare_struct(*d->structure); break;
      case DeclKind::kFunction: declare_function(*d->function); break;
      case DeclKind::kTechnique: check_technique(*d->technique); break;
      case DeclKind::kNamespace: {
        std::string outer = namespace_prefix_;
        namespace_prefix_ += d->namespace_name + "::";
        declare_all(d->members);
        namespace_prefix_ = outer;
        break;
      }
    }
  }
}

std::vector<std::string> Analyzer::candidates(const std::string& name) const {
  // Inner namespaces first: inside A::B, "x" may be A::B::x, A::x or x. "::x" is only the global x.
  if (name.compare(0, 2, "::") == 0) return {name.substr(2)};
  std::vector<std::string> out;
  std::string prefix = namespace_prefix_;
  for (;;) {
    out.push_back(prefix + name);
    if (prefix.empty()) break;
    std::size_t cut = prefix.rfind("::", prefix.size() - 3);
    prefix = cut == std::string::npos ? std::string() : prefix.substr(0, cut + 2);
  }
  return out;
}

const VariableDecl* Analyzer::find_variable(const std::string& name) const {
  if (name.find("::") == std::string::npos)
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope) {
      auto it = scope->find(name);
      if (it != scope->end()) return it->second;
    }
  for (const std::string& candidate : candidates(name)) {
    auto it = globals_.find(candidate);
    if (it != globals_.end()) return it->second;
  }
  return nullptr;
}

const std::vector<FunctionDecl*>* Analyzer::find_functions(const std::string& name, std::string* qualified) const {
  for (const std::string& candidate : candidates(name)) {
    auto it = functions_.find(candidate);
    if (it == functions_.end()) continue;
    if (qualified) *qualified = candidate;
    return &it->second;
  }
  return nullptr;
}

Type Analyzer::resolve_type(const TypeSyntax& syntax, SourceLocation where) {
  Type type;
  type.base = syntax.base;
  type.shape = syntax.shape;
  type.rows = syntax.rows;
  type.columns = syntax.columns;
  type.dimension = syntax.dimension;
  type.element_base = syntax.element_base;
  type.element_rows = syntax.element_rows;
  if (syntax.base != BaseType::kStruct) return type;
  for (const std::string& candidate : candidates(syntax.struct_name)) {
    auto it = structs_.find(candidate);
    if (it != structs_.end()) return type.structure = it->second, type;
  }
  diagnostics_.error(where, "unknown type '" + syntax.struct_name + "'");
  return error_type();
}

bool Analyzer::resolve_array_sizes(VariableDecl& variable, Type& type) {
  long long elements = 1;
  for (std::size_t i = 0; i < variable.array_sizes.size(); ++i) {
    ExprPtr& size = variable.array_sizes[i];
    if (!size) {  // unsized: the initialiser decides (outermost dimension only)
      if (i != 0) return diagnostics_.error(variable.location, "only the first array dimension may be unsized"), false;
      type.array.push_back(0);
      continue;
    }
    check(*size);
    auto value = is_error(size->resolved) ? std::nullopt : evaluate_integer_constant(*size);
    if (!value) return diagnostics_.error(size->location, "array size is not an integer constant"), false;
    if (*value <= 0) return diagnostics_.error(size->location, "array size must be positive, not " + std::to_string(*value)), false;
    elements = *value > limits::kMaxArrayElements ? *value : elements * *value;
    if (elements > limits::kMaxArrayElements) {
      diagnostics_.error(size->location, "array '" + variable.name + "' has more than " +
                                             std::to_string(limits::kMaxArrayElements) + " elements");
      return false;
    }
    type.array.push_back(static_cast<int>(*value));
  }
  return true;
}

void Analyzer::declare_variables(std::vector<VariableDecl>& variables, bool global) {
  for (VariableDecl& v : variables) {
    Type type = resolve_type(v.type, v.location);
    if (is_error(type) || !resolve_array_sizes(v, type)) type = error_type();
    if (type.is_void() && !is_error(type)) diagnostics_.error(v.location, "variable '" + v.name + "' cannot be void");
    v.resolved = type;
    if (v.initializer) check_initializer(v);
    if (!global && (type.is_object() || (type.is_array() && type.base >= BaseType::kTexture)))
      diagnostics_.error(v.location, "'" + v.name + "': textures, samplers and storages must be global");
    if (v.has_state_block || type.is_object()) check_object(v);
    if (global) {
      std::string qualified = namespace_prefix_ + v.name;
      if (globals_.count(qualified)) diagnostics_.error(v.location, "redefinition of '" + v.name + "'");
      globals_[qualified] = &v;
      global_variables_.insert(&v);
      if (type.base == BaseType::kTexture) textures_.insert(qualified);
    } else {
      if (scopes_.back().count(v.name)) diagnostics_.error(v.location, "redefinition of '" + v.name + "'");
      scopes_.back()[v.name] = &v;
    }
  }
}

void Analyzer::check_initializer(VariableDecl& v) {
  if (is_error(v.resolved)) return;
  if (v.initializer->kind == ExprKind::kInitList) {
    check_init_list(*v.initializer, v.resolved);
    if (v.resolved.is_array() && v.resolved.array[0] == 0)
      v.resolved.array[0] = static_cast<int>(v.initializer->operands.size());
    return;
  }
  check(*v.initializer);
  convert(v.initializer, v.resolved, "the initialisation of '" + v.name + "'");
}

void Analyzer::declare_struct(StructDecl& structure) {
  std::string qualified = namespace_prefix_ + structure.name;
  if (structs_.count(qualified)) diagnostics_.error(structure.location, "redefinition of struct '" + structure.name + "'");
  std::set<std::string> names;
  for (VariableDecl& field : structure.fields) {
    Type type = resolve_type(field.type, field.location);
    if (!is_error(type) && !resolve_array_sizes(field, type)) type = error_type();
    if (type.is_object()) diagnostics_.error(field.location, "struct members cannot be textures, samplers or storages");
    if (!names.insert(field.name).second) diagnostics_.error(field.location, "duplicate member '" + field.name + "'");
    field.resolved = type;
  }
  structs_[qualified] = &structure;
}

}  // namespace pfx::fx

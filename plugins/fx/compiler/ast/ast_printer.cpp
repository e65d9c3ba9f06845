#include "ast_printer.hpp"

#include "semantic_type.hpp"

namespace pfx::fx {
namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\0') out += "\\0";
    else if (c == '\n') out += "\\n";
    else if (c == '"' || c == '\\') out += std::string("\\") + c;
    else out += c;
  }
  return out + "\"";
}

std::string list(const char* head, const std::vector<ExprPtr>& operands) {
  std::string out = std::string("(") + head;
  for (const ExprPtr& operand : operands) out += " " + (operand ? print_expression(*operand) : std::string("_"));
  return out + ")";
}

std::string print_variable(const VariableDecl& v);

std::string print_annotations(const std::vector<Annotation>& annotations) {
  std::string out;
  for (const Annotation& a : annotations) out += " (@ " + a.name + " " + print_expression(*a.value) + ")";
  return out;
}

std::string print_states(const std::vector<StateAssignment>& states) {
  std::string out;
  for (const StateAssignment& s : states) {
    out += " (state " + s.name + " " + print_expression(*s.value);
    if (!s.thread_group.empty()) out += " " + list("threads", s.thread_group);
    out += ")";
  }
  return out;
}

std::string qualifier_words(unsigned q) {
  static const struct {
    unsigned bit;
    const char* word;
  } table[] = {{kQualStatic, "static"}, {kQualConst, "const"}, {kQualUniform, "uniform"}, {kQualExtern, "extern"},
               {kQualGroupShared, "groupshared"}, {kQualPrecise, "precise"}, {kQualIn, "in"}, {kQualOut, "out"}};
  std::string out;
  for (const auto& entry : table)
    if (q & entry.bit) out += std::string(entry.word) + " ";
  return out;
}

std::string print_variable(const VariableDecl& v) {
  std::string out = "(var " + qualifier_words(v.qualifiers) + type_spelling(v.type) + " " + v.name;
  for (const ExprPtr& size : v.array_sizes) out += "[" + (size ? print_expression(*size) : std::string()) + "]";
  if (!v.semantic.empty()) out += " :" + v.semantic;
  out += print_annotations(v.annotations);
  if (v.initializer) out += " " + print_expression(*v.initializer);
  if (v.has_state_block) out += " (states" + print_states(v.states) + ")";
  return out + ")";
}

std::string print_attributes(const std::vector<Attribute>& attributes) {
  std::string out;
  for (const Attribute& a : attributes) out += a.arguments.empty() ? "[" + a.name + "] " : list(("[" + a.name + "]").c_str(), a.arguments) + " ";
  return out;
}

}  // namespace

std::string print_expression(const Expr& e) {
  switch (e.kind) {
    case ExprKind::kInt:
    case ExprKind::kFloat:
    case ExprKind::kBool:
    case ExprKind::kName: return e.text;
    case ExprKind::kString: return quoted(e.text);
    case ExprKind::kUnary: return list(punct_spelling(e.op), e.operands);
    case ExprKind::kPostfix: return list((std::string("post") + punct_spelling(e.op)).c_str(), e.operands);
    case ExprKind::kBinary:
    case ExprKind::kAssign: return list(punct_spelling(e.op), e.operands);
    case ExprKind::kConditional: return list("?", e.operands);
    case ExprKind::kSequence: return list(",", e.operands);
    case ExprKind::kCall: return list(("call " + e.text).c_str(), e.operands);
    case ExprKind::kConstruct: return list(type_spelling(e.type).c_str(), e.operands);
    case ExprKind::kCast: return list(("cast " + type_spelling(e.type)).c_str(), e.operands);
    case ExprKind::kMember: return "(. " + print_expression(*e.operands[0]) + " " + e.text + ")";
    case ExprKind::kIndex: return list("[]", e.operands);
    case ExprKind::kInitList: return list("{}", e.operands);
  }
  return "?";
}

std::string print_typed_expression(const Expr& e) {
  std::string type = ":" + type_name(e.resolved);
  if (e.kind == ExprKind::kCast && e.implicit) return "(implicit " + print_typed_expression(*e.operands[0]) + ")" + type;
  if (e.operands.empty()) return print_expression(e) + type;
  std::string head;
  switch (e.kind) {
    case ExprKind::kUnary:
    case ExprKind::kBinary:
    case ExprKind::kAssign: head = punct_spelling(e.op); break;
    case ExprKind::kPostfix: head = std::string("post") + punct_spelling(e.op); break;
    case ExprKind::kConditional: head = "?"; break;
    case ExprKind::kSequence: head = ","; break;
    case ExprKind::kCall: head = "call " + e.text; break;
    case ExprKind::kConstruct: head = type_spelling(e.type); break;
    case ExprKind::kCast: head = "cast " + type_spelling(e.type); break;
    case ExprKind::kMember: head = "."; break;
    case ExprKind::kIndex: head = "[]"; break;
    default: head = "{}"; break;
  }
  std::string out = "(" + head;
  for (const ExprPtr& operand : e.operands) out += " " + print_typed_expression(*operand);
  if (e.kind == ExprKind::kMember) out += " " + e.text;
  return out + ")" + type;
}

std::string print_statement(const Stmt& s) {
  std::string out = print_attributes(s.attributes);
  auto optional = [](const auto& p) { return p ? " " + print_expression(*p) : std::string(" _"); };
  switch (s.kind) {
    case StmtKind::kEmpty: return out + "(empty)";
    case StmtKind::kExpression: return out + "(expr " + print_expression(*s.expression) + ")";
    case StmtKind::kDeclaration: {
      out += "(decl";
      for (const VariableDecl& v : s.variables) out += " " + print_variable(v);
      return out + ")";
    }
    case StmtKind::kBlock: {
      out += "(block";
      for (const StmtPtr& inner : s.statements) out += " " + print_statement(*inner);
      return out + ")";
    }
    case StmtKind::kIf:
      return out + "(if " + print_expression(*s.expression) + " " + print_statement(*s.body) +
             (s.else_body ? " " + print_statement(*s.else_body) : std::string()) + ")";
    case StmtKind::kFor:
      return out + "(for " + (s.init ? print_statement(*s.init) : std::string("_")) + optional(s.expression) +
             optional(s.increment) + " " + print_statement(*s.body) + ")";
    case StmtKind::kWhile: return out + "(while " + print_expression(*s.expression) + " " + print_statement(*s.body) + ")";
    case StmtKind::kDoWhile: return out + "(do " + print_statement(*s.body) + " " + print_expression(*s.expression) + ")";
    case StmtKind::kSwitch: {
      out += "(switch " + print_expression(*s.expression);
      for (const SwitchCase& c : s.cases) {
        out += " (case";
        for (const ExprPtr& label : c.labels) out += " " + print_expression(*label);
        if (c.has_default) out += " default";
        for (const StmtPtr& inner : c.body) out += " " + print_statement(*inner);
        out += ")";
      }
      return out + ")";
    }
    case StmtKind::kBreak: return out + "(break)";
    case StmtKind::kContinue: return out + "(continue)";
    case StmtKind::kDiscard: return out + "(discard)";
    case StmtKind::kReturn: return out + (s.expression ? "(return " + print_expression(*s.expression) + ")" : "(return)");
  }
  return "?";
}

std::string print_declaration(const Decl& d) {
  switch (d.kind) {
    case DeclKind::kVariables: {
      std::string out;
      for (const VariableDecl& v : d.variables) out += (out.empty() ? "" : " ") + print_variable(v);
      return out;
    }
    case DeclKind::kFunction: {
      const FunctionDecl& f = *d.function;
      std::string out = print_attributes(f.attributes) + "(function " + type_spelling(f.return_type) + " " + f.name + " (";
      for (std::size_t i = 0; i < f.parameters.size(); ++i) out += (i ? " " : "") + print_variable(f.parameters[i]);
      out += ")";
      if (!f.return_semantic.empty()) out += " :" + f.return_semantic;
      return out + " " + (f.body ? print_statement(*f.body) : std::string("prototype")) + ")";
    }
    case DeclKind::kStruct: {
      std::string out = "(struct " + d.structure->name;
      for (const VariableDecl& v : d.structure->fields) out += " " + print_variable(v);
      return out + ")";
    }
    case DeclKind::kTechnique: {
      const TechniqueDecl& t = *d.technique;
      std::string out = "(technique " + t.name + print_annotations(t.annotations);
      for (const PassDecl& p : t.passes)
        out += " (pass" + (p.name.empty() ? std::string() : " " + p.name) + print_annotations(p.annotations) +
               print_states(p.states) + ")";
      return out + ")";
    }
    case DeclKind::kNamespace: {
      std::string out = "(namespace " + d.namespace_name;
      for (const DeclPtr& member : d.members) out += " " + print_declaration(*member);
      return out + ")";
    }
  }
  return "?";
}

std::string print_unit(const TranslationUnit& unit) {
  std::string out;
  for (const DeclPtr& d : unit.declarations) out += print_declaration(*d) + "\n";
  return out;
}

}  // namespace pfx::fx

// Statements and function definitions.
#include "glsl_writer.hpp"

#include <cstdint>
#include <optional>

#include "../sema/constant_eval.hpp"

namespace pfx::fx {
namespace {

std::string pad(int indent) { return std::string(static_cast<std::size_t>(indent) * 2, ' '); }

// A case label as a literal of the selector's type: HLSL's labels are constant expressions, names
// of static consts among them (case Mode_Radial:), which GLSL takes only as constants of its own,
// and it wants int labels for an int selector and uint ones for a uint selector. The analyser has
// folded every label already.
std::string case_label(const Expr& label, const Type& selector) {
  const std::optional<long long> value = evaluate_integer_constant(label);
  if (!value) return "0";
  if (selector.base == BaseType::kUint) return std::to_string(static_cast<std::uint32_t>(*value)) + "u";
  return std::to_string(static_cast<std::int32_t>(*value));
}

}  // namespace

void GlslWriter::line_directive(SourceLocation where, std::string& out) {
  // Driver messages then name the FX file (by its index) and line the code came from.
  if (where.line > 0) out += "#line " + std::to_string(where.line) + " " + std::to_string(where.file) + "\n";
}

void GlslWriter::declaration(const VariableDecl& v, int indent, std::string& out) {
  out += pad(indent) + type(v.resolved) + " " + name_of(v) + array_suffix(v.resolved);
  if (v.initializer) {
    if (v.initializer->kind == ExprKind::kInitList) out += " = " + init_list(*v.initializer, v.resolved);
    else out += " = " + expr(*v.initializer);
  }
  out += ";\n";
}

void GlslWriter::statement(const Stmt& s, int indent, std::string& out) {
  std::string p = pad(indent);
  line_directive(s.location, out);
  switch (s.kind) {
    case StmtKind::kEmpty: out += p + ";\n"; return;
    case StmtKind::kExpression: out += p + expr(*s.expression) + ";\n"; return;
    case StmtKind::kDeclaration:
      for (const VariableDecl& v : s.variables)
        if (!model_.globals.count(&v)) declaration(v, indent, out);  // a function's statics are the program's
      return;
    case StmtKind::kBlock:
      out += p + "{\n";
      for (const StmtPtr& child : s.statements) statement(*child, indent + 1, out);
      out += p + "}\n";
      return;
    case StmtKind::kIf:
      out += p + "if (" + expr(*s.expression) + ")\n";
      statement(*s.body, indent + 1, out);
      if (s.else_body) {
        out += p + "else\n";
        statement(*s.else_body, indent + 1, out);
      }
      return;
    case StmtKind::kFor: {
      // The initialiser goes in a block of its own so several declarators keep GLSL's rules.
      out += p + "{\n";
      if (s.init) statement(*s.init, indent + 1, out);
      out += p + "  for (; " + (s.expression ? expr(*s.expression) : std::string("true")) + "; " +
             (s.increment ? expr(*s.increment) : std::string()) + ")\n";
      statement(*s.body, indent + 2, out);
      out += p + "}\n";
      return;
    }
    case StmtKind::kWhile:
      out += p + "while (" + expr(*s.expression) + ")\n";
      statement(*s.body, indent + 1, out);
      return;
    case StmtKind::kDoWhile:
      out += p + "do\n";
      statement(*s.body, indent + 1, out);
      out += p + "while (" + expr(*s.expression) + ");\n";
      return;
    case StmtKind::kSwitch: {
      const Type& t = s.expression->resolved;
      std::string selector = expr(*s.expression);
      if (t.base != BaseType::kInt && t.base != BaseType::kUint) selector = "int(" + selector + ")";
      out += p + "switch (" + selector + ") {\n";
      for (const SwitchCase& c : s.cases) {
        for (const ExprPtr& label : c.labels) out += p + "  case " + case_label(*label, t) + ":\n";
        if (c.has_default) out += p + "  default:\n";
        for (const StmtPtr& child : c.body) statement(*child, indent + 2, out);
        if (c.body.empty() && &c == &s.cases.back()) out += p + "    break;\n";  // GLSL wants a statement after the last label
      }
      out += p + "}\n";
      return;
    }
    case StmtKind::kBreak: out += p + "break;\n"; return;
    case StmtKind::kContinue: out += p + "continue;\n"; return;
    case StmtKind::kReturn: out += p + "return" + (s.expression ? " " + expr(*s.expression) : std::string()) + ";\n"; return;
    case StmtKind::kDiscard:
      if (stage_ != Stage::kPixel) error(s.location, "'discard' is only allowed in a pixel shader");
      uses_discard = true;
      out += p + "discard;\n";
      return;
  }
}

void GlslWriter::function(const FunctionDecl& f, std::string& out) {
  line_directive(f.location, out);
  const std::string* name = names_.of(&f);
  out += type(f.resolved) + " " + (name ? *name : f.name) + "(";
  for (std::size_t i = 0; i < f.parameters.size(); ++i) {
    const VariableDecl& p = f.parameters[i];
    bool in = (p.qualifiers & kQualIn) != 0, o = (p.qualifiers & kQualOut) != 0;
    std::string qualifier = in && o ? "inout " : o ? "out " : "";
    out += (i ? ", " : "") + qualifier + type(p.resolved) + " " + name_of(p) + array_suffix(p.resolved);
  }
  out += ")";
  if (!f.body) {
    out += ";\n";
    return;
  }
  out += "\n";
  std::string body;
  statement(*f.body, 0, body);
  // The temporaries its expressions needed, declared first in the body's block.
  std::size_t open = body.find("{\n");
  if (open != std::string::npos) body.insert(open + 2, take_temporaries(1));
  out += body;
}

}  // namespace pfx::fx

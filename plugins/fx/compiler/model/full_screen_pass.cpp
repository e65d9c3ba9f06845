#include "full_screen_pass.hpp"

#include <cctype>
#include <string>

namespace pfx::fx {
namespace {

constexpr const char* kStandard = "PostProcessVS";

bool has_semantic(const VariableDecl& v, const char* semantic) {
  const std::string& s = v.semantic;
  std::string upper;
  for (char c : s) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return upper == semantic;
}

// The variable an argument names, through an implicit conversion the analysis put around it.
const VariableDecl* named(const Expr* e) {
  while (e && e->kind == ExprKind::kCast && e->implicit && e->operands.size() == 1) e = e->operands[0].get();
  return e && e->kind == ExprKind::kName ? e->variable : nullptr;
}

// The call `PostProcessVS(id, position, ...)` as a statement.
bool is_standard_call(const Stmt& s, const VariableDecl* id, const VariableDecl* position) {
  if (s.kind != StmtKind::kExpression || !s.expression) return false;
  const Expr& call = *s.expression;
  return call.kind == ExprKind::kCall && call.function && call.function->name == kStandard && call.operands.size() >= 2 &&
         named(call.operands[0].get()) == id && named(call.operands[1].get()) == position;
}

// How often the expression names either variable.
int uses(const Expr* e, const VariableDecl* a, const VariableDecl* b) {
  if (!e) return 0;
  int n = (e->kind == ExprKind::kName && (e->variable == a || e->variable == b)) ? 1 : 0;
  for (const auto& operand : e->operands) n += uses(operand.get(), a, b);
  return n;
}

// How often the statement names either variable; `returns` is set by a return statement.
int uses(const Stmt* s, const VariableDecl* a, const VariableDecl* b, bool* returns) {
  if (!s) return 0;
  if (s->kind == StmtKind::kReturn) *returns = true;
  int n = uses(s->expression.get(), a, b) + uses(s->increment.get(), a, b) + uses(s->init.get(), a, b, returns) +
          uses(s->body.get(), a, b, returns) + uses(s->else_body.get(), a, b, returns);
  for (const auto& inner : s->statements) n += uses(inner.get(), a, b, returns);
  for (const auto& v : s->variables) n += uses(v.initializer.get(), a, b);
  for (const auto& c : s->cases)
    for (const auto& inner : c.body) n += uses(inner.get(), a, b, returns);
  return n;
}

}  // namespace

bool draws_full_screen_triangle(const FunctionDecl* vs) {
  if (!vs) return false;
  if (vs->name == kStandard) return true;
  if (!vs->body) return false;
  const VariableDecl *id = nullptr, *position = nullptr;
  for (const VariableDecl& p : vs->parameters) {
    if (has_semantic(p, "SV_VERTEXID")) id = &p;
    if (has_semantic(p, "SV_POSITION") && (p.qualifiers & kQualOut)) position = &p;
  }
  if (!id || !position) return false;
  int calls = 0;
  for (const auto& s : vs->body->statements) calls += is_standard_call(*s, id, position) ? 1 : 0;
  bool returns = false;
  // The one call names each once; any other mention could move the position or change the id.
  return calls == 1 && uses(vs->body.get(), id, position, &returns) == 2 && !returns;
}

bool covers_back_buffer(const PassInfo& pass, bool may_discard) {
  return draws_full_screen_triangle(pass.vertex_shader) && !pass.blend[0].enable && pass.blend[0].write_mask == 0xF && !may_discard &&
         pass.vertex_count == 3 && pass.topology == Topology::kTriangleList && !pass.stencil.enable;
}

}  // namespace pfx::fx

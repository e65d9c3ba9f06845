// Global declarations: namespaces, structs, functions, variables (with semantics, annotations,
// initialisers and texture/sampler/storage state blocks).
#include "nesting_guard.hpp"
#include "parser.hpp"

namespace pfx::fx {

void Parser::parse_declarations(std::vector<DeclPtr>& out, bool in_namespace) {
  while (!stopped()) {
    if (peek().kind == TokenKind::kEnd || (in_namespace && at(Punct::kRightBrace))) return;
    if (accept(Punct::kSemicolon)) continue;
    std::size_t before = position_;
    DeclPtr declaration = parse_declaration();
    if (declaration) {
      out.push_back(std::move(declaration));
      continue;
    }
    recover(before, false);
  }
}


DeclPtr Parser::parse_declaration() {
  NestingGuard guard(*this);
  if (!guard.ok()) return nullptr;
  if (at_word("namespace")) return parse_namespace();
  if (at_word("struct")) return parse_struct();
  if (at_word("technique")) return parse_technique();
  std::vector<Attribute> attributes;
  if (!parse_attributes(attributes)) return nullptr;
  return parse_function_or_variables(std::move(attributes));
}

DeclPtr Parser::parse_namespace() {
  auto declaration = std::make_unique<Decl>();
  declaration->kind = DeclKind::kNamespace;
  declaration->location = advance().location;
  if (!expect_identifier(declaration->namespace_name, "a namespace name") ||
      !expect(Punct::kLeftBrace, "to open the namespace"))
    return nullptr;
  std::string outer = namespace_prefix_;
  namespace_prefix_ += declaration->namespace_name + "::";
  parse_declarations(declaration->members, true);
  namespace_prefix_ = outer;
  if (!expect(Punct::kRightBrace, "to close the namespace")) return nullptr;
  return declaration;
}

DeclPtr Parser::parse_struct() {
  auto declaration = std::make_unique<Decl>();
  declaration->kind = DeclKind::kStruct;
  declaration->location = advance().location;
  declaration->structure = std::make_unique<StructDecl>();
  StructDecl& structure = *declaration->structure;
  structure.location = declaration->location;
  if (!expect_identifier(structure.name, "a struct name")) return nullptr;
  struct_names_.insert(structure.name);
  struct_names_.insert(namespace_prefix_ + structure.name);
  if (!expect(Punct::kLeftBrace, "to open the struct")) return nullptr;
  while (!accept(Punct::kRightBrace)) {
    if (peek().kind == TokenKind::kEnd) return error_at(structure.location, "struct is never closed"), nullptr;
    unsigned qualifiers = parse_qualifiers();
    TypeSyntax type;
    if (!parse_type(type) || !parse_declarators(qualifiers, type, false, structure.fields)) return nullptr;
    if (!expect(Punct::kSemicolon, "after a struct member")) return nullptr;
  }
  if (!expect(Punct::kSemicolon, "after a struct")) return nullptr;
  return declaration;
}

DeclPtr Parser::parse_function_or_variables(std::vector<Attribute> attributes) {
  auto declaration = std::make_unique<Decl>();
  declaration->location = peek().location;
  unsigned qualifiers = parse_qualifiers();
  TypeSyntax type;
  if (!at_type() && !(peek().kind == TokenKind::kIdentifier && peek(1).kind == TokenKind::kIdentifier)) {
    error_here("expected a declaration");
    return nullptr;
  }
  if (!parse_type(type)) return nullptr;
  if (peek().kind == TokenKind::kIdentifier && at(Punct::kLeftParen, 1)) {
    declaration->kind = DeclKind::kFunction;
    declaration->function = std::make_unique<FunctionDecl>();
    FunctionDecl& function = *declaration->function;
    function.location = peek().location;
    function.qualifiers = qualifiers;
    function.attributes = std::move(attributes);
    function.return_type = type;
    function.name = advance().text;
    if (!parse_function_rest(function)) return nullptr;
    return declaration;
  }
  declaration->kind = DeclKind::kVariables;
  if (!parse_declarators(qualifiers, type, true, declaration->variables)) return nullptr;
  bool state_block = declaration->variables.back().has_state_block;  // "texture t { ... }" may end there
  if (!accept(Punct::kSemicolon) && !state_block) return error_here("expected ';' after a declaration"), nullptr;
  return declaration;
}

bool Parser::parse_function_rest(FunctionDecl& function) {
  advance();  // (
  if (at_word("void") && at(Punct::kRightParen, 1)) advance();
  while (!accept(Punct::kRightParen)) {
    VariableDecl parameter;
    if (!parse_parameter(parameter)) return false;
    function.parameters.push_back(std::move(parameter));
    if (!at(Punct::kRightParen) && !expect(Punct::kComma, "or ')' in parameter list")) return false;
  }
  if (!parse_semantic(function.return_semantic)) return false;
  if (accept(Punct::kSemicolon)) return true;  // a prototype
  if (!at(Punct::kLeftBrace)) return error_here("expected '{' to open the function body"), false;
  function.body = parse_block();
  return function.body != nullptr;
}

bool Parser::parse_parameter(VariableDecl& parameter) {
  parameter.location = peek().location;
  parameter.qualifiers = parse_qualifiers();
  if (!parse_type(parameter.type)) return false;
  if (!expect_identifier(parameter.name, "a parameter name")) return false;
  if (!parse_array_sizes(parameter.array_sizes) || !parse_semantic(parameter.semantic)) return false;
  if (accept(Punct::kAssign)) {
    parameter.initializer = parse_assignment();
    if (!parameter.initializer) return false;
  }
  return true;
}

bool Parser::parse_declarators(unsigned qualifiers, const TypeSyntax& type, bool global,
                               std::vector<VariableDecl>& out) {
  do {
    VariableDecl variable;
    variable.qualifiers = qualifiers;
    variable.type = type;
    if (!parse_declarator(variable, global)) return false;
    out.push_back(std::move(variable));
  } while (accept(Punct::kComma));
  return true;
}

bool Parser::parse_declarator(VariableDecl& variable, bool global) {
  variable.location = peek().location;
  if (!expect_identifier(variable.name, "a variable name")) return false;
  if (!parse_array_sizes(variable.array_sizes) || !parse_semantic(variable.semantic)) return false;
  bool assign_follows = false;
  if (at(Punct::kLess)) {
    if (!parse_annotations(variable.annotations)) return false;
    assign_follows = tokens_[position_ - 1].is(Punct::kGreaterEqual);  // "< ... >= 1.0"
  }
  if (global && variable.type.is_object() && at(Punct::kLeftBrace)) {
    variable.has_state_block = true;
    return parse_state_block(variable.states, false);
  }
  if (assign_follows || accept(Punct::kAssign)) {
    variable.initializer = parse_initializer();
    return variable.initializer != nullptr;
  }
  return true;
}

bool Parser::parse_array_sizes(std::vector<ExprPtr>& sizes) {
  while (accept(Punct::kLeftBracket)) {
    if (accept(Punct::kRightBracket)) {
      sizes.push_back(nullptr);
      continue;
    }
    ExprPtr size = parse_conditional();
    if (!size || !expect(Punct::kRightBracket, "after an array size")) return false;
    sizes.push_back(std::move(size));
  }
  return true;
}

bool Parser::parse_semantic(std::string& semantic) {
  if (!accept(Punct::kColon)) return true;
  if (!expect_identifier(semantic, "a semantic after ':'")) return false;
  if ((semantic == "register" || semantic == "packoffset") && accept(Punct::kLeftParen)) {
    semantic.clear();  // D3D register bindings mean nothing here
    while (!accept(Punct::kRightParen))
      if (advance().kind == TokenKind::kEnd) return error_here("expected ')'"), false;
  }
  return true;
}

bool Parser::parse_annotations(std::vector<Annotation>& annotations) {
  advance();  // <
  while (!accept(Punct::kGreater) && !accept(Punct::kGreaterEqual)) {
    Annotation annotation;
    if (at_type() && peek(1).kind == TokenKind::kIdentifier) {  // "< string UIName = ...; >"
      TypeSyntax ignored;
      if (!parse_type(ignored)) return false;
    }
    annotation.location = peek().location;
    if (!expect_identifier(annotation.name, "an annotation name or '>'") ||
        !expect(Punct::kAssign, "after an annotation name"))
      return false;
    in_annotation_ = true;  // '>' ends the annotations, it is no comparison here
    annotation.value = parse_initializer();
    in_annotation_ = false;
    if (!annotation.value || !expect(Punct::kSemicolon, "after an annotation")) return false;
    annotations.push_back(std::move(annotation));
  }
  return true;
}

bool Parser::parse_state_block(std::vector<StateAssignment>& states, bool pass) {
  if (!expect(Punct::kLeftBrace, "to open a state block")) return false;
  while (!accept(Punct::kRightBrace)) {
    StateAssignment state;
    state.location = peek().location;
    if (!expect_identifier(state.name, "a state name") || !expect(Punct::kAssign, "after a state name")) return false;
    bool shader = pass && (state.name == "ComputeShader" || state.name == "VertexShader" ||
                           state.name == "PixelShader");
    if (shader) {
      // A function name, then for compute shaders the thread group size: Main<8, 8, 1>.
      auto name = std::make_unique<Expr>();
      name->kind = ExprKind::kName;
      name->location = peek().location;
      if (!parse_qualified_name(name->text)) return false;
      state.value = std::move(name);
      if (accept(Punct::kLess)) {
        do {
          ExprPtr size = parse_unary();
          if (!size) return false;
          state.thread_group.push_back(std::move(size));
        } while (accept(Punct::kComma));
        if (!expect(Punct::kGreater, "after the thread group size")) return false;
      }
    } else {
      state.value = parse_assignment();
      if (!state.value) return false;
    }
    if (!expect(Punct::kSemicolon, "after a state")) return false;
    states.push_back(std::move(state));
  }
  return true;
}

}  // namespace pfx::fx

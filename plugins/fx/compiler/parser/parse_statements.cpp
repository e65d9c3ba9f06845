// Statements: blocks, control flow, jumps, local declarations and expression statements, each
// optionally preceded by attributes ([unroll], [loop], [branch], [flatten], [fastopt] ...).
#include "nesting_guard.hpp"
#include "parser.hpp"

namespace pfx::fx {
namespace {

StmtPtr make(StmtKind kind, SourceLocation where) {
  auto statement = std::make_unique<Stmt>();
  statement->kind = kind;
  statement->location = where;
  return statement;
}

}  // namespace

bool Parser::parse_attributes(std::vector<Attribute>& attributes) {
  while (at(Punct::kLeftBracket)) {
    Attribute attribute;
    attribute.location = advance().location;
    if (!expect_identifier(attribute.name, "an attribute name")) return false;
    if (accept(Punct::kLeftParen) && !parse_arguments(attribute.arguments)) return false;
    if (!expect(Punct::kRightBracket, "after an attribute")) return false;
    attributes.push_back(std::move(attribute));
  }
  return true;
}

StmtPtr Parser::parse_statement() {
  NestingGuard guard(*this);
  if (!guard.ok()) return nullptr;
  std::vector<Attribute> attributes;
  if (!parse_attributes(attributes)) return nullptr;
  StmtPtr statement = parse_statement_body();
  if (statement) statement->attributes = std::move(attributes);
  return statement;
}

StmtPtr Parser::parse_statement_body() {
  const Token& token = peek();
  if (token.is(Punct::kLeftBrace)) return parse_block();
  if (token.is(Punct::kSemicolon)) return make(StmtKind::kEmpty, advance().location);
  if (token.is_identifier("if")) return parse_if();
  if (token.is_identifier("for")) return parse_for();
  if (token.is_identifier("while")) return parse_while();
  if (token.is_identifier("do")) return parse_do_while();
  if (token.is_identifier("switch")) return parse_switch();
  if (token.is_identifier("return") || token.is_identifier("break") || token.is_identifier("continue") ||
      token.is_identifier("discard"))
    return parse_jump();
  if (at_declaration()) return parse_local_declaration();
  StmtPtr statement = make(StmtKind::kExpression, token.location);
  statement->expression = parse_expression();
  if (!statement->expression || !expect(Punct::kSemicolon, "after an expression")) return nullptr;
  return statement;
}

StmtPtr Parser::parse_block() {
  StmtPtr block = make(StmtKind::kBlock, advance().location);
  while (!accept(Punct::kRightBrace)) {
    if (peek().kind == TokenKind::kEnd) {
      error_at(block->location, "'{' is never closed");
      return nullptr;
    }
    std::size_t start = position_;
    StmtPtr statement = parse_statement();
    if (stopped()) return nullptr;
    if (statement) block->statements.push_back(std::move(statement));
    else recover(start, true);
  }
  return block;
}

StmtPtr Parser::parse_if() {
  StmtPtr statement = make(StmtKind::kIf, advance().location);
  if (!expect(Punct::kLeftParen, "after 'if'")) return nullptr;
  statement->expression = parse_expression();
  if (!statement->expression || !expect(Punct::kRightParen, "after the condition")) return nullptr;
  statement->body = parse_statement();
  if (!statement->body) return nullptr;
  if (accept_word("else")) {
    statement->else_body = parse_statement();
    if (!statement->else_body) return nullptr;
  }
  return statement;
}

StmtPtr Parser::parse_for() {
  StmtPtr statement = make(StmtKind::kFor, advance().location);
  if (!expect(Punct::kLeftParen, "after 'for'")) return nullptr;
  if (at_declaration()) {
    statement->init = parse_local_declaration();  // takes the ';'
    if (!statement->init) return nullptr;
  } else if (!accept(Punct::kSemicolon)) {
    statement->init = make(StmtKind::kExpression, peek().location);
    statement->init->expression = parse_expression();
    if (!statement->init->expression || !expect(Punct::kSemicolon, "after the loop's initialisation")) return nullptr;
  }
  if (!at(Punct::kSemicolon)) {
    statement->expression = parse_expression();
    if (!statement->expression) return nullptr;
  }
  if (!expect(Punct::kSemicolon, "after the loop condition")) return nullptr;
  if (!at(Punct::kRightParen)) {
    statement->increment = parse_expression();
    if (!statement->increment) return nullptr;
  }
  if (!expect(Punct::kRightParen, "after the loop's increment")) return nullptr;
  statement->body = parse_statement();
  return statement->body ? std::move(statement) : nullptr;
}

StmtPtr Parser::parse_while() {
  StmtPtr statement = make(StmtKind::kWhile, advance().location);
  if (!expect(Punct::kLeftParen, "after 'while'")) return nullptr;
  statement->expression = parse_expression();
  if (!statement->expression || !expect(Punct::kRightParen, "after the condition")) return nullptr;
  statement->body = parse_statement();
  return statement->body ? std::move(statement) : nullptr;
}

StmtPtr Parser::parse_do_while() {
  StmtPtr statement = make(StmtKind::kDoWhile, advance().location);
  statement->body = parse_statement();
  if (!statement->body) return nullptr;
  if (!accept_word("while")) return error_here("expected 'while' after the body of 'do'"), nullptr;
  if (!expect(Punct::kLeftParen, "after 'while'")) return nullptr;
  statement->expression = parse_expression();
  if (!statement->expression || !expect(Punct::kRightParen, "after the condition") ||
      !expect(Punct::kSemicolon, "after 'do ... while (...)'"))
    return nullptr;
  return statement;
}

StmtPtr Parser::parse_switch() {
  StmtPtr statement = make(StmtKind::kSwitch, advance().location);
  if (!expect(Punct::kLeftParen, "after 'switch'")) return nullptr;
  statement->expression = parse_expression();
  if (!statement->expression || !expect(Punct::kRightParen, "after the switch value") ||
      !expect(Punct::kLeftBrace, "to open the switch body"))
    return nullptr;
  while (!accept(Punct::kRightBrace)) {
    if (!at_word("case") && !at_word("default")) return error_here("expected 'case' or 'default'"), nullptr;
    SwitchCase group;
    group.location = peek().location;
    while (at_word("case") || at_word("default")) {  // several labels share one body
      if (advance().text == "default") {
        group.has_default = true;
      } else {
        ExprPtr label = parse_conditional();
        if (!label) return nullptr;
        group.labels.push_back(std::move(label));
      }
      if (!expect(Punct::kColon, "after a case label")) return nullptr;
    }
    while (!at_word("case") && !at_word("default") && !at(Punct::kRightBrace)) {
      if (peek().kind == TokenKind::kEnd) return error_at(statement->location, "switch body is never closed"), nullptr;
      StmtPtr inner = parse_statement();
      if (!inner) return nullptr;
      group.body.push_back(std::move(inner));
    }
    statement->cases.push_back(std::move(group));
  }
  return statement;
}

StmtPtr Parser::parse_jump() {
  const Token& word = advance();
  StmtKind kind = word.text == "return" ? StmtKind::kReturn
                  : word.text == "break" ? StmtKind::kBreak
                  : word.text == "continue" ? StmtKind::kContinue
                                            : StmtKind::kDiscard;
  StmtPtr statement = make(kind, word.location);
  if (kind == StmtKind::kReturn && !at(Punct::kSemicolon)) {
    statement->expression = parse_expression();
    if (!statement->expression) return nullptr;
  }
  if (!expect(Punct::kSemicolon, ("after '" + word.text + "'").c_str())) return nullptr;
  return statement;
}

StmtPtr Parser::parse_local_declaration() {
  StmtPtr statement = make(StmtKind::kDeclaration, peek().location);
  unsigned qualifiers = parse_qualifiers();
  TypeSyntax type;
  if (!parse_type(type) || !parse_declarators(qualifiers, type, false, statement->variables)) return nullptr;
  if (!expect(Punct::kSemicolon, "after a declaration")) return nullptr;
  return statement;
}

}  // namespace pfx::fx

// Expressions, with HLSL's (C's) precedence from the comma operator down to postfix operators.
#include <cctype>

#include "../literals.hpp"
#include "../operator_precedence.hpp"
#include "nesting_guard.hpp"
#include "parser.hpp"

namespace pfx::fx {
namespace {

ExprPtr make(ExprKind kind, SourceLocation where) {
  auto expression = std::make_unique<Expr>();
  expression->kind = kind;
  expression->location = where;
  return expression;
}

bool assignment_operator(const Token& token) {
  if (token.kind != TokenKind::kPunct) return false;
  switch (token.punct) {
    case Punct::kAssign: case Punct::kPlusAssign: case Punct::kMinusAssign: case Punct::kStarAssign:
    case Punct::kSlashAssign: case Punct::kPercentAssign: case Punct::kAmpAssign: case Punct::kPipeAssign:
    case Punct::kCaretAssign: case Punct::kShiftLeftAssign: case Punct::kShiftRightAssign: return true;
    default: return false;
  }
}

// Counts the operators one loop chains, and gives them back when the loop's expression is done.
class ChainScope {
 public:
  explicit ChainScope(long& total) : total_(total) {}
  ~ChainScope() { total_ -= local_; }
  ChainScope(const ChainScope&) = delete;
  ChainScope& operator=(const ChainScope&) = delete;
  long& count() { return local_; }

 private:
  long& total_;
  long local_ = 0;
};

}  // namespace

ExprPtr Parser::parse_expression() {
  ExprPtr first = parse_assignment();
  if (!first || !at(Punct::kComma)) return first;
  ExprPtr sequence = make(ExprKind::kSequence, first->location);
  sequence->operands.push_back(std::move(first));
  while (accept(Punct::kComma)) {
    ExprPtr next = parse_assignment();
    if (!next) return nullptr;
    sequence->operands.push_back(std::move(next));
  }
  return sequence;
}

ExprPtr Parser::parse_assignment() {
  NestingGuard guard(*this);
  if (!guard.ok()) return nullptr;
  ExprPtr target = parse_conditional();
  if (!target || !assignment_operator(peek())) return target;
  const Token& op = advance();
  ExprPtr assignment = make(ExprKind::kAssign, op.location);
  assignment->op = op.punct;
  // ReShade takes a braced list as the value of a plain assignment too: a = { 1, 0, 1 };
  ExprPtr value = op.is(Punct::kAssign) && at(Punct::kLeftBrace) ? parse_initializer() : parse_assignment();
  if (!value) return nullptr;
  assignment->operands.push_back(std::move(target));
  assignment->operands.push_back(std::move(value));
  return assignment;
}

ExprPtr Parser::parse_conditional() {
  ExprPtr condition = parse_binary(0);
  if (!condition || !at(Punct::kQuestion)) return condition;
  ExprPtr select = make(ExprKind::kConditional, advance().location);
  ExprPtr yes = parse_expression();
  if (!yes || !expect(Punct::kColon, "in conditional expression")) return nullptr;
  ExprPtr no = parse_assignment();
  if (!no) return nullptr;
  select->operands.push_back(std::move(condition));
  select->operands.push_back(std::move(yes));
  select->operands.push_back(std::move(no));
  return select;
}

ExprPtr Parser::parse_binary(int level) {
  ExprPtr left = level > kTightestBinaryLevel ? parse_unary() : parse_binary(level + 1);
  ChainScope chain(chain_);
  while (left && binary_precedence(peek()) == level && level <= kTightestBinaryLevel) {
    if (in_annotation_ && (at(Punct::kGreater) || at(Punct::kGreaterEqual) || at(Punct::kShiftRight))) break;
    if (!extend_chain(chain.count())) return nullptr;
    const Token& op = advance();
    ExprPtr binary = make(ExprKind::kBinary, op.location);
    binary->op = op.punct;
    ExprPtr right = parse_binary(level + 1);
    if (!right) return nullptr;
    binary->operands.push_back(std::move(left));
    binary->operands.push_back(std::move(right));
    left = std::move(binary);
  }
  return left;
}

bool Parser::at_cast() const {
  if (!at(Punct::kLeftParen) || !at_type(1)) return false;
  std::size_t i = 1;
  if (peek(i).is(Punct::kColonColon)) ++i;
  while (peek(i).kind == TokenKind::kIdentifier && peek(i + 1).is(Punct::kColonColon)) i += 2;
  ++i;
  if (peek(i).is(Punct::kLess)) {  // vector<float, 2>
    while (peek(i).kind != TokenKind::kEnd && !peek(i).is(Punct::kGreater)) ++i;
    ++i;
  }
  return peek(i).is(Punct::kRightParen);
}

ExprPtr Parser::parse_unary() {
  NestingGuard guard(*this);
  if (!guard.ok()) return nullptr;
  const Token& token = peek();
  bool prefix = token.is(Punct::kMinus) || token.is(Punct::kPlus) || token.is(Punct::kBang) ||
                token.is(Punct::kTilde) || token.is(Punct::kPlusPlus) || token.is(Punct::kMinusMinus);
  if (prefix) {
    ExprPtr unary = make(ExprKind::kUnary, token.location);
    unary->op = advance().punct;
    ExprPtr operand = parse_unary();
    if (!operand) return nullptr;
    unary->operands.push_back(std::move(operand));
    return unary;
  }
  if (at_cast()) {
    ExprPtr cast = make(ExprKind::kCast, advance().location);
    if (!parse_type(cast->type) || !expect(Punct::kRightParen, "after the type of a cast")) return nullptr;
    ExprPtr operand = parse_unary();
    if (!operand) return nullptr;
    cast->operands.push_back(std::move(operand));
    return cast;
  }
  ExprPtr primary = parse_primary();
  return primary ? parse_postfix(std::move(primary)) : nullptr;
}

ExprPtr Parser::parse_postfix(ExprPtr expression) {
  ChainScope chain(chain_);
  while (expression) {
    const Token& token = peek();
    if (token.is(Punct::kDot) || token.is(Punct::kLeftBracket) || token.is(Punct::kPlusPlus) ||
        token.is(Punct::kMinusMinus) || token.is(Punct::kLeftParen))
      if (!extend_chain(chain.count())) return nullptr;
    if (token.is(Punct::kDot)) {
      ExprPtr member = make(ExprKind::kMember, advance().location);
      if (!expect_identifier(member->text, "a member name or swizzle after '.'")) return nullptr;
      member->operands.push_back(std::move(expression));
      expression = std::move(member);
    } else if (token.is(Punct::kLeftBracket)) {
      ExprPtr index = make(ExprKind::kIndex, advance().location);
      ExprPtr subscript = parse_expression();
      if (!subscript || !expect(Punct::kRightBracket, "after an index")) return nullptr;
      index->operands.push_back(std::move(expression));
      index->operands.push_back(std::move(subscript));
      expression = std::move(index);
    } else if (token.is(Punct::kPlusPlus) || token.is(Punct::kMinusMinus)) {
      ExprPtr postfix = make(ExprKind::kPostfix, token.location);
      postfix->op = advance().punct;
      postfix->operands.push_back(std::move(expression));
      expression = std::move(postfix);
    } else if (token.is(Punct::kLeftParen) && expression->kind == ExprKind::kName) {
      ExprPtr call = make(ExprKind::kCall, expression->location);
      call->text = expression->text;
      advance();
      if (!parse_arguments(call->operands)) return nullptr;
      expression = std::move(call);
    } else {
      break;
    }
  }
  return expression;
}

bool Parser::parse_arguments(std::vector<ExprPtr>& arguments) {
  // The '(' is already taken.
  if (accept(Punct::kRightParen)) return true;
  for (;;) {
    ExprPtr argument = parse_assignment();
    if (!argument) return false;
    arguments.push_back(std::move(argument));
    if (accept(Punct::kRightParen)) return true;
    if (!expect(Punct::kComma, "or ')' in argument list")) return false;
  }
}

ExprPtr Parser::parse_literal() {
  const Token& token = advance();
  if (token.kind == TokenKind::kString) {
    ExprPtr string = make(ExprKind::kString, token.location);
    std::string error;
    string->text = unescape_string(token.text, error);
    while (peek().kind == TokenKind::kString) string->text += unescape_string(advance().text, error);
    if (!error.empty()) error_at(token.location, error);
    return string;
  }
  std::string error;
  std::string spelling = token.text;
  std::string swizzle;
  auto number = parse_number(spelling, error);
  std::size_t dot = spelling.rfind('.');
  if (!number && dot != std::string::npos && dot + 1 < spelling.size() &&
      std::isalpha(static_cast<unsigned char>(spelling[dot + 1]))) {
    // "0.0.xxx": the lexer reads a swizzled literal as one number; split off the swizzle.
    std::string ignored;
    number = parse_number(spelling.substr(0, dot), ignored);
    if (number) swizzle = spelling.substr(dot + 1), spelling.resize(dot);
  }
  if (!number) {
    error_at(token.location, error);
    return nullptr;
  }
  bool integer = number->kind == NumberLiteral::Kind::kInt || number->kind == NumberLiteral::Kind::kUint;
  ExprPtr literal = make(integer ? ExprKind::kInt : ExprKind::kFloat, token.location);
  literal->number = *number;
  literal->text = spelling;
  if (swizzle.empty()) return literal;
  ExprPtr member = make(ExprKind::kMember, token.location);
  member->text = swizzle;
  member->operands.push_back(std::move(literal));
  return member;
}

ExprPtr Parser::parse_primary() {
  const Token& token = peek();
  if (token.kind == TokenKind::kNumber || token.kind == TokenKind::kString) return parse_literal();
  if (token.is_identifier("true") || token.is_identifier("false")) {
    ExprPtr literal = make(ExprKind::kBool, token.location);
    literal->boolean = advance().text == "true";
    literal->text = token.text;
    return literal;
  }
  if (token.is(Punct::kLeftParen)) {
    advance();
    ExprPtr inner = parse_expression();
    if (!inner || !expect(Punct::kRightParen, "to close '('")) return nullptr;
    return inner;
  }
  if (token.kind == TokenKind::kIdentifier && at_type() && !at(Punct::kColonColon, 1) &&
      (at(Punct::kLeftParen, 1) || at(Punct::kLess, 1))) {
    ExprPtr construct = make(ExprKind::kConstruct, token.location);
    if (!parse_type(construct->type) || !expect(Punct::kLeftParen, "after a type in a constructor")) return nullptr;
    if (!parse_arguments(construct->operands)) return nullptr;
    return construct;
  }
  if (token.kind == TokenKind::kIdentifier || token.is(Punct::kColonColon)) {
    ExprPtr name = make(ExprKind::kName, token.location);
    if (!parse_qualified_name(name->text)) return nullptr;
    return name;
  }
  error_here("expected an expression");
  return nullptr;
}

ExprPtr Parser::parse_initializer() {
  if (!at(Punct::kLeftBrace)) return parse_assignment();
  NestingGuard guard(*this);
  if (!guard.ok()) return nullptr;
  ExprPtr list = make(ExprKind::kInitList, advance().location);
  while (!accept(Punct::kRightBrace)) {
    ExprPtr element = parse_initializer();
    if (!element) return nullptr;
    list->operands.push_back(std::move(element));
    if (!at(Punct::kRightBrace) && !expect(Punct::kComma, "or '}' in initializer list")) return nullptr;
  }
  return list;
}

}  // namespace pfx::fx

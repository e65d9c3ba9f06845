#include "if_expression.hpp"

#include "../limits.hpp"
#include "../literals.hpp"
#include "../operator_precedence.hpp"

namespace pfx::fx {
namespace {

class IfEvaluator {
 public:
  IfEvaluator(const TokenList& tokens, SourceLocation directive, Diagnostics& diagnostics)
      : tokens_(tokens), directive_(directive), diagnostics_(diagnostics) {}

  std::optional<long long> run() {
    if (tokens_.empty()) return fail(directive_, "#if with no expression");
    long long value = conditional();
    if (!failed_ && position_ < tokens_.size()) fail(tokens_[position_].location, "unexpected '" + tokens_[position_].text + "' in #if expression");
    if (failed_) return std::nullopt;
    return value;
  }

 private:
  // Binary levels from loosest to tightest (operator_precedence.hpp).
  long long binary(int level) {
    if (level > kTightestBinaryLevel) return unary();
    long long left = binary(level + 1);
    while (!failed_ && position_ < tokens_.size()) {
      if (binary_precedence(tokens_[position_]) != level) break;
      Punct op = tokens_[position_].punct;
      SourceLocation where = tokens_[position_++].location;
      long long right = binary(level + 1);
      left = apply(op, left, right, where);
    }
    return left;
  }



  long long apply(Punct op, long long a, long long b, SourceLocation where) {
    using U = unsigned long long;
    switch (op) {
      case Punct::kPipePipe: return a || b;
      case Punct::kAmpAmp: return a && b;
      case Punct::kPipe: return a | b;
      case Punct::kCaret: return a ^ b;
      case Punct::kAmp: return a & b;
      case Punct::kEqualEqual: return a == b;
      case Punct::kBangEqual: return a != b;
      case Punct::kLess: return a < b;
      case Punct::kGreater: return a > b;
      case Punct::kLessEqual: return a <= b;
      case Punct::kGreaterEqual: return a >= b;
      case Punct::kShiftLeft: return (b < 0 || b > 63) ? (fail(where, "shift count out of range in #if"), 0) : static_cast<long long>(static_cast<U>(a) << b);
      case Punct::kShiftRight: return (b < 0 || b > 63) ? (fail(where, "shift count out of range in #if"), 0) : a >> b;
      case Punct::kPlus: return static_cast<long long>(static_cast<U>(a) + static_cast<U>(b));
      case Punct::kMinus: return static_cast<long long>(static_cast<U>(a) - static_cast<U>(b));
      case Punct::kStar: return static_cast<long long>(static_cast<U>(a) * static_cast<U>(b));
      case Punct::kSlash:
      case Punct::kPercent:
        if (b == 0) return fail(where, "division by zero in #if"), 0;
        if (a == INT64_MIN && b == -1) return op == Punct::kSlash ? a : 0;
        return op == Punct::kSlash ? a / b : a % b;
      default: return 0;
    }
  }

  long long conditional() {
    if (++depth_ > limits::kMaxIfExpressionNesting) return fail(here(), "#if expression nested too deeply"), 0;
    long long condition = binary(0);
    if (!failed_ && accept(Punct::kQuestion)) {
      long long yes = conditional();
      if (!accept(Punct::kColon)) return fail(here(), "expected ':' in #if expression"), 0;
      long long no = conditional();
      condition = condition ? yes : no;
    }
    --depth_;
    return condition;
  }

  long long unary() {
    if (failed_) return 0;
    if (position_ >= tokens_.size()) return fail(here(), "#if expression ends early"), 0;
    if (++depth_ > limits::kMaxIfExpressionNesting) return fail(here(), "#if expression nested too deeply"), 0;
    long long value = unary_body();
    --depth_;
    return value;
  }

  long long unary_body() {
    const Token& token = tokens_[position_++];
    if (token.is(Punct::kMinus)) return static_cast<long long>(0ull - static_cast<unsigned long long>(unary()));
    if (token.is(Punct::kPlus)) return unary();
    if (token.is(Punct::kBang)) return !unary();
    if (token.is(Punct::kTilde)) return ~unary();
    if (token.is(Punct::kLeftParen)) {
      long long value = conditional();
      if (!accept(Punct::kRightParen)) return fail(here(), "expected ')' in #if expression"), 0;
      return value;
    }
    if (token.kind == TokenKind::kIdentifier) return token.text == "true" ? 1 : 0;
    if (token.kind == TokenKind::kNumber) {
      std::string error;
      auto literal = parse_number(token.text, error, 64);  // wider than the language: a 64-bit hash
      if (!literal) return fail(token.location, error), 0;
      if (literal->kind != NumberLiteral::Kind::kInt && literal->kind != NumberLiteral::Kind::kUint)
        return fail(token.location, "floating-point literal in #if expression"), 0;
      return static_cast<long long>(literal->integer);
    }
    return fail(token.location, "unexpected '" + token.text + "' in #if expression"), 0;
  }

  bool accept(Punct punct) {
    if (position_ < tokens_.size() && tokens_[position_].is(punct)) return ++position_, true;
    return false;
  }

  SourceLocation here() const { return position_ < tokens_.size() ? tokens_[position_].location : directive_; }

  std::nullopt_t fail(SourceLocation where, const std::string& message) {
    if (!failed_) diagnostics_.error(where, message);
    failed_ = true;
    return std::nullopt;
  }

  const TokenList& tokens_;
  SourceLocation directive_;
  Diagnostics& diagnostics_;
  std::size_t position_ = 0;
  int depth_ = 0;
  bool failed_ = false;
};

}  // namespace

std::optional<long long> evaluate_if_expression(const TokenList& tokens, SourceLocation directive,
                                                Diagnostics& diagnostics) {
  return IfEvaluator(tokens, directive, diagnostics).run();
}

}  // namespace pfx::fx

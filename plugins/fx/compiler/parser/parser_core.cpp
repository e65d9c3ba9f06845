// The parser's token handling, errors and nesting limit.
#include "../limits.hpp"
#include "parser.hpp"

namespace pfx::fx {

Parser::Parser(const TokenList& tokens, Diagnostics& diagnostics) : tokens_(tokens), diagnostics_(diagnostics) {
  end_.kind = TokenKind::kEnd;
  end_.text = "end of file";
  if (!tokens.empty()) {
    end_.location = tokens.back().location;
    end_.location.column += static_cast<std::uint32_t>(tokens.back().text.size());
  }
}

TranslationUnit Parser::parse() {
  TranslationUnit unit;
  parse_declarations(unit.declarations, false);
  return unit;
}

const Token& Parser::peek(std::size_t ahead) const {
  std::size_t at = position_ + ahead;
  return at < tokens_.size() ? tokens_[at] : end_;
}

const Token& Parser::advance() {
  const Token& token = peek();
  if (position_ < tokens_.size()) ++position_;
  return token;
}

bool Parser::accept(Punct punct) {
  if (!at(punct)) return false;
  advance();
  return true;
}

bool Parser::accept_word(const char* word) {
  if (!at_word(word)) return false;
  advance();
  return true;
}

bool Parser::expect(Punct punct, const char* context) {
  if (accept(punct)) return true;
  error_here(std::string("expected '") + punct_spelling(punct) + "' " + context);
  return false;
}

bool Parser::expect_identifier(std::string& name, const char* what) {
  if (peek().kind != TokenKind::kIdentifier) {
    error_here(std::string("expected ") + what);
    return false;
  }
  name = advance().text;
  return true;
}

void Parser::error_here(const std::string& message) {
  const Token& token = peek();
  std::string found = token.kind == TokenKind::kEnd ? "end of file" : "'" + token.text + "'";
  if (token.kind == TokenKind::kUnknown) {
    error_at(token.location, "unexpected character '" + token.text + "'");
    return;
  }
  error_at(token.location, message + ", found " + found);
}

void Parser::error_at(SourceLocation where, const std::string& message) { diagnostics_.error(where, message); }

void Parser::recover(std::size_t start, bool inside_block) {
  // Skip the rest of the statement or declaration that failed: close every brace it opened, then
  // stop after its ';' or its last '}', so one mistake gives one error. Inside a block the '}'
  // that closes the block is left for the block.
  int braces = 0;
  for (std::size_t i = start; i < position_ && i < tokens_.size(); ++i) {
    if (tokens_[i].is(Punct::kLeftBrace)) ++braces;
    if (tokens_[i].is(Punct::kRightBrace) && braces > 0) --braces;
  }
  while (peek().kind != TokenKind::kEnd) {
    if (at(Punct::kRightBrace) && braces == 0) {
      if (!inside_block || position_ == start) advance();  // always make progress
      return;
    }
    const Token& token = advance();
    if (token.is(Punct::kLeftBrace)) ++braces;
    if (token.is(Punct::kRightBrace) && --braces == 0) {
      accept(Punct::kSemicolon);
      return;
    }
    if (token.is(Punct::kSemicolon) && braces == 0) return;
  }
}

bool Parser::enter() {
  if (failed_nesting_) return false;
  if (++depth_ > limits::kMaxSyntaxNesting) {
    error_at(peek().location, "nesting deeper than " + std::to_string(limits::kMaxSyntaxNesting) + " levels");
    failed_nesting_ = true;
    return false;
  }
  return true;
}

bool Parser::extend_chain(long& local) {
  ++local;
  if (++chain_ <= limits::kMaxOperatorChain) return true;
  error_at(peek().location, "more than " + std::to_string(limits::kMaxOperatorChain) + " operators in a row");
  failed_nesting_ = true;
  return false;
}

TranslationUnit parse_tokens(const TokenList& tokens, Diagnostics& diagnostics) {
  return Parser(tokens, diagnostics).parse();
}

}  // namespace pfx::fx

#include "lexer.hpp"

#include <cctype>

#include "limits.hpp"

namespace pfx::fx {
namespace {

bool is_identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Length of a backslash-newline at `p` (0 if there is none).
std::size_t continuation_at(std::string_view s, std::size_t p) {
  if (p >= s.size() || s[p] != '\\') return 0;
  if (p + 1 < s.size() && s[p + 1] == '\n') return 2;
  if (p + 2 < s.size() && s[p + 1] == '\r' && s[p + 2] == '\n') return 3;
  return 0;
}

}  // namespace

Lexer::Lexer(std::string_view source, std::uint32_t file, Diagnostics& diagnostics)
    : source_(source), file_(file), diagnostics_(diagnostics) {
  // A UTF-8 byte order mark, as editors on Windows write it, is not part of the text.
  if (source_.substr(0, 3) == "\xEF\xBB\xBF") position_ = 3;
}

char Lexer::peek(std::size_t ahead) {
  std::size_t p = position_;
  for (;;) {
    while (std::size_t n = continuation_at(source_, p)) p += n;
    if (p >= source_.size()) return '\0';
    if (ahead == 0) return source_[p];
    ++p;
    --ahead;
  }
}

void Lexer::skip_continuations() {
  while (std::size_t n = continuation_at(source_, position_)) {
    position_ += n;
    ++line_;
    column_ = 1;
  }
}

char Lexer::take() {
  skip_continuations();
  if (position_ >= source_.size()) return '\0';
  char c = source_[position_++];
  if (c == '\n') {
    ++line_;
    column_ = 1;
  } else {
    ++column_;
  }
  return c;
}

bool Lexer::skip_space_and_comments(bool& saw_space, bool& saw_newline) {
  for (;;) {
    char c = peek();
    if (c == '\n') {
      saw_newline = true;
      saw_space = true;
      take();
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      saw_space = true;
      take();
    } else if (c == '/' && peek(1) == '/') {
      while (peek() != '\n' && peek() != '\0') take();
      saw_space = true;
    } else if (c == '/' && peek(1) == '*') {
      skip_continuations();
      SourceLocation start{file_, static_cast<std::uint32_t>(line_ + line_offset_), static_cast<std::uint32_t>(column_)};
      take();
      take();
      for (;;) {
        if (peek() == '\0') {
          diagnostics_.error(start, "unterminated comment");
          return false;
        }
        if (peek() == '*' && peek(1) == '/') break;
        take();
      }
      take();
      take();
      saw_space = true;
    } else {
      return true;
    }
  }
}

Token Lexer::next() {
  Token token;
  bool saw_space = false, saw_newline = false;
  skip_space_and_comments(saw_space, saw_newline);
  skip_continuations();
  token.space_before = saw_space || at_line_start_;  // a file boundary separates tokens too
  token.line_start = at_line_start_ || saw_newline;
  at_line_start_ = false;
  token.location = {file_, static_cast<std::uint32_t>(line_ + line_offset_), static_cast<std::uint32_t>(column_)};
  char c = peek();
  if (c == '\0') {
    token.kind = TokenKind::kEnd;
    token.line_start = true;
    return token;
  }
  if (is_identifier_start(c)) {
    token.kind = TokenKind::kIdentifier;
    while (is_identifier_char(peek())) token.text += take();
  } else if (is_digit(c) || (c == '.' && is_digit(peek(1)))) {
    lex_number(token);
  } else if (c == '"') {
    lex_string(token);
  } else {
    lex_punct(token);
  }
  return token;
}

void Lexer::lex_number(Token& token) {
  // A preprocessing number: digits, letters, dots and signed exponents. literals.cpp decides
  // whether it is a valid integer or float literal.
  token.kind = TokenKind::kNumber;
  for (;;) {
    char c = peek();
    if ((c == '+' || c == '-') && !token.text.empty()) {
      char last = token.text.back();
      bool hex = token.text.size() > 1 && (token.text[1] == 'x' || token.text[1] == 'X');
      if ((last == 'e' || last == 'E') && !hex) {
        token.text += take();
        continue;
      }
      return;
    }
    if (!is_identifier_char(c) && c != '.') return;
    token.text += take();
  }
}

void Lexer::lex_string(Token& token) {
  token.kind = TokenKind::kString;
  token.text += take();
  for (;;) {
    char c = peek();
    if (c == '\0' || c == '\n') {
      if (!quiet_) diagnostics_.error(token.location, "unterminated string literal");
      token.text += '"';
      return;
    }
    if (token.text.size() > limits::kMaxStringBytes) {
      diagnostics_.error(token.location, "string literal longer than " + std::to_string(limits::kMaxStringBytes) + " bytes");
      while (peek() != '\0' && peek() != '\n' && peek() != '"') take();
      if (peek() == '"') take();
      token.text += '"';
      return;
    }
    token.text += take();
    if (c == '\\' && peek() != '\0' && peek() != '\n') token.text += take();
    if (c == '"' && token.text.size() > 1) return;
  }
}

void Lexer::lex_punct(Token& token) {
  // Longest match first: three-character operators, then two, then one.
  static const struct {
    const char* spelling;
    Punct punct;
  } table[] = {
      {"<<=", Punct::kShiftLeftAssign}, {">>=", Punct::kShiftRightAssign}, {"...", Punct::kEllipsis},
      {"::", Punct::kColonColon}, {"++", Punct::kPlusPlus}, {"--", Punct::kMinusMinus}, {"&&", Punct::kAmpAmp},
      {"||", Punct::kPipePipe}, {"<<", Punct::kShiftLeft}, {">>", Punct::kShiftRight}, {"<=", Punct::kLessEqual},
      {">=", Punct::kGreaterEqual}, {"==", Punct::kEqualEqual}, {"!=", Punct::kBangEqual}, {"+=", Punct::kPlusAssign},
      {"-=", Punct::kMinusAssign}, {"*=", Punct::kStarAssign}, {"/=", Punct::kSlashAssign},
      {"%=", Punct::kPercentAssign}, {"&=", Punct::kAmpAssign}, {"|=", Punct::kPipeAssign},
      {"^=", Punct::kCaretAssign}, {"##", Punct::kHashHash}, {"{", Punct::kLeftBrace}, {"}", Punct::kRightBrace},
      {"[", Punct::kLeftBracket}, {"]", Punct::kRightBracket}, {"(", Punct::kLeftParen}, {")", Punct::kRightParen},
      {";", Punct::kSemicolon}, {",", Punct::kComma}, {".", Punct::kDot}, {":", Punct::kColon},
      {"?", Punct::kQuestion}, {"+", Punct::kPlus}, {"-", Punct::kMinus}, {"*", Punct::kStar}, {"/", Punct::kSlash},
      {"%", Punct::kPercent}, {"&", Punct::kAmp}, {"|", Punct::kPipe}, {"^", Punct::kCaret}, {"~", Punct::kTilde},
      {"!", Punct::kBang}, {"<", Punct::kLess}, {">", Punct::kGreater}, {"=", Punct::kAssign}, {"#", Punct::kHash},
  };
  for (const auto& entry : table) {
    std::size_t length = std::char_traits<char>::length(entry.spelling);
    bool match = true;
    for (std::size_t i = 0; i < length && match; ++i) match = peek(i) == entry.spelling[i];
    if (!match) continue;
    for (std::size_t i = 0; i < length; ++i) token.text += take();
    token.kind = TokenKind::kPunct;
    token.punct = entry.punct;
    return;
  }
  token.kind = TokenKind::kUnknown;
  token.text += take();
}

TokenList lex_all(std::string_view source, std::uint32_t file, Diagnostics& diagnostics) {
  Lexer lexer(source, file, diagnostics);
  TokenList tokens;
  for (Token t = lexer.next(); t.kind != TokenKind::kEnd; t = lexer.next()) tokens.push_back(std::move(t));
  return tokens;
}

}  // namespace pfx::fx

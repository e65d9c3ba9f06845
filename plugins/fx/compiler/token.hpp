#pragma once
// The tokens shared by the preprocessor and the parser. The preprocessor works on these directly
// (not on text), which is how a location survives macro expansion and #include.
#include <cstdint>
#include <string>
#include <vector>

#include "source_location.hpp"

namespace pfx::fx {

enum class TokenKind : std::uint8_t {
  kEnd,         // end of input
  kIdentifier,  // also keywords: the parser tells them apart (keywords.hpp)
  kNumber,      // a preprocessing number; literals.hpp turns it into a value
  kString,      // the spelling with its quotes and escapes
  kPunct,
  kUnknown,  // a character the language has no use for; an error only if the parser sees it
};

enum class Punct : std::uint8_t {
  kNone,
  kLeftBrace, kRightBrace, kLeftBracket, kRightBracket, kLeftParen, kRightParen,
  kSemicolon, kComma, kDot, kColon, kColonColon, kQuestion,
  kPlus, kMinus, kStar, kSlash, kPercent, kPlusPlus, kMinusMinus,
  kAmp, kPipe, kCaret, kTilde, kBang, kAmpAmp, kPipePipe, kShiftLeft, kShiftRight,
  kLess, kGreater, kLessEqual, kGreaterEqual, kEqualEqual, kBangEqual,
  kAssign, kPlusAssign, kMinusAssign, kStarAssign, kSlashAssign, kPercentAssign,
  kAmpAssign, kPipeAssign, kCaretAssign, kShiftLeftAssign, kShiftRightAssign,
  kHash, kHashHash, kEllipsis,
};

const char* punct_spelling(Punct punct);

struct Token {
  TokenKind kind = TokenKind::kEnd;
  Punct punct = Punct::kNone;
  bool space_before = false;  // for stringizing and for printing preprocessed text
  bool line_start = false;    // first token of a line: where a directive may begin
  std::string text;           // spelling as written (for kPunct: the operator)
  SourceLocation location;
  std::vector<std::uint32_t> hide_set;  // macros that must not expand this token again (sorted)

  bool is(Punct p) const { return kind == TokenKind::kPunct && punct == p; }
  bool is_identifier(const char* name) const { return kind == TokenKind::kIdentifier && text == name; }
};

using TokenList = std::vector<Token>;

// Tokens back to text, one space where the source had space; used for #error, stringizing and dumps.
std::string spell(const TokenList& tokens);

}  // namespace pfx::fx

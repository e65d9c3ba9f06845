#include "token.hpp"

namespace pfx::fx {

const char* punct_spelling(Punct punct) {
  switch (punct) {
    case Punct::kNone: return "";
    case Punct::kLeftBrace: return "{";
    case Punct::kRightBrace: return "}";
    case Punct::kLeftBracket: return "[";
    case Punct::kRightBracket: return "]";
    case Punct::kLeftParen: return "(";
    case Punct::kRightParen: return ")";
    case Punct::kSemicolon: return ";";
    case Punct::kComma: return ",";
    case Punct::kDot: return ".";
    case Punct::kColon: return ":";
    case Punct::kColonColon: return "::";
    case Punct::kQuestion: return "?";
    case Punct::kPlus: return "+";
    case Punct::kMinus: return "-";
    case Punct::kStar: return "*";
    case Punct::kSlash: return "/";
    case Punct::kPercent: return "%";
    case Punct::kPlusPlus: return "++";
    case Punct::kMinusMinus: return "--";
    case Punct::kAmp: return "&";
    case Punct::kPipe: return "|";
    case Punct::kCaret: return "^";
    case Punct::kTilde: return "~";
    case Punct::kBang: return "!";
    case Punct::kAmpAmp: return "&&";
    case Punct::kPipePipe: return "||";
    case Punct::kShiftLeft: return "<<";
    case Punct::kShiftRight: return ">>";
    case Punct::kLess: return "<";
    case Punct::kGreater: return ">";
    case Punct::kLessEqual: return "<=";
    case Punct::kGreaterEqual: return ">=";
    case Punct::kEqualEqual: return "==";
    case Punct::kBangEqual: return "!=";
    case Punct::kAssign: return "=";
    case Punct::kPlusAssign: return "+=";
    case Punct::kMinusAssign: return "-=";
    case Punct::kStarAssign: return "*=";
    case Punct::kSlashAssign: return "/=";
    case Punct::kPercentAssign: return "%=";
    case Punct::kAmpAssign: return "&=";
    case Punct::kPipeAssign: return "|=";
    case Punct::kCaretAssign: return "^=";
    case Punct::kShiftLeftAssign: return "<<=";
    case Punct::kShiftRightAssign: return ">>=";
    case Punct::kHash: return "#";
    case Punct::kHashHash: return "##";
    case Punct::kEllipsis: return "...";
  }
  return "";
}

std::string spell(const TokenList& tokens) {
  std::string text;
  for (const Token& t : tokens) {
    if (!text.empty() && t.space_before) text += ' ';
    text += t.text;
  }
  return text;
}

}  // namespace pfx::fx

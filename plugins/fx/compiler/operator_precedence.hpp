#pragma once
// C's (and HLSL's) binary operator precedence, shared by the #if evaluator and the parser:
// 0 for ||, the loosest, up to kTightestBinaryLevel for * / %; -1 for a token that is no binary
// operator.
#include "token.hpp"

namespace pfx::fx {

inline constexpr int kTightestBinaryLevel = 9;

inline int binary_precedence(const Token& token) {
  if (token.kind != TokenKind::kPunct) return -1;
  switch (token.punct) {
    case Punct::kPipePipe: return 0;
    case Punct::kAmpAmp: return 1;
    case Punct::kPipe: return 2;
    case Punct::kCaret: return 3;
    case Punct::kAmp: return 4;
    case Punct::kEqualEqual: case Punct::kBangEqual: return 5;
    case Punct::kLess: case Punct::kGreater: case Punct::kLessEqual: case Punct::kGreaterEqual: return 6;
    case Punct::kShiftLeft: case Punct::kShiftRight: return 7;
    case Punct::kPlus: case Punct::kMinus: return 8;
    case Punct::kStar: case Punct::kSlash: case Punct::kPercent: return 9;
    default: return -1;
  }
}

}  // namespace pfx::fx

#pragma once
// Evaluates the integer constant expression of #if/#elif after macro expansion, with C's
// operators and precedence in 64-bit signed arithmetic. Identifiers left after expansion are 0
// (true and false are 1 and 0). Division by zero and malformed expressions are errors.
#include <optional>

#include "../diagnostics.hpp"
#include "../token.hpp"

namespace pfx::fx {

std::optional<long long> evaluate_if_expression(const TokenList& tokens, SourceLocation directive,
                                                Diagnostics& diagnostics);

}  // namespace pfx::fx

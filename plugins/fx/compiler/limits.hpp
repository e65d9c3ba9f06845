#pragma once
// Bounds that keep malformed or hostile input from hanging the compiler or exhausting its stack or
// memory. Each one has a message of its own where it is enforced, naming the limit.
#include <cstddef>

namespace pfx::fx::limits {

inline constexpr std::size_t kMaxSourceBytes = 16u << 20;          // one file
inline constexpr int kMaxIncludeDepth = 64;                         // nested #include
inline constexpr int kMaxConditionalDepth = 256;                    // nested #if
inline constexpr std::size_t kMaxOutputTokens = 1u << 20;           // preprocessed tokens of one effect
inline constexpr std::size_t kMaxExpansionTokens = 4u << 20;        // tokens produced by macro expansion
inline constexpr std::size_t kMaxMacroArguments = 256;              // arguments of one macro use
inline constexpr int kMaxSyntaxNesting = 256;                       // nested expressions, statements, blocks
// Operators chained at one level ("a + b + c ...", "a[0][1].x") deepen the tree without nesting:
// bounded separately so walking the tree recursively stays within the stack.
inline constexpr long kMaxOperatorChain = 1024;
inline constexpr int kMaxIfExpressionNesting = 256;                 // parentheses in an #if expression
inline constexpr std::size_t kMaxErrors = 100;                      // then "too many errors" and stop
inline constexpr long long kMaxArrayElements = 1 << 20;             // one array
inline constexpr long long kMaxTextureSize = 16384;               // Width, Height, Depth
inline constexpr std::size_t kMaxStringBytes = 1u << 20;            // one string literal

}  // namespace pfx::fx::limits

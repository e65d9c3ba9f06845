#pragma once
// Where a token came from. Tokens produced by a macro expansion carry the location of the macro's
// use in the file being compiled, so every error points at a line the user wrote.
#include <cstdint>

namespace pfx::fx {

struct SourceLocation {
  std::uint32_t file = 0;    // index into SourceFiles' names (#line may add names)
  std::uint32_t line = 0;    // 1-based; 0 means "no location"
  std::uint32_t column = 0;  // 1-based, in bytes
};

}  // namespace pfx::fx

// Cutting an OBJ text into chunks that can be parsed independently: every cut falls right after a
// line end that does not end a continued line (a backslash before it), so no statement is split.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace pfx_obj {

// About `count` chunks of similar size (fewer when the text has fewer line ends); their
// concatenation is the text. An empty text gives one empty chunk.
std::vector<std::string_view> split_at_line_ends(std::string_view text, size_t count);

}  // namespace pfx_obj

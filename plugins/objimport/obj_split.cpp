#include "obj_split.hpp"

#include "obj_text.hpp"

namespace pfx_obj {

namespace {

// The position just after the first line end at or after `from` that is not a continuation, or
// text.size() when there is none.
size_t next_cut(std::string_view text, size_t from) {
  const size_t n = text.size();
  size_t i = from;
  // Never cut between the CR and LF of one line end.
  if (i > 0 && i < n && text[i] == '\n' && text[i - 1] == '\r') ++i;
  for (; i < n; ++i) {
    if (!is_line_end(text[i])) continue;
    const size_t start = i;  // first byte of this line end
    size_t after = (text[i] == '\r' && i + 1 < n && text[i + 1] == '\n') ? i + 2 : i + 1;
    if (start > 0 && text[start - 1] == '\\') {  // a continued line: keep looking
      i = after - 1;
      continue;
    }
    return after;
  }
  return n;
}

}  // namespace

std::vector<std::string_view> split_at_line_ends(std::string_view text, size_t count) {
  std::vector<std::string_view> chunks;
  if (count < 1) count = 1;
  const size_t step = text.size() / count;
  size_t begin = 0;
  for (size_t k = 1; k < count && begin < text.size(); ++k) {
    size_t target = k * step;
    if (target <= begin) continue;
    size_t cut = next_cut(text, target);
    if (cut >= text.size()) break;
    chunks.push_back(text.substr(begin, cut - begin));
    begin = cut;
  }
  chunks.push_back(text.substr(begin));
  return chunks;
}

}  // namespace pfx_obj

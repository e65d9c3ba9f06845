#include "frame_pattern.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace pfx::app {

namespace {

bool parse_frame_number(const std::string& text, long long* out) {
  if (text.empty() || text.size() > 9) return false;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  *out = std::stoll(text);
  return true;
}

// One token found at `at`: its length and padding; 0 length when none starts there. A `%` that
// starts no token sets *bad_percent.
struct Token {
  size_t length = 0;
  int width = 0;
};

Token token_at(const std::string& path, size_t at, bool* bad_percent) {
  const char c = path[at];
  if (c == '#' || c == '@') {
    size_t end = at;
    while (end < path.size() && path[end] == c) ++end;
    return {end - at, static_cast<int>(end - at)};
  }
  if (c != '%') return {};
  // %d, or %0Nd with one digit N from 1 to 9.
  if (at + 1 < path.size() && path[at + 1] == 'd') return {2, 0};
  if (at + 3 < path.size() && path[at + 1] == '0' && path[at + 2] >= '1' && path[at + 2] <= '9' &&
      path[at + 3] == 'd')
    return {4, path[at + 2] - '0'};
  *bad_percent = true;
  return {};
}

}  // namespace

bool parse_frame_range(const std::string& text, FrameRange* out, std::string* error) {
  const std::string what = "--frames " + text + ": ";
  std::string range = text, step_text;
  if (const size_t x = text.find('x'); x != std::string::npos) {
    range = text.substr(0, x);
    step_text = text.substr(x + 1);
  }
  FrameRange frames;
  const size_t dash = range.find('-', 1);
  const bool ok_numbers =
      dash == std::string::npos
          ? parse_frame_number(range, &frames.first) && (frames.last = frames.first, true)
          : parse_frame_number(range.substr(0, dash), &frames.first) &&
                parse_frame_number(range.substr(dash + 1), &frames.last);
  if (!ok_numbers || (text.find('x') != std::string::npos && !parse_frame_number(step_text, &frames.step))) {
    *error = what + "expected FIRST-LAST or FIRST-LASTxSTEP, whole frame numbers from 0 to 999999999 "
                    "(e.g. 1001-1240 or 1001-1240x2)";
    return false;
  }
  if (frames.last < frames.first) {
    *error = what + "the last frame comes before the first";
    return false;
  }
  if (frames.step < 1) {
    *error = what + "the step must be 1 or more";
    return false;
  }
  *out = frames;
  return true;
}

long long chunk_count(const FrameRange& range, long long size) { return (range.count() + size - 1) / size; }

FrameRange chunk_of(const FrameRange& range, long long size, long long index) {
  const long long first = index * size, last = std::min(first + size, range.count()) - 1;
  return {range.at(first), range.at(last), range.step};
}

std::string FramePattern::path(long long frame) const {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%0*lld", width, frame);
  return prefix + digits + suffix;
}

bool has_frame_token(const std::string& path) {
  bool bad_percent = false;
  for (size_t i = 0; i < path.size(); ++i)
    if (token_at(path, i, &bad_percent).length) return true;
  return false;
}

bool has_printf_frame_token(const std::string& path) {
  bool bad_percent = false;
  for (size_t i = 0; i < path.size(); ++i)
    if (path[i] == '%' && token_at(path, i, &bad_percent).length) return true;
  return false;
}

bool parse_frame_pattern(const std::string& option, const std::string& path, FramePattern* out, std::string* error) {
  const std::string what = option + " " + path + ": ";
  FramePattern pattern;
  int tokens = 0;
  for (size_t i = 0; i < path.size();) {
    if (path[i] == '%' && i + 1 < path.size() && path[i + 1] == '%') {
      (tokens ? pattern.suffix : pattern.prefix) += '%';
      i += 2;
      continue;
    }
    bool bad_percent = false;
    const Token token = token_at(path, i, &bad_percent);
    if (bad_percent) {
      *error = what + "a % must start %d, %0Nd (N from 1 to 9) or %% (a literal %)";
      return false;
    }
    if (token.length) {
      if (++tokens > 1) {
        *error = what + "more than one frame number (%d, %0Nd, # or @); a file name may hold only one";
        return false;
      }
      pattern.width = token.width;
      i += token.length;
      continue;
    }
    (tokens ? pattern.suffix : pattern.prefix) += path[i++];
  }
  if (!tokens) {
    *error = what + "no frame number in the name: write it as %04d, #### or @@@@ (e.g. shot.%04d.exr)";
    return false;
  }
  *out = pattern;
  return true;
}

}  // namespace pfx::app

// Small parsers our programs' command lines share, so every program reads "a,b,c" and "WxH" the
// same way and says the same thing when they are wrong.
#pragma once

#include <string>
#include <vector>

namespace pfx::app {

bool ends_with(const std::string& text, const std::string& suffix);
// "a,b,,c" -> {"a", "b", "c"}: empty items are dropped.
std::vector<std::string> split_list(const std::string& text, char separator = ',');
// "1920x1080" with 1 <= W, H <= 16384; false with *error starting with `option`.
// A whole number >= 0 in decimal, nothing else (no sign, no blanks), at most 18 digits.
bool parse_count(const std::string& text, long long* out);
bool parse_frame_size(const std::string& option, const std::string& text, int* width, int* height, std::string* error);

}  // namespace pfx::app

// Small parsers our programs' command lines share, so every program reads "a,b,c" and "WxH" the
// same way and says the same thing when they are wrong.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pfx::app {

bool ends_with(const std::string& text, const std::string& suffix);
// "a,b,,c" -> {"a", "b", "c"}: empty items are dropped.
std::vector<std::string> split_list(const std::string& text, char separator = ',');
// A whole number >= 0 in decimal, nothing else (no sign, no blanks), at most 18 digits.
bool parse_count(const std::string& text, long long* out);
// The values of options several programs share, with the same rules and messages everywhere:
// --lights N (0..10000000), --seed S (>= 0), --exposure EV (a number, not NaN).
bool parse_light_count(const std::string& text, int* out, std::string* error);
bool parse_seed(const std::string& text, uint64_t* out, std::string* error);
bool parse_exposure(const std::string& text, double* out, std::string* error);
// The keys of "fovy=45,far=inf": {"fovy", "far"}.
std::vector<std::string> option_keys(const std::string& text);
// "1920x1080" with 1 <= W, H <= 16384; false with *error starting with `option`.
bool parse_frame_size(const std::string& option, const std::string& text, int* width, int* height, std::string* error);
// "1280x720,1920x1080": each size as parse_frame_size reads it, in order (none for an empty list).
bool parse_frame_sizes(const std::string& option, const std::string& text, std::vector<std::pair<int, int>>* sizes,
                       std::string* error);

}  // namespace pfx::app

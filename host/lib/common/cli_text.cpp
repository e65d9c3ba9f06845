#include "cli_text.hpp"

#include <cstdio>
#include <cstdlib>

namespace pfx::app {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::vector<std::string> split_list(const std::string& text, char separator) {
  std::vector<std::string> items;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(separator, start);
    if (end == std::string::npos) end = text.size();
    if (end > start) items.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return items;
}

bool parse_count(const std::string& text, long long* out) {
  if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos) return false;
  *out = std::stoll(text);
  return true;
}

bool parse_light_count(const std::string& text, int* out, std::string* error) {
  long long count = 0;
  if (!parse_count(text, &count) || count > 10000000) {
    *error = "--lights " + text + ": expected a whole number from 0 to 10000000";
    return false;
  }
  *out = static_cast<int>(count);
  return true;
}

bool parse_seed(const std::string& text, uint64_t* out, std::string* error) {
  long long seed = 0;
  if (!parse_count(text, &seed)) {
    *error = "--seed " + text + ": expected a whole number >= 0";
    return false;
  }
  *out = static_cast<uint64_t>(seed);
  return true;
}

bool parse_exposure(const std::string& text, double* out, std::string* error) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || value != value) {
    *error = "--exposure " + text + ": not a number";
    return false;
  }
  *out = value;
  return true;
}

std::vector<std::string> option_keys(const std::string& text) {
  std::vector<std::string> keys;
  for (const auto& item : split_list(text)) keys.push_back(item.substr(0, item.find('=')));
  return keys;
}

bool parse_frame_size(const std::string& option, const std::string& text, int* width, int* height, std::string* error) {
  int w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384) {
    *error = option + " " + text + ": expected WxH with 1 <= W, H <= 16384";
    return false;
  }
  *width = w;
  *height = h;
  return true;
}

bool parse_frame_sizes(const std::string& option, const std::string& text, std::vector<std::pair<int, int>>* sizes,
                       std::string* error) {
  sizes->clear();
  for (const std::string& item : split_list(text)) {
    int w = 0, h = 0;
    if (!parse_frame_size(option, item, &w, &h, error)) return false;
    sizes->push_back({w, h});
  }
  return true;
}

}  // namespace pfx::app

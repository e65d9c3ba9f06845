#include "param_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <vector>

#include "descriptor_check.hpp"

namespace pfx::host {
namespace {

std::string trim(const std::string& text) {
  size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  size_t end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// For a decimal number from_chars found out of range: whether its magnitude is above the
// largest double (overflow) rather than below the smallest denormal (underflow). The magnitude is
// the power of ten of its first non-zero digit plus its exponent, which can only be far from 0 here.
bool overflows(const std::string& text) {
  size_t mark = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, mark);
  long long exponent = 0;
  if (mark != std::string::npos) {
    size_t i = mark + 1;
    const bool negative = i < text.size() && text[i] == '-';
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
      exponent = std::min(exponent * 10 + (text[i] - '0'), 1000000000LL);  // saturates: 1e99999999999
    if (negative) exponent = -exponent;
  }
  const size_t point = std::min(mantissa.find('.'), mantissa.size());
  const size_t first = mantissa.find_first_of("123456789");
  if (first == std::string::npos) return false;  // all zeros: never out of range, but not large
  const long long power = first < point ? static_cast<long long>(point - first) - 1 : -static_cast<long long>(first - point);
  return power + exponent > 0;
}

bool parse_number(const std::string& raw, double* out, std::string* error) {
  std::string text = trim(raw);
  std::string l = lower(text);
  if (l == "nan" || l == "+nan" || l == "-nan") {
    *error = "NaN is not a valid value";
    return false;
  }
  // from_chars takes no leading '+'; accept it as people write it.
  const char* begin = text.c_str();
  if (*begin == '+') ++begin;
  const char* end = text.c_str() + text.size();
  double value = 0;
  auto result = std::from_chars(begin, end, value);
  if (text.empty() || result.ec == std::errc::invalid_argument || result.ptr != end) {
    *error = "'" + text + "' is not a number";
    return false;
  }
  // Out of range, from_chars leaves the value alone: the sign is the text's, and a number too
  // large becomes infinity while one too small becomes zero, as strtod gives them.
  if (result.ec == std::errc::result_out_of_range)
    value = std::copysign(overflows(text) ? HUGE_VAL : 0.0, text[0] == '-' ? -1.0 : 1.0);
  if (std::isnan(value)) {
    *error = "NaN is not a valid value";
    return false;
  }
  *out = value;
  return true;
}

}  // namespace

std::string format_number(double value) {
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

bool parse_param_text(const pfx_param_desc& desc, const std::string& raw, pfx_value* out, std::string* error) {
  pfx_value value = desc.default_value;
  std::string text = trim(raw);
  switch (desc.type) {
    case PFX_PARAM_BOOL: {
      std::string l = lower(text);
      if (l == "true" || l == "1" || l == "on" || l == "yes") value.v[0] = 1;
      else if (l == "false" || l == "0" || l == "off" || l == "no") value.v[0] = 0;
      else {
        *error = "'" + text + "' is not a boolean (true/false, on/off, 1/0)";
        return false;
      }
      break;
    }
    case PFX_PARAM_ENUM: {
      for (uint32_t i = 0; i < desc.item_count; ++i)
        if (text == desc.items[i].id) {
          value.v[0] = i;
          *out = value;
          return true;
        }
      double index = 0;
      std::string ignored;
      if (!parse_number(text, &index, &ignored) || index != std::floor(index) || index < 0 ||
          index >= desc.item_count) {
        std::string items;
        for (uint32_t i = 0; i < desc.item_count; ++i) items += (i ? ", " : "") + std::string(desc.items[i].id);
        *error = "'" + text + "' is not one of: " + items;
        return false;
      }
      value.v[0] = index;
      break;
    }
    default: {
      int count = param_component_count(desc.type);
      std::vector<std::string> parts;
      size_t start = 0;
      while (true) {
        size_t comma = text.find(',', start);
        parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
      // A single number for a colour or vector fills every component ("tint=1").
      if (static_cast<int>(parts.size()) != count && !(parts.size() == 1 && count > 1)) {
        *error = "expected " + std::to_string(count) + " comma-separated numbers, got '" + text + "'";
        return false;
      }
      for (int i = 0; i < count; ++i)
        if (!parse_number(parts[parts.size() == 1 ? 0 : i], &value.v[i], error)) return false;
      break;
    }
  }
  *out = value;
  return true;
}

std::string format_param_text(const pfx_param_desc& desc, const pfx_value& value) {
  switch (desc.type) {
    case PFX_PARAM_BOOL: return value.v[0] != 0 ? "true" : "false";
    case PFX_PARAM_ENUM: {
      auto index = static_cast<uint32_t>(value.v[0]);
      return index < desc.item_count ? desc.items[index].id : format_number(value.v[0]);
    }
    default: {
      std::string text;
      for (int i = 0; i < param_component_count(desc.type); ++i) text += (i ? "," : "") + format_number(value.v[i]);
      return text;
    }
  }
}

bool validate_param_value(const pfx_param_desc& desc, pfx_value* value, std::string* error, std::string* note) {
  int count = param_component_count(desc.type);
  bool whole = desc.type == PFX_PARAM_INT || desc.type == PFX_PARAM_ENUM || desc.type == PFX_PARAM_BOOL;
  bool clamped = false;
  for (int i = 0; i < count; ++i) {
    double& v = value->v[i];
    if (std::isnan(v)) {
      *error = "NaN is not a valid value";
      return false;
    }
    if (whole && v != std::floor(v)) {
      *error = format_number(v) + " is not a whole number";
      return false;
    }
    if (v < desc.hard_min || v > desc.hard_max) {
      bool reject = (desc.flags & PFX_PARAM_REJECT_OUT_OF_RANGE) || desc.type == PFX_PARAM_ENUM;
      if (reject) {
        *error = format_number(v) + " is outside [" + format_number(desc.hard_min) + ", " +
                 format_number(desc.hard_max) + "]";
        return false;
      }
      v = v < desc.hard_min ? desc.hard_min : desc.hard_max;
      clamped = true;
    }
    // -0 means 0 to every parameter, but not to every reader of a saved value: JSON's "-0" reads
    // back as the integer 0. Adding +0 turns -0 into 0 and leaves every other value as it is.
    v += 0.0;
  }
  for (int i = count; i < 4; ++i) value->v[i] = 0;
  if (clamped && note) *note = "clamped to " + format_param_text(desc, *value);
  return true;
}

}  // namespace pfx::host

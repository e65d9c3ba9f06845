#include "literals.hpp"

#include <cctype>
#include <cerrno>
#include <cstdlib>

namespace pfx::fx {
namespace {

int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

bool looks_like_float(const std::string& s) {
  bool hex = s.size() > 1 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
  if (hex) return false;
  for (char c : s)
    if (c == '.' || c == 'e' || c == 'E' || c == 'f' || c == 'F' || c == 'h' || c == 'H') return true;
  return false;
}

std::optional<NumberLiteral> parse_float(const std::string& s, std::string& error) {
  std::size_t end = s.size();
  NumberLiteral literal;
  literal.kind = NumberLiteral::Kind::kFloat;
  char last = s.back();
  if (last == 'f' || last == 'F') {
    --end;
  } else if (last == 'h' || last == 'H') {
    literal.kind = NumberLiteral::Kind::kHalf;
    --end;
  } else if (last == 'l' || last == 'L') {
    literal.kind = NumberLiteral::Kind::kDouble;
    --end;
  }
  std::string body = s.substr(0, end);
  // strtod would also take hex floats, "inf" and "nan": check the HLSL form by hand first.
  std::size_t i = 0;
  bool digits = false;
  while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i, digits = true;
  if (i < body.size() && body[i] == '.') ++i;
  while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i, digits = true;
  if (digits && i < body.size() && (body[i] == 'e' || body[i] == 'E')) {
    ++i;
    if (i < body.size() && (body[i] == '+' || body[i] == '-')) ++i;
    bool exponent_digits = false;
    while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i, exponent_digits = true;
    if (!exponent_digits) digits = false;
  }
  if (!digits || i != body.size()) {
    error = "invalid floating-point literal '" + s + "'";
    return std::nullopt;
  }
  literal.real = std::strtod(body.c_str(), nullptr);  // overflow gives inf, as HLSL compilers do
  return literal;
}

}  // namespace

std::optional<NumberLiteral> parse_number(const std::string& s, std::string& error, int integer_bits) {
  if (s.empty()) {
    error = "empty number";
    return std::nullopt;
  }
  if (looks_like_float(s)) return parse_float(s, error);
  NumberLiteral literal;
  std::size_t end = s.size();
  while (end > 0 && (s[end - 1] == 'u' || s[end - 1] == 'U' || s[end - 1] == 'l' || s[end - 1] == 'L')) {
    if (s[end - 1] == 'u' || s[end - 1] == 'U') literal.kind = NumberLiteral::Kind::kUint;
    --end;
  }
  std::size_t i = 0;
  int base = 10;
  if (end > 1 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    base = 16;
    i = 2;
  } else if (end > 1 && s[0] == '0') {
    base = 8;
    i = 1;
  }
  if (i == end || end + 2 < s.size()) {
    error = "invalid integer literal '" + s + "'";
    return std::nullopt;
  }
  std::uint64_t value = 0;
  bool overflow = false;
  for (; i < end; ++i) {
    int digit = digit_value(s[i]);
    if (digit >= base) {
      error = "invalid digit '" + std::string(1, s[i]) + "' in integer literal '" + s + "'";
      return std::nullopt;
    }
    if (value > (UINT64_MAX - static_cast<std::uint64_t>(digit)) / static_cast<std::uint64_t>(base)) overflow = true;
    value = value * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(digit);
  }
  if (overflow || (integer_bits < 64 && value > 0xffffffffull)) {
    error = "integer literal '" + s + "' does not fit in " + std::to_string(integer_bits < 64 ? 32 : 64) + " bits";
    return std::nullopt;
  }
  literal.integer = value;
  return literal;
}

std::string unescape_string(const std::string& quoted, std::string& error) {
  std::string out;
  std::size_t end = quoted.size() >= 2 ? quoted.size() - 1 : quoted.size();
  for (std::size_t i = 1; i < end; ++i) {
    char c = quoted[i];
    if (c != '\\' || i + 1 >= end) {
      out += c;
      continue;
    }
    char e = quoted[++i];
    switch (e) {
      case 'n': out += '\n'; break;
      case 't': out += '\t'; break;
      case 'r': out += '\r'; break;
      case 'a': out += '\a'; break;
      case 'b': out += '\b'; break;
      case 'f': out += '\f'; break;
      case 'v': out += '\v'; break;
      case '\\': case '"': case '\'': case '?': out += e; break;
      case 'x': {
        unsigned value = 0;
        int count = 0;
        while (i + 1 < end && digit_value(quoted[i + 1]) < 16 && count < 2) value = value * 16 + digit_value(quoted[++i]), ++count;
        if (count == 0) error = "\\x used with no following hex digits";
        out += static_cast<char>(value);
        break;
      }
      default:
        if (e >= '0' && e <= '7') {
          unsigned value = static_cast<unsigned>(e - '0');
          for (int count = 1; count < 3 && i + 1 < end && quoted[i + 1] >= '0' && quoted[i + 1] <= '7'; ++count)
            value = value * 8 + static_cast<unsigned>(quoted[++i] - '0');
          out += static_cast<char>(value & 0xff);
        } else {
          // ReShade keeps the character after a backslash it does not know ("Color\0\HSV"), as
          // public effects' combo lists rely on.
          out += e;
        }
    }
  }
  return out;
}

}  // namespace pfx::fx

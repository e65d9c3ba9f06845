#pragma once
// Values of number and string literals, by HLSL's rules: integers in decimal, hex (0x) and octal
// (leading 0) with u/U/l/L suffixes; floats with a dot or an exponent, or an f/F/h/H suffix.
#include <cstdint>
#include <optional>
#include <string>

namespace pfx::fx {

struct NumberLiteral {
  enum class Kind { kInt, kUint, kFloat, kHalf, kDouble } kind = Kind::kInt;
  std::uint64_t integer = 0;  // kInt/kUint (kInt values above INT_MAX wrap like HLSL's)
  double real = 0.0;          // kFloat/kHalf/kDouble
};

// nullopt with `error` set when the spelling is not a valid literal. An integer must fit in 32
// bits, as the language's types are; #if arithmetic (64-bit) takes `integer_bits` 64.
std::optional<NumberLiteral> parse_number(const std::string& spelling, std::string& error, int integer_bits = 32);

// The bytes a quoted string literal stands for (escapes resolved). `error` set on a bad escape.
std::string unescape_string(const std::string& quoted, std::string& error);

}  // namespace pfx::fx

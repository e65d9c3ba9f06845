// The common statement forms, read in one pass without a bounds check per byte: what exporters
// write for nearly every line of a large file — "f" with positive indices in any of the four corner
// forms, and "v", "vt", "vn" with plain decimals ([+-]digits[.digits] or [+-].digits, at most 19
// digits, no exponent), blanks between, LF, CRLF or CR at the end.
//
// A reader either takes the whole line and returns where the next line starts, or returns nullptr
// and the general grammar (obj_chunk.cpp) reads the line instead: for a comment, a continuation,
// an exponent, a negative index, a malformed token, a wrong count, the last bytes of a chunk —
// anything else. So a line either reader takes gives exactly what the general grammar gives (the
// tests and the fuzz target compare the two on the same text), and every message comes from it.
//
// Bounds: the caller passes limit = end - kPlainLineMargin. Each element (number or corner) starts
// before limit and reads at most kPlainElementBytes past its start, so nothing past end is read.
#pragma once

#include <algorithm>
#include <cstdint>

#include "obj_chunk.hpp"
#include "obj_text.hpp"

namespace pfx_obj {

constexpr long kPlainLineMargin = 64;
constexpr long kPlainElementBytes = 48;  // sign, 20 digits, '.', 20 digits, one byte after; a corner: 35

namespace plain {

inline bool digit(char c, uint32_t* value) {
  *value = static_cast<uint32_t>(static_cast<unsigned char>(c)) - '0';
  return *value < 10;
}
inline bool blank(char c) { return c == ' ' || c == '\t'; }

// Steps over blanks up to limit; at a line end returns the start of the next line, else nullptr
// with *p at the next token (which must start before limit to be read).
inline const char* line_end_after_blanks(const char*& p, const char* limit) {
  while (blank(*p) && p < limit) ++p;
  if (*p == '\n') return p + 1;
  if (*p == '\r') return p + (p[1] == '\n' ? 2 : 1);
  return nullptr;
}

// A positive index of 1 to 9 digits (below 2^31, so never too large); false for anything else.
inline bool index(const char*& p, uint32_t* out) {
  uint32_t value, d;
  if (!digit(*p, &value)) return false;
  ++p;
  for (int i = 1; i < 9 && digit(*p, &d); ++i, ++p) value = value * 10 + d;
  if (digit(*p, &d) || value == 0) return false;
  *out = value;
  return true;
}

// A plain decimal ending at a blank or line end; false for anything else (the general grammar
// then reads it: exponents, long mantissas, malformed or non-finite tokens).
inline bool number(const char*& p, double* out) {
  const char* q = p;
  const bool negative = *q == '-';
  if (*q == '-' || *q == '+') ++q;
  uint64_t mantissa = 0;
  uint32_t d;
  int digits = 0, fraction = 0;
  for (; digits < 20 && digit(*q, &d); ++q, ++digits) mantissa = mantissa * 10 + d;
  if (*q == '.') {
    ++q;
    for (; digits < 20 && digit(*q, &d); ++q, ++digits, ++fraction) mantissa = mantissa * 10 + d;
  }
  // 20 digits or more, no digit, or not followed by a blank or line end: not plain.
  if (digits == 0 || digits > 19 || !(blank(*q) || *q == '\n' || *q == '\r')) return false;
  // Clinger's fast path, as in parse_number_prefix, so both give the same double.
  if (mantissa >= (uint64_t{1} << 53)) return false;
  const double value = static_cast<double>(mantissa) / kExactPowersOf10[fraction];
  *out = negative ? -value : value;
  p = q;
  return true;
}

}  // namespace plain

// Reads "n n n..." (after the keyword) to the line end: up to `capacity` plain numbers. Returns the
// start of the next line, or nullptr (more numbers than capacity, or anything not plain).
inline const char* read_plain_numbers(const char* p, const char* limit, double* values, int capacity, int* count) {
  int n = 0;
  for (;;) {
    if (const char* next = plain::line_end_after_blanks(p, limit)) {
      *count = n;
      return next;
    }
    if (p >= limit || n == capacity || !plain::number(p, &values[n])) return nullptr;
    ++n;
  }
}

// Reads the corners of an "f" line (after the keyword) to the line end, three fields each as the
// general grammar stores them (the index as written minus one, kNoIndex for a missing vt or vn) at
// `fields`, which has room for every corner the rest of the chunk can hold, and raises max_index
// (v, vt, vn) to the largest index read. Returns the start of the next line, or nullptr (fewer than
// 3 corners, a negative index, anything not plain) having changed nothing but fields.
inline const char* read_plain_face(const char* p, const char* limit, uint32_t* fields, uint32_t* corner_count,
                                   uint32_t* max_index) {
  uint32_t corners = 0, max_v = max_index[0], max_vt = max_index[1], max_vn = max_index[2];
  for (;;) {
    if (const char* next = plain::line_end_after_blanks(p, limit)) {
      *corner_count = corners;
      max_index[0] = max_v;
      max_index[1] = max_vt;
      max_index[2] = max_vn;
      return corners >= 3 ? next : nullptr;
    }
    if (p >= limit) return nullptr;
    uint32_t v, vt = 0, vn = 0;
    if (!plain::index(p, &v)) return nullptr;
    if (*p == '/') {
      ++p;
      if (*p == '/') {
        ++p;
        if (!plain::index(p, &vn)) return nullptr;
      } else {
        if (!plain::index(p, &vt)) return nullptr;
        if (*p == '/') {
          ++p;
          if (!plain::index(p, &vn)) return nullptr;
        }
      }
    }
    if (!(plain::blank(*p) || *p == '\n' || *p == '\r')) return nullptr;
    max_v = std::max(max_v, v);
    max_vt = std::max(max_vt, vt);
    max_vn = std::max(max_vn, vn);
    static_assert(kNoIndex == uint32_t{0} - 1, "an absent field (0) minus one is kNoIndex");
    fields[0] = v - 1;
    fields[1] = vt - 1;
    fields[2] = vn - 1;
    fields += 3;
    ++corners;
  }
}

}  // namespace pfx_obj

// Frame numbers and file-name patterns of image sequences, as VFX tools write them:
//   --frames 1001-1240, 1001-1240x2 (every second frame), 1001 (one frame)
//   shot.%04d.exr, shot.%d.exr, shot.####.exr, shot.@@@@.exr: the frame number, zero-padded to
//   the width the pattern gives (each # or @ is one digit, %0Nd is N digits, %d and a lone @ are
//   unpadded); a number wider than the padding is written in full, as printf does.
// Pure text handling, no file system: tested and fuzzed on its own.
#pragma once

#include <string>

namespace pfx::app {

// The frames first, first + step, ... up to and including last (last itself only when the
// step lands on it).
struct FrameRange {
  long long first = 0, last = 0, step = 1;
  long long count() const { return (last - first) / step + 1; }
  long long at(long long index) const { return first + index * step; }
};

// The range cut into chunks of `size` frames (size >= 1), in order; the last may be shorter. What
// pfx-farm hands each task of a job array: chunk `index` of the range, from 0.
long long chunk_count(const FrameRange& range, long long size);
// Chunk `index` (0 <= index < chunk_count) as a range of its own, with the same step.
FrameRange chunk_of(const FrameRange& range, long long size, long long index);

// The largest frame number accepted: nine digits, the widest padding VFX tools use.
constexpr long long kMaxFrameNumber = 999999999;

// "A", "A-B" or "A-BxSTEP" with 0 <= A <= B <= kMaxFrameNumber and STEP >= 1. False with
// *error starting "--frames TEXT: " otherwise (negative frames included).
bool parse_frame_range(const std::string& text, FrameRange* out, std::string* error);

// A file name with exactly one frame-number token.
struct FramePattern {
  std::string prefix, suffix;  // the text around the token, with "%%" already made "%"
  int width = 0;               // the zero padding: 0 or 1 means none
  std::string path(long long frame) const;
};

// True when `path` holds a frame-number token (%d, %0Nd, a run of # or @).
bool has_frame_token(const std::string& path);
// Only %d and %0Nd (N 1-9): what a user may have given by mistake without --frames. A run of # or
// @ is left alone there, since plain file names may hold them.
bool has_printf_frame_token(const std::string& path);

// Parses `path` as a pattern with exactly one token. False with *error starting with `option`
// ("--out shot.exr: ...") when it has none, more than one, or a % that is neither %%, %d nor %0Nd.
bool parse_frame_pattern(const std::string& option, const std::string& path, FramePattern* out, std::string* error);

}  // namespace pfx::app

// Writing an output file so that readers only ever see the old file or the complete new one:
// the content goes to a temporary name in the same folder (same file system, so the final
// rename is atomic) and is renamed over the target only when it was written in full.
#pragma once

#include <functional>
#include <string>

namespace pfx::app {

// Writes the whole file at temp_path. Returns false and sets *reason (without the path; the
// caller adds it) on failure. It may leave a partial file behind; write_atomically removes it.
using WriteFileFn = std::function<bool(const std::string& temp_path, std::string* reason)>;

// Calls write() with a temporary path beside `path` (".NAME.tmp-PID-N"), flushes it to disk and
// renames it to `path`. On any failure (folder missing, write() failing or throwing, rename
// failing) the temporary file is removed, an existing file at `path` is left untouched, and
// *error says "cannot write PATH: REASON".
bool write_atomically(const std::string& path, const WriteFileFn& write, std::string* error);

// write_atomically for a file whose whole content is `text`.
bool write_text_atomically(const std::string& path, const std::string& text, std::string* error);

}  // namespace pfx::app

#pragma once
// How the preprocessor reads files: through a callback, so tests and the runtime's cache can serve
// files from memory, and the compiler itself never touches the disk unless asked to.
#include <functional>
#include <string>

namespace pfx::fx {

// Fills `contents` and returns true if `path` names a readable file.
using FileReader = std::function<bool(const std::string& path, std::string& contents)>;

// Reads from the file system.
bool read_file_from_disk(const std::string& path, std::string& contents);

// The folder part of a path ("" for a bare name), and a path joined and normalised lexically.
std::string parent_folder(const std::string& path);
std::string join_path(const std::string& folder, const std::string& name);

}  // namespace pfx::fx

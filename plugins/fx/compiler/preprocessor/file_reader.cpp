#include "file_reader.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace pfx::fx {

bool read_file_from_disk(const std::string& path, std::string& contents) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  std::ifstream stream(path, std::ios::binary);
  if (!stream) return false;
  std::ostringstream buffer;
  buffer << stream.rdbuf();
  contents = buffer.str();
  return true;
}

std::string parent_folder(const std::string& path) {
  return std::filesystem::path(path).parent_path().generic_string();
}

std::string join_path(const std::string& folder, const std::string& name) {
  std::filesystem::path joined = folder.empty() ? std::filesystem::path(name) : std::filesystem::path(folder) / name;
  return joined.lexically_normal().generic_string();
}

}  // namespace pfx::fx

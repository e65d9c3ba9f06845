#pragma once
// Errors and warnings collected while compiling. The library never throws out of its entry points:
// every problem becomes a Diagnostic, formatted like a compiler's ("file:line:column: error: ...").
#include <string>
#include <vector>

#include "source_location.hpp"

namespace pfx::fx {

enum class Severity { kWarning, kError };

struct Diagnostic {
  Severity severity = Severity::kError;
  SourceLocation location;
  std::string message;
};

// Names of the files locations point into; #line may add a name that is not a real file.
class FileNames {
 public:
  std::uint32_t add(const std::string& name);
  const std::string& name(std::uint32_t index) const;
  std::size_t size() const { return names_.size(); }

 private:
  std::vector<std::string> names_;
};

class Diagnostics {
 public:
  explicit Diagnostics(const FileNames& names) : names_(names) {}

  void error(SourceLocation where, std::string message);
  void warning(SourceLocation where, std::string message);

  bool has_errors() const { return error_count_ > 0; }
  // True once kMaxErrors errors were reported: callers stop early instead of cascading.
  bool too_many_errors() const;
  std::size_t error_count() const { return error_count_; }
  const std::vector<Diagnostic>& all() const { return list_; }

  std::string format(const Diagnostic& diagnostic) const;
  // Every diagnostic, one per line.
  std::string format_all() const;

 private:
  const FileNames& names_;
  std::vector<Diagnostic> list_;
  std::size_t error_count_ = 0;
};

}  // namespace pfx::fx

#include "diagnostics.hpp"

#include "limits.hpp"

namespace pfx::fx {

std::uint32_t FileNames::add(const std::string& name) {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return static_cast<std::uint32_t>(i);
  names_.push_back(name);
  return static_cast<std::uint32_t>(names_.size() - 1);
}

const std::string& FileNames::name(std::uint32_t index) const {
  static const std::string unknown = "<unknown>";
  return index < names_.size() ? names_[index] : unknown;
}

void Diagnostics::error(SourceLocation where, std::string message) {
  if (error_count_ > limits::kMaxErrors) return;
  ++error_count_;
  if (error_count_ > limits::kMaxErrors) message = "too many errors; stopping";
  list_.push_back({Severity::kError, where, std::move(message)});
}

void Diagnostics::warning(SourceLocation where, std::string message) {
  if (list_.size() > 4 * limits::kMaxErrors) return;  // a warning flood must not eat memory either
  list_.push_back({Severity::kWarning, where, std::move(message)});
}

bool Diagnostics::too_many_errors() const { return error_count_ > limits::kMaxErrors; }

std::string Diagnostics::format(const Diagnostic& d) const {
  std::string text = names_.name(d.location.file) + ":" + std::to_string(d.location.line) + ":" +
                     std::to_string(d.location.column) + ": ";
  text += d.severity == Severity::kError ? "error: " : "warning: ";
  return text + d.message;
}

std::string Diagnostics::format_all() const {
  std::string text;
  for (const Diagnostic& d : list_) text += format(d) + "\n";
  return text;
}

}  // namespace pfx::fx

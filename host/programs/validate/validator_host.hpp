// The pfx_host the no-GL checks hand to a plugin's init: it keeps the plugin's error messages
// (to quote them in a failure) and counts GL requests, which are forbidden outside the GL calls.
#pragma once

#include <string>
#include <vector>

#include <pfx/core.h>

namespace pfx::validate {

class ValidatorHost {
 public:
  ValidatorHost();
  ValidatorHost(const ValidatorHost&) = delete;
  ValidatorHost& operator=(const ValidatorHost&) = delete;

  const pfx_host* host() const { return &host_; }
  int gl_requests() const { return gl_requests_; }
  const std::string& first_gl_request() const { return first_gl_request_; }
  // ": the plugin logged: ..." with its warnings and errors, or "" when it logged none.
  std::string errors_logged() const;

 private:
  static void log(void* host_data, pfx_log_level level, const char* message);
  static pfx_gl_proc get_proc_address(void* host_data, const char* name);
  pfx_host host_{};
  int gl_requests_ = 0;
  std::string first_gl_request_;
  std::vector<std::string> errors_;
};

}  // namespace pfx::validate

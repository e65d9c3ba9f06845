#include "validator_host.hpp"

namespace pfx::validate {

ValidatorHost::ValidatorHost() {
  host_.struct_size = sizeof(pfx_host);
  host_.abi_major = PFX_ABI_MAJOR;
  host_.abi_minor = PFX_ABI_MINOR;
  host_.host_name = "pfx-validate";
  host_.host_data = this;
  host_.log = &ValidatorHost::log;
  host_.get_proc_address = &ValidatorHost::get_proc_address;
}

void ValidatorHost::log(void* host_data, pfx_log_level level, const char* message) {
  auto* self = static_cast<ValidatorHost*>(host_data);
  if (self && level >= PFX_LOG_WARNING) self->errors_.emplace_back(message ? message : "(null message)");
}

pfx_gl_proc ValidatorHost::get_proc_address(void* host_data, const char* name) {
  auto* self = static_cast<ValidatorHost*>(host_data);
  if (self && self->gl_requests_++ == 0) self->first_gl_request_ = name ? name : "(null)";
  return nullptr;
}

std::string ValidatorHost::errors_logged() const {
  std::string text;
  for (const std::string& e : errors_) text += (text.empty() ? "" : " | ") + e;
  return text.empty() ? "" : ": the plugin logged: " + text;
}

}  // namespace pfx::validate

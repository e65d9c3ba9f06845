#include "display_transfer.hpp"

namespace pfx::app {

bool parse_transfer(const std::string& text, Transfer* out, std::string* error) {
  if (text == "srgb") *out = Transfer::SRGB;
  else if (text == "linear") *out = Transfer::LINEAR;
  else {
    *error = "transfer '" + text + "': expected srgb or linear";
    return false;
  }
  return true;
}

const char* transfer_name(Transfer transfer) { return transfer == Transfer::SRGB ? "srgb" : "linear"; }

}  // namespace pfx::app

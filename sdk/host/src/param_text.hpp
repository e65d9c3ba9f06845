// Conversions between parameter values and their text form, shared by the store's text and JSON
// paths. Locale-independent (std::from_chars / std::to_chars), shortest round-trip numbers.
#pragma once

#include <string>

#include <pfx/params.h>

namespace pfx::host {

// Parses text for the descriptor's type. Range checks are the caller's; NaN is refused here.
bool parse_param_text(const pfx_param_desc& desc, const std::string& text, pfx_value* out, std::string* error);
std::string format_param_text(const pfx_param_desc& desc, const pfx_value& value);
// Shortest text that reads back as the same double.
std::string format_number(double value);
// Clamps or refuses by the descriptor's flags; whole-number types must be whole.
bool validate_param_value(const pfx_param_desc& desc, pfx_value* value, std::string* error, std::string* note);

}  // namespace pfx::host

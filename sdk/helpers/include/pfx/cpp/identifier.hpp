// A name made into a pfx id ([a-z0-9_]+: effects, parameters, enum items), one rule for whoever
// makes ids from names and whoever must find them again: the FX plugin names its effects and
// parameters after FX techniques and uniforms, and a host reading a ReShade preset names them the
// same way.
#pragma once

#include <string>

namespace pfx {

// Lower case; every run of other characters one '_', none at either end; "value" for a name with
// nothing left: "fUISharpness" -> "fuisharpness", "Sharp Strength" -> "sharp_strength".
inline std::string identifier_from(const std::string& name) {
  std::string id;
  for (char c : name) {
    char lower = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    if ((lower >= 'a' && lower <= 'z') || (lower >= '0' && lower <= '9')) id += lower;
    else if (!id.empty() && id.back() != '_') id += '_';
  }
  while (!id.empty() && id.back() == '_') id.pop_back();
  return id.empty() ? "value" : id;
}

}  // namespace pfx

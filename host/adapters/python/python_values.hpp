// Values between Python and pfx: JSON (descriptions, values, reports) becomes plain Python
// objects; a Python value given to Chain.set becomes the text form the parameter store parses,
// so Python and --set accept the same values with the same messages.
#pragma once

#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace pfx::python {

// dict, list, str, int, float, bool or None.
pybind11::object to_python(const nlohmann::ordered_json& json);
// bool -> "true"/"false", int -> its digits, float -> its shortest exact repr, str as it is, a
// sequence (list, tuple, 1-D array) -> its elements joined by ','. Anything else raises TypeError.
std::string value_text(const pybind11::handle& value);

}  // namespace pfx::python

// The errors the module raises, as C++ exceptions that module.cpp turns into Python's: pfx.Error
// for what pfx reports (an unknown effect, a chain that fails, a missing input, no OpenGL), its
// subclass pfx.ParameterError for a value the parameter store refuses. Wrong arrays raise
// Python's own TypeError (dtype) and ValueError (shape, layout), thrown as pybind11's.
#pragma once

#include <stdexcept>
#include <string>

namespace pfx::python {

struct Error : std::runtime_error {
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

struct ParameterError : Error {
  explicit ParameterError(const std::string& message) : Error(message) {}
};

}  // namespace pfx::python

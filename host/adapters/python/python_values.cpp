#include "python_values.hpp"

namespace py = pybind11;

namespace pfx::python {

py::object to_python(const nlohmann::ordered_json& json) {
  switch (json.type()) {
    case nlohmann::ordered_json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : json.items()) dict[py::str(key)] = to_python(item);
      return std::move(dict);
    }
    case nlohmann::ordered_json::value_t::array: {
      py::list list;
      for (const auto& item : json) list.append(to_python(item));
      return std::move(list);
    }
    case nlohmann::ordered_json::value_t::string:
      return py::str(json.get<std::string>());
    case nlohmann::ordered_json::value_t::boolean:
      return py::bool_(json.get<bool>());
    case nlohmann::ordered_json::value_t::number_integer:
      return py::int_(json.get<int64_t>());
    case nlohmann::ordered_json::value_t::number_unsigned:
      return py::int_(json.get<uint64_t>());
    case nlohmann::ordered_json::value_t::number_float:
      return py::float_(json.get<double>());
    default:
      return py::none();
  }
}

std::string value_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  // numpy scalars and Python numbers alike: ints by their digits, floats by repr, which reads back
  // as the same double.
  const auto object = py::reinterpret_borrow<py::object>(value);
  if (py::isinstance<py::int_>(value) || py::hasattr(value, "__index__")) return py::str(py::int_(object));
  if (py::isinstance<py::float_>(value) || py::hasattr(value, "__float__")) return py::repr(py::float_(object));
  if (py::isinstance<py::sequence>(value) || py::hasattr(value, "tolist")) {
    const py::object items = py::hasattr(value, "tolist") ? value.attr("tolist")() : object;
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : ",") + value_text(item);
    return text;
  }
  throw py::type_error("a parameter value must be a number, a bool, a string or a sequence of numbers, not " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

}  // namespace pfx::python

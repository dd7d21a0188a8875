#include "json_to_python.h"

#include <string>

namespace penumbra::python {

namespace py = pybind11;

py::object to_python(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, member] : value.items()) dict[py::str(key)] = to_python(member);
      return std::move(dict);
    }
    case nlohmann::json::value_t::array: {
      py::list list(value.size());
      for (std::size_t k = 0; k < value.size(); ++k) list[k] = to_python(value[k]);
      return std::move(list);
    }
    case nlohmann::json::value_t::string:
      return py::str(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(value.get<double>());
    default:
      return py::none();
  }
}

nlohmann::json from_python(py::handle value, const std::string& path) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    // non-negative integers as nlohmann makes them from sizes, so that documents compare equal
    const auto number = value.cast<long long>();
    if (number >= 0) return static_cast<unsigned long long>(number);
    return number;
  }
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, member] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) throw py::type_error(path + ": a key is not a string");
      const std::string name = key.cast<std::string>();
      object[name] = from_python(member, path + "." + name);
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nlohmann::json array = nlohmann::json::array();
    std::size_t k = 0;
    for (const py::handle item : value) {
      array.push_back(from_python(item, path + "[" + std::to_string(k) + "]"));
      ++k;
    }
    return array;
  }
  throw py::type_error(path + ": " + py::str(py::type::of(value)).cast<std::string>() +
                       " is not a JSON value");
}

}  // namespace penumbra::python

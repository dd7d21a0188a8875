#pragma once
// Documents between their C++ form (nlohmann::json, as the verbs write them) and Python's
// (dict, list, str, int, float, bool, None), value for value: a double crosses as the same
// double, so a document the module returns equals the command line's file read by json.load.

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace penumbra::python {

// returns value as Python objects.
pybind11::object to_python(const nlohmann::json& value);

// returns the Python value (dicts with str keys, lists, tuples, str, int, float, bool, None)
// as JSON; throws pybind11::type_error naming the path of anything else.
nlohmann::json from_python(pybind11::handle value, const std::string& path = "$");

}  // namespace penumbra::python

// nlohmann JSON values -> Python objects (dict, list, str, int, float, bool, None), so the
// reports the library builds for the command line reach Python unchanged (same keys, same
// numbers, same order for ordered_json).
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

namespace implicitfit::python {

pybind11::object ToPython(const nlohmann::json& value);
pybind11::object ToPython(const nlohmann::ordered_json& value);

}  // namespace implicitfit::python

// Python values of the library's parameters and JSON documents.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

#include "common/core/params.hpp"

namespace plumbago::python {

namespace py = pybind11;

// Sets parameter `key` to a bool, a number or a choice's name, as a scene file's "params"
// does; a ParamError (ValueError) names the key.
void set_param(ParamSet& set, const std::string& key, const py::handle& value);
// A parameter's value as Python has it: bool, int, float, or the choice's name.
py::object param_value(const ParamSpec& spec, double value);
// The Python objects json.loads makes of `j`.
py::object from_json(const nlohmann::json& j);

}  // namespace plumbago::python

#include "python/values.hpp"

namespace plumbago::python {

void set_param(ParamSet& set, const std::string& key, const py::handle& value) {
  if (py::isinstance<py::bool_>(value))
    set.set(key, value.cast<bool>() ? 1.0 : 0.0);
  else if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))
    set.set(key, value.cast<double>());
  else if (py::isinstance<py::str>(value))
    set.set(key, value.cast<std::string>());
  else
    throw ParamError("parameter '" + key + "': expected a number, a boolean or a choice name, not " +
                     std::string(py::str(py::type::of(value).attr("__name__"))));
}

py::object param_value(const ParamSpec& spec, double value) {
  switch (spec.type) {
    case ParamType::Boolean:
      return py::bool_(value != 0);
    case ParamType::Integer:
      return py::int_(int64_t(value));
    case ParamType::Choice:
      return py::str(spec.choices.at(size_t(value)));
    default:
      return py::float_(value);
  }
}

py::object from_json(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

}  // namespace plumbago::python

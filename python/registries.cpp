// params() and effects(): the registries `plumbago params` and `plumbago effects` print.
#include <pybind11/stl.h>

#include <stdexcept>

#include "common/core/param_text.hpp"
#include "common/core/passes.hpp"
#include "python/bindings.hpp"
#include "python/values.hpp"

namespace plumbago::python {
namespace {

using namespace py::literals;

py::dict param_entry(const ParamSpec& s) {
  py::dict d("type"_a = param_type_name(s.type), "default"_a = param_value(s, s.default_value),
             "range"_a = param_range(s), "doc"_a = s.doc);
  if (s.type == ParamType::Choice) {
    d["choices"] = s.choices;
  } else {
    d["min"] = param_value(s, s.min);
    d["max"] = param_value(s, s.max);
  }
  return d;
}

py::dict params(const std::string& stage) {
  py::dict out;
  for (const ParamSpec& s : param_specs())
    if (stage.empty() || s.key.rfind(stage + ".", 0) == 0) out[py::str(s.key)] = param_entry(s);
  if (out.empty()) throw std::invalid_argument("unknown stage '" + stage + "' (see plumbago.params())");
  return out;
}

py::list effects() {
  py::list out;
  for (const EffectDef& e : effect_table())
    out.append(py::dict("name"_a = e.name, "doc"_a = e.doc, "stages"_a = passes_for({e.name})));
  return out;
}

}  // namespace

void bind_registries(py::module_& m) {
  m.def("params", &params, py::arg("stage") = "",
        "Every parameter (or one stage's, e.g. params(\"edge\")) as {key: {type, default, range, min and max\n"
        "or choices, doc}}, the table `plumbago params` prints. ValueError for an unknown stage.");
  m.def("effects", &effects,
        "Every effect a scene can ask for: [{name, doc, stages}], the stages it runs with the default\n"
        "parameters, as `plumbago effects` prints them.");
}

}  // namespace plumbago::python

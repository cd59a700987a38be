// The parts of the module `plumbago` (python/module.cpp), each adding its functions.
#pragma once

#include <pybind11/pybind11.h>

namespace plumbago::python {

namespace py = pybind11;

void bind_registries(py::module_& m);  // params(), effects()
void bind_curvature(py::module_& m);   // curvature()
void bind_scene(py::module_& m);       // Scene
void bind_images(py::module_& m);      // read_image(), renderer()

}  // namespace plumbago::python

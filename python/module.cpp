// The Python module `plumbago` (docs/python.md): the library as the command line uses it,
// results as NumPy arrays, errors as exceptions with the command line's messages.
#include <pybind11/pybind11.h>

#include "common/mesh/mesh.hpp"
#include "common/scene/scene.hpp"
#include "parity/parity.hpp"
#include "python/bindings.hpp"

namespace plumbago::python {
namespace {

// SceneError and MeshError become plumbago.SceneError and plumbago.MeshError, both
// ValueErrors; a ParamError a ValueError; std::invalid_argument too (pybind11's own).
void bind_errors(py::module_& m) {
  py::register_exception<SceneError>(m, "SceneError", PyExc_ValueError);
  py::register_exception<MeshError>(m, "MeshError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ParamError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace
}  // namespace plumbago::python

PYBIND11_MODULE(plumbago, m) {
  using namespace plumbago::python;
  m.doc() = R"(Plumbago: real-time pencil and sketch rendering of 3D meshes, with a CPU reference for
every stage (README.md, docs/python.md).

    import plumbago as pg
    s = pg.Scene("scenes/fandisk_pencil.json")    # or "builtin:torus", or a dict
    s.size = (640, 480); s.set("edge.depth_scale", 12)
    img = s.render()                              # H x W x 3 uint8, as the PNG file

Errors raise exceptions carrying the command line's messages: SceneError and MeshError
(ValueErrors) name the file and line or the key, ValueError a bad parameter.)";
  plumbago::check_stage_registry();  // as the program does before any command
  bind_errors(m);
  bind_registries(m);
  bind_curvature(m);
  bind_images(m);
  bind_scene(m);
}

// read_image() and renderer(): image files as the module's arrays, the GPU's name.
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "gpu/gl/context.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/gpu_turn.hpp"

namespace plumbago::python {

void bind_images(py::module_& m) {
  m.def(
      "read_image", [](const std::filesystem::path& path) { return image_array(read_image(path.string())); },
      py::arg("path"),
      "A PNG or EXR file as H x W x C float32, top row first (PNG: 0..1): what Scene.render(linear=True)\n"
      "and Scene.stages() return for the files the command line writes.");
  m.def(
      "renderer",
      [] {
        py::gil_scoped_release free;
        GpuTurn turn;
        return gpu::Context::get().renderer();
      },
      "The GL renderer of the GPU backend (GL_RENDERER), making its context if there is none yet.");
}

}  // namespace plumbago::python

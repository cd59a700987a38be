// NumPy arrays over the module's results without copies (docs/python.md): each array
// owns, through a capsule, the C++ object whose memory it views.
#pragma once

#include <pybind11/numpy.h>

#include <utility>
#include <vector>

#include "common/util/image.hpp"

namespace plumbago::python {

namespace py = pybind11;

// An array of `shape` over the elements of `values`, which it keeps alive.
template <class Elem, class T>
py::array_t<Elem> owned_array(std::vector<T> values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<Elem>(std::move(shape), reinterpret_cast<const Elem*>(owned->data()), base);
}

// (n,) for scalars, (n, k) for vectors of k components (glm::vec3: k = 3).
template <class Elem, class T>
py::array_t<Elem> vector_array(std::vector<T> values) {
  constexpr py::ssize_t k = sizeof(T) / sizeof(Elem);
  static_assert(sizeof(T) == k * sizeof(Elem), "a value must be whole elements");
  py::ssize_t n = py::ssize_t(values.size());
  return owned_array<Elem>(std::move(values), k == 1 ? std::vector<py::ssize_t>{n} : std::vector<py::ssize_t>{n, k});
}

// H x W x C float32, the top row first as in image files: a view of `img` (bottom row
// first, common/util/image.hpp) through a negative row stride.
py::array_t<float> image_array(Image img);
// H x W x C uint8: the values a PNG file of `img` holds (png_bytes).
py::array_t<uint8_t> png_array(const Image& img);

}  // namespace plumbago::python

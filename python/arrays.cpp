#include "python/arrays.hpp"

namespace plumbago::python {

py::array_t<float> image_array(Image img) {
  auto* owned = new Image(std::move(img));
  py::capsule base(owned, [](void* p) { delete static_cast<Image*>(p); });
  py::ssize_t h = owned->height, w = owned->width, c = owned->channels, f = sizeof(float);
  const float* top = owned->empty() ? nullptr : owned->pixel(0, owned->height - 1);
  return py::array_t<float>({h, w, c}, {-w * c * f, c * f, f}, top, base);
}

py::array_t<uint8_t> png_array(const Image& img) {
  return owned_array<uint8_t>(png_bytes(img), {img.height, img.width, img.channels});
}

}  // namespace plumbago::python

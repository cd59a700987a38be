#include "common/scene/open_scene.hpp"

#include <stdexcept>

namespace plumbago {

const char* const kDefaultBuiltinScene = "pencil";

Scene open_scene(const std::string& name) {
  if (name.empty()) return builtin_scene(kDefaultBuiltinScene);
  if (name.rfind("builtin:", 0) == 0) return builtin_scene(name.substr(8));
  return load_scene(name);
}

void resize_scene(Scene& scene, int width, int height, const std::string& what) {
  std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument(what + ": " + size + " is out of range (1..16384 each)");
  if (auto fault = camera_fault(scene.camera, double(width) / height, scene.origin))  // the field of view across it
    throw std::invalid_argument(what + " " + size + ": " + scene.source + ": /camera/" + fault->key + ": " +
                                fault->what);
  scene.width = width;
  scene.height = height;
}

}  // namespace plumbago

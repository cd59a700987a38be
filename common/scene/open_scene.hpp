// Scenes as the commands and the Python module (python/) open them: by name, resized.
#pragma once

#include <string>

#include "common/scene/scene.hpp"

namespace plumbago {

// The built-in scene opened when no scene is named.
extern const char* const kDefaultBuiltinScene;

// A scene file, "builtin:NAME", or the default built-in scene when `name` is empty.
Scene open_scene(const std::string& name);

// Sets the image size (1..16384 each) and checks the camera's field of view across it; a
// refusal is a std::invalid_argument whose message starts with `what` (the option or key
// that gave the size) and leaves `scene` as it was.
void resize_scene(Scene& scene, int width, int height, const std::string& what);

}  // namespace plumbago

// The feature lines and decals of a scene at its camera, with their visibility from one
// backend's ID image (Kalnins et al. 2002, §4.5, §4.6): `plumbago lines` and the Python
// module's Scene.lines (python/).
#pragma once

#include <string>
#include <vector>

#include <optional>
#include "common/core/frame.hpp"

#include "common/scene/scene.hpp"
#include "common/strokes/strokes.hpp"
#include "common/strokes/visibility.hpp"

namespace plumbago {

struct SceneLines {
  Scene scene;  // the scene drawn: every object but the sketchy ones with strokes
  WindowLines lines;
  Frame frame;                          // that scene's frame, with its buffers
  ImageU32 keys;                        // its ID image
  std::optional<ImageU32> crease_keys;  // under strokes.crease_under_silhouettes: that image before the silhouettes
  Visibility visibility;
};

// The lines of every object but the sketchy ones, and the decals of the scene's stroke
// files projected by `backend` ("gpu" or "reference"), their visibility from its ID image.
// The lines and the visible runs are the backend's frame's own: the GPU's chains, points and
// runs, made on the GPU in double; the reference's chained and bisected in double.
SceneLines scene_lines(const Scene& scene, const std::string& backend);

// Per point of `path`: whether it shows (front-facing, and its sample passes the ID image).
std::vector<bool> points_visible(const WindowPath& path, const SceneLines& found);

}  // namespace plumbago

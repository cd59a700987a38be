// Camera paths (scene key "animation", docs/scene-format.md): an orbit about the target or
// a dolly toward it, over a number of frames at a frame rate. `plumbago render SCENE -o DIR`
// writes the numbered frames; `plumbago bench` times up to --frames of them.
#pragma once

#include <optional>
#include <vector>

#include "common/scene/camera.hpp"

namespace plumbago {

struct Scene;

struct Animation {
  enum class Kind { Orbit, Dolly };
  Kind kind = Kind::Orbit;
  // Orbit: degrees turned about the camera's up vector through the target, from the first
  // frame to the last. Dolly: distance the eye moves toward the target (negative: away).
  double amount = 0;
  int frames = 1;
  double fps = 30;

  // Where frame i lies on the path: 0 at the first frame, 1 at the last.
  double fraction(int frame) const { return frames > 1 ? double(frame) / double(frames - 1) : 0.0; }
  // Frame i's time in seconds (i / fps): what time-driven effects read.
  double time_s(int frame) const { return double(frame) / fps; }
};

// Frame i's camera: the first frame is `c` itself. An orbit turns the eye about the up
// vector through the target and keeps the planes (the eye's distance to the target does not
// change); a dolly moves the eye along the view direction and fits the near and far planes
// to the bounding sphere (center, radius) again.
Camera camera_at(const Camera& c, const Animation& a, int frame, glm::vec3 center, float radius);

// The scene at frame i of its animation: its camera, and its lights when they follow the
// camera; Scene::frame says which frame it is. The scene itself when it has no animation.
// `scene` may itself be a frame of the path.
Scene scene_at_frame(const Scene& scene, int frame);
// The same in place: `scene` (its path's first frame, or any other) moved to frame i.
void move_along_path(Scene& scene, int frame);
// `to` takes the view of `from`, all that scene_at_frame changes: camera, lights, frame and
// path start.
void take_view(Scene& to, const Scene& from);

// The camera of frame i of the path `scene` lies on (its own camera without an animation).
Camera frame_camera(const Scene& scene, int frame);
// The cameras of frames 0..scene.frame: what time-driven effects (the hatching of Kalnins et al. 2002, §6,
// transitions) replay, so that a frame does not depend on the frames rendered before it.
std::vector<Camera> path_cameras(const Scene& scene);

}  // namespace plumbago

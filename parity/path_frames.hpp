// The frames of a scene's camera path (Scene::animation) on one backend, for `render -o DIR`,
// `bench` and the Python module (python/). The GPU backend builds a renderer per frame (a
// renderer draws the camera it was made with), sharing the preprocessing the first one made.
#pragma once

#include <memory>
#include <string>

#include "common/core/frame.hpp"
#include "common/scene/scene.hpp"

namespace plumbago {
struct Preprocessed;

class PathFrames {
 public:
  PathFrames(const Scene& scene, std::string backend) : scene_(scene), backend_(std::move(backend)) {}
  int count() const { return scene_.animation ? scene_.animation->frames : 1; }
  // Frame i, read back.
  Frame render(int frame, const FrameOptions& options = {});
  // Frame i without readback: the wall-clock ms of its passes (GPU: to glFinish), with
  // their times in `timing.ran`; `setup_ms` the time to make its renderer (GPU: uploads of
  // the frame's geometry, lights and camera; 0 for the reference).
  double timed(int frame, Frame& timing, double& setup_ms);

 private:
  const Scene& scene_;
  std::string backend_;
  std::shared_ptr<const Preprocessed> preprocessed_;
};

}  // namespace plumbago

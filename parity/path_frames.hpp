// The frames of a scene's camera path (Scene::animation) on one backend, for `render -o DIR`,
// `bench` and the Python module (python/). The GPU backend makes one renderer, on the first
// frame asked for, and moves it along the path (gpu::Renderer::camera_moved). Where a frame
// reads the one before it (coherent silhouettes, common/strokes/brush_parameters.hpp), the
// reference's carry goes from frame to frame, and the frames before the one asked for that
// were not drawn just before it are drawn first: frame k is the same asked for alone or in order.
#pragma once

#include <memory>
#include <string>

#include "common/core/frame.hpp"
#include "common/scene/scene.hpp"

namespace plumbago {
namespace gpu {
class Renderer;
}

class PathFrames {
 public:
  PathFrames(const Scene& scene, std::string backend);
  ~PathFrames();
  int count() const { return scene_.animation ? scene_.animation->frames : 1; }
  // Frame i, read back.
  Frame render(int frame, const FrameOptions& options = {});
  // Frame i without readback: the wall-clock ms of its passes (GPU: to glFinish), with
  // their times in `timing.ran`; `setup_ms` the time to make the renderer or move it there
  // (GPU: on the first frame asked for, the uploads of the geometry; after it, what the
  // camera move makes again; 0 for the reference).
  double timed(int frame, Frame& timing, double& setup_ms);

 private:
  // The GPU renderer at `frame`, made on first use.
  gpu::Renderer& gpu_at(int frame);
  // Draws the frames before `frame` that it follows and that were not drawn last, where the
  // scene's frames read the one before.
  void draw_before(int frame);

  const Scene& scene_;
  std::string backend_;
  Scene at_;  // the GPU renderer's scene, at the frame it last drew
  std::unique_ptr<gpu::Renderer> renderer_;
  bool chained_;    // frames read the one before
  int drawn_ = -1;  // the frame drawn last
  Carry carry_;     // the reference's, from the frame drawn last
};

}  // namespace plumbago

#include "parity/path_frames.hpp"

#include "common/core/passes.hpp"
#include "common/scene/animation.hpp"
#include "gpu/core/pipeline.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago {

PathFrames::PathFrames(const Scene& scene, std::string backend) : scene_(scene), backend_(std::move(backend)) {}

PathFrames::~PathFrames() = default;

gpu::Renderer& PathFrames::gpu_at(int frame) {
  if (!renderer_) {
    at_ = scene_at_frame(scene_, frame);
    renderer_ = std::make_unique<gpu::Renderer>(at_);
  } else {
    move_along_path(at_, frame);
    renderer_->camera_moved();
  }
  return *renderer_;
}

Frame PathFrames::render(int frame, const FrameOptions& options) {
  if (backend_ == "reference") return reference::render(scene_at_frame(scene_, frame), options);
  return gpu_at(frame).render(options);
}

double PathFrames::timed(int frame, Frame& timing, double& setup_ms) {
  if (backend_ == "reference") {
    setup_ms = 0;
    Stopwatch w;
    timing = reference::render(scene_at_frame(scene_, frame));
    double total = w.ms();
    for (const auto& p : timing.ran) total -= is_preprocessing(p.name) ? p.ms : 0.0;  // a frame excludes preprocessing
    return total;
  }
  Stopwatch w;
  gpu::Renderer& renderer = gpu_at(frame);
  setup_ms = w.ms();
  return renderer.render_frame(timing);
}

}  // namespace plumbago

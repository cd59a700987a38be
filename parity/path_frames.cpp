#include "parity/path_frames.hpp"

#include <algorithm>

#include "common/core/passes.hpp"
#include "common/scene/animation.hpp"
#include "gpu/core/pipeline.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago {

PathFrames::PathFrames(const Scene& scene, std::string backend) : scene_(scene), backend_(std::move(backend)) {
  std::vector<std::string> passes = passes_for(scene.effects, scene.params);
  chained_ = scene.animation && std::find(passes.begin(), passes.end(), "brush_parameters") != passes.end();
}

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

void PathFrames::draw_before(int frame) {
  if (!chained_) return;
  for (int k = drawn_ >= 0 && drawn_ < frame ? drawn_ + 1 : 0; k < frame; ++k) {
    Frame ignored;
    double setup_ms = 0;
    timed(k, ignored, setup_ms);
  }
}

Frame PathFrames::render(int frame, const FrameOptions& options) {
  draw_before(frame);
  drawn_ = frame;
  if (backend_ == "reference") {
    FrameOptions carried = options;
    carried.carry = &carry_;
    return reference::render(scene_at_frame(scene_, frame), carried);
  }
  return gpu_at(frame).render(options);
}

double PathFrames::timed(int frame, Frame& timing, double& setup_ms) {
  draw_before(frame);
  drawn_ = frame;
  if (backend_ == "reference") {
    setup_ms = 0;
    FrameOptions carried;
    carried.carry = &carry_;
    Stopwatch w;
    timing = reference::render(scene_at_frame(scene_, frame), carried);
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

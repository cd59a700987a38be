#include "parity/path_frames.hpp"

#include "common/core/passes.hpp"
#include "common/scene/animation.hpp"
#include "gpu/core/pipeline.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago {

Frame PathFrames::render(int frame, const FrameOptions& options) {
  Scene s = scene_at_frame(scene_, frame);
  if (backend_ == "reference") return reference::render(s, options);
  gpu::Renderer renderer(s, preprocessed_);
  preprocessed_ = renderer.preprocessed();
  return renderer.render(options);
}

double PathFrames::timed(int frame, Frame& timing, double& setup_ms) {
  Scene s = scene_at_frame(scene_, frame);
  if (backend_ == "reference") {
    setup_ms = 0;
    Stopwatch w;
    timing = reference::render(s);
    double total = w.ms();
    for (const auto& p : timing.ran) total -= is_preprocessing(p.name) ? p.ms : 0.0;  // a frame excludes preprocessing
    return total;
  }
  Stopwatch w;
  gpu::Renderer renderer(s, preprocessed_);
  preprocessed_ = renderer.preprocessed();
  setup_ms = w.ms();
  return renderer.render_frame(timing);
}

}  // namespace plumbago

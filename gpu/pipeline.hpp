// The GPU backend: runs the stages a scene's effects need (common/passes.hpp) through the
// GPU passes that compute them (gpu/stage.hpp), keeping every intermediate buffer in GPU
// memory. A frame ends with glFinish; per-pass times come from GL timer queries.
#pragma once

#include <memory>

#include "common/frame.hpp"
#include "common/scene.hpp"
#include "gpu/gbuffer.hpp"

namespace plumbago::gpu {

class Renderer {
 public:
  // Uploads the scene's geometry and compiles the programs the scene's passes need.
  explicit Renderer(const Scene& scene);
  ~Renderer();
  // Renders one frame and reads it back. `ran` holds GPU times per pass, plus
  // "readback" (CPU wall time of downloading the image).
  Frame render(const FrameOptions& options = {});
  // Renders one frame without reading anything back; returns wall-clock ms to glFinish
  // and fills `timing.ran` with the GPU time of each pass.
  double render_frame(Frame& timing);
  // What a frame writes of the G-buffer `stage` ("gbuffer", "sketchy_gbuffer"): what its
  // passes sample.
  GBufferChannels frame_channels(const std::string& stage) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace plumbago::gpu

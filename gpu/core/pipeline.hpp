// The GPU backend: runs the stages a scene's effects need (common/core/passes.hpp) through the
// GPU passes that compute them (gpu/core/stage.hpp), keeping every intermediate buffer in GPU
// memory. A frame ends with glFinish; per-pass times come from GL timer queries.
#pragma once

#include <memory>

#include "common/core/frame.hpp"
#include "common/scene/scene.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago {
struct Preprocessed;  // common/core/preprocess.hpp
}

namespace plumbago::gpu {

class GpuFrame;  // gpu/core/stage.hpp

class Renderer {
 public:
  // Uploads the scene's geometry and compiles the programs the scene's passes need. The
  // renderer reads `scene` while it lives. `preprocessed`, when given, is what another
  // renderer made (preprocessed()) for the same objects, styles, passes and values of
  // the parameters preprocessing reads: it is used, not made again (plumbago view, after
  // a camera move or a change to a per-frame parameter).
  explicit Renderer(const Scene& scene, std::shared_ptr<const Preprocessed> preprocessed = nullptr);
  ~Renderer();
  // The scene's view changed (common/scene/animation.hpp take_view: its camera, the lights
  // where they follow it, a path's frame): what the passes made of the old one is made again,
  // the rest kept; the next frame sizes the stroke buffers again (it reads their counts back).
  void camera_moved();
  // From now on each frame follows the one drawn before it, whatever its path frame (the
  // viewer's orbit): what carries from frame to frame (coherent silhouettes,
  // common/strokes/brush_parameters.hpp) carries into it. Else only the path's next frame
  // follows (PathFrames).
  void follow_every_frame();
  // Renders one frame and reads it back. `ran` holds the preprocessing steps that made
  // its data (once, possibly by an earlier renderer) and the GPU times per pass, plus
  // "readback" (CPU wall time of downloading the image).
  Frame render(const FrameOptions& options = {});
  // Renders one frame without reading the image back; returns wall-clock ms to glFinish
  // and fills `timing.ran` with the GPU time of each pass, `host_ms` and `readback_bytes`
  // (what its passes read back). Its strokes' lines are not kept whole on the CPU, and once
  // a frame has sized the buffers the stroke steps size theirs by (the renderer's first
  // frame, the first after camera_moved(), and every render()), it reads nothing back: its
  // buffers are as those frames sized them, which hold the same frame's; where a frame needs
  // more (a per-frame parameter changed since), the strokes past them are left out until
  // render() sizes them again.
  double render_frame(Frame& timing);
  // The last frame's image (RGB, row 0 = bottom), read back.
  Image color() const;
  // What a frame writes of the G-buffer `stage` ("gbuffer", "sketchy_gbuffer"): what its
  // passes sample.
  GBufferChannels frame_channels(const std::string& stage) const;
  // The scene's preprocessed data (common/core/preprocess.hpp), for another renderer to reuse.
  std::shared_ptr<const Preprocessed> preprocessed() const;
  // The last frame's data as its passes left them on the GPU (tests read what it wrote).
  const GpuFrame& frame() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace plumbago::gpu

// Whole frames at 800x800 (every pass of the scene's effects): the GPU frame ends with
// glFinish (no readback); the reference frame includes its ray-traced G-buffer.
// BM_Frame*: contours only; BM_PencilFrame*: every effect of Lee 2006 (contours, interior,
// cross hatching, paper). Preprocessing (curvature, textures) is not part of a frame.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "bench/frame_timing.hpp"

namespace plumbago::bench {
namespace {

const std::vector<std::string> kPencilEffects = {"contours", "interior", "crosshatch", "paper"};

void frame_gpu(benchmark::State& state, const std::string& model, const std::vector<std::string>& effects) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  scene.effects = effects;
  time_gpu_frames(state, scene);
}

void frame_reference(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (load_bench_scene(state, model, scene)) time_reference_frames(state, scene);
}

const bool registered = [] {
  register_per_model("BM_FrameGpu", [](benchmark::State& s, const std::string& m) { frame_gpu(s, m, {"contours"}); });
  register_per_model("BM_PencilFrameGpu",
                     [](benchmark::State& s, const std::string& m) { frame_gpu(s, m, kPencilEffects); });
  register_per_model("BM_FrameReference", frame_reference);
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

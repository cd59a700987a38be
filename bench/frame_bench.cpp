// Whole frames at 800x800 (every pass of the scene's effects): the GPU frame ends with
// glFinish (no readback); the reference frame includes its ray-traced G-buffer.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "gpu/context.hpp"
#include "gpu/pipeline.hpp"
#include "reference/pipeline.hpp"

namespace plumbago::bench {
namespace {

void frame_gpu(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  gpu::Renderer renderer(scene);
  renderer.render();  // warm-up
  for (auto _ : state) {
    Frame timing;
    state.SetIterationTime(renderer.render_frame(timing) * 1e-3);
  }
  state.SetLabel(gpu::Context::get().renderer());
}

void frame_reference(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  for (auto _ : state) {
    Stopwatch w;
    benchmark::DoNotOptimize(reference::render(scene));
    state.SetIterationTime(w.ms() * 1e-3);
  }
}

const bool registered = [] {
  register_per_model("BM_FrameGpu", frame_gpu);
  register_per_model("BM_FrameReference", frame_reference);
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

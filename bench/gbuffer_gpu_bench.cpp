// Rasterized G-buffer (docs/stages.md, gbuffer) at 800x800: wall time to glFinish per frame and the GL
// timer query. Its ray-traced twin is in bench/gbuffer_bench.cpp.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "common/core/frame.hpp"
#include "gpu/gl/context.hpp"
#include "gpu/gl/timer.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago::bench {
namespace {

void gbuffer_gpu(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  gpu::Context& ctx = gpu::Context::get();
  gpu::GBufferPass pass(scene);
  gpu::GBufferTargets targets = gpu::make_gbuffer_targets(scene.width, scene.height, GBufferFormat::RGBA32F);
  gpu::PassTimer timer;
  double gpu_ms = 0;
  for (auto _ : state) {
    Stopwatch w;
    timer.begin("gbuffer");
    pass.render(scene, targets);
    timer.end();
    glFinish();
    state.SetIterationTime(w.ms() * 1e-3);
    gpu_ms += timer.results().at(0).ms;
  }
  ctx.check_errors("gbuffer benchmark");
  state.counters["gl_timer_ms"] = benchmark::Counter(gpu_ms, benchmark::Counter::kAvgIterations);
  state.counters["faces"] = double(scene.objects.at(0).mesh->triangles.size());
  state.SetLabel(ctx.renderer());
}

const bool registered = [] {
  register_per_model("BM_GBufferGpu", gbuffer_gpu);
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

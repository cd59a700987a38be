// Edge detection (Nienhaus & Döllner 2003, as given in Pacheco §2) on both backends at 800x800, on the same G-buffer.
// The GPU pass also writes the lit contours (Lee et al. 2006, §4.1, Eq. 1) as its second output.
// GPU: wall time to glFinish per iteration (manual time) and the GL timer query.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "common/core/frame.hpp"
#include "common/scene/lights.hpp"
#include "gpu/gl/context.hpp"
#include "gpu/gl/timer.hpp"
#include "gpu/pencil/edge_detect.hpp"
#include "reference/pencil/edge_detect.hpp"
#include "reference/scene/gbuffer.hpp"

namespace plumbago::bench {
namespace {

void edge_detect_reference(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  auto p = scene.params.get<EdgeDetectParams>();
  for (auto _ : state) {
    Stopwatch w;
    benchmark::DoNotOptimize(reference::contour_darkness(g, p));
    state.SetIterationTime(w.ms() * 1e-3);
  }
}

void edge_detect_gpu(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  gpu::Context& ctx = gpu::Context::get();
  gpu::GBufferTargets g = gpu::upload_gbuffer(reference::trace_gbuffer(scene, scene.width, scene.height));
  gpu::Texture out = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::Texture lit = gpu::make_texture(scene.width, scene.height, GL_R32F);
  std::vector<Light> lights = view_space_lights(scene);
  auto light = scene.params.get<ContourLightParams>();
  gpu::EdgeDetectPass pass;
  gpu::PassTimer timer;
  auto p = scene.params.get<EdgeDetectParams>();
  double gpu_ms = 0;
  for (auto _ : state) {
    Stopwatch w;
    timer.begin("edge_detect");
    pass.run(g, p, lights, light, {lit, &out}, filter_rect(scene, 1));
    timer.end();
    glFinish();
    state.SetIterationTime(w.ms() * 1e-3);
    gpu_ms += timer.results().at(0).ms;
  }
  ctx.check_errors("edge_detect benchmark");
  state.counters["gl_timer_ms"] = benchmark::Counter(gpu_ms, benchmark::Counter::kAvgIterations);
  state.SetLabel(ctx.renderer());
}

const bool registered = [] {
  register_per_model("BM_EdgeDetectReference", edge_detect_reference);
  register_per_model("BM_EdgeDetectGpu", edge_detect_gpu);
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

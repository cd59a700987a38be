// Ray-traced G-buffer (docs/stages.md, gbuffer) at 800x800: BVH build, tracing and channel filling
// together, reported as ms and primary rays per second. Its raster twin is in
// bench/gbuffer_gpu_bench.cpp.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "common/core/frame.hpp"
#include "reference/scene/gbuffer.hpp"

namespace plumbago::bench {
namespace {

void gbuffer_reference(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  for (auto _ : state) {
    Stopwatch w;
    benchmark::DoNotOptimize(reference::trace_gbuffer(scene, scene.width, scene.height));
    state.SetIterationTime(w.ms() * 1e-3);
  }
  double rays = double(scene.width) * scene.height;
  state.counters["rays_per_s"] = benchmark::Counter(rays, benchmark::Counter::kIsIterationInvariantRate);
}

const bool registered = [] {
  register_per_model("BM_GBufferReference", gbuffer_reference);
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

// The machine's own limits (gpu/core/limits.hpp) as Google Benchmark cases, at 800x800 with
// each bench model's triangles: the probes `plumbago bench --limits` reads every GPU pass
// against, so that a run of the pass benchmarks here can be read the same way.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "gpu/core/limits.hpp"
#include "gpu/gl/context.hpp"

namespace plumbago::bench {
namespace {

void probe(benchmark::State& state, gpu::Probe which, const std::string& model) {
  Scene scene;
  if (!load_bench_scene(state, model, scene)) return;
  gpu::Context& context = gpu::Context::get();
  gpu::measure_probe(which, scene, 1);  // warm-up: compilation, first-use allocations
  for (auto _ : state) state.SetIterationTime(gpu::measure_probe(which, scene, 1) * 1e-3);
  state.SetLabel(context.renderer());
}

const bool registered = [] {
  for (gpu::Probe p : gpu::kProbes)
    register_per_model(std::string("BM_Limit/") + gpu::probe_name(p),
                       [p](benchmark::State& s, const std::string& model) { probe(s, p, model); });
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

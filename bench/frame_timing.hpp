// Whole-frame timing loops shared by the frame benchmarks: the GPU frame ends with
// glFinish (no readback), after one warm-up frame; the reference frame is timed whole.
#pragma once

#include <benchmark/benchmark.h>

#include "common/core/frame.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/gl/context.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago::bench {

inline void time_gpu_frames(benchmark::State& state, const Scene& scene) {
  gpu::Renderer renderer(scene);
  renderer.render();  // warm-up
  for (auto _ : state) {
    Frame timing;
    state.SetIterationTime(renderer.render_frame(timing) * 1e-3);
  }
  state.SetLabel(gpu::Context::get().renderer());
}

inline void time_reference_frames(benchmark::State& state, const Scene& scene) {
  for (auto _ : state) {
    Stopwatch w;
    benchmark::DoNotOptimize(reference::render(scene));
    state.SetIterationTime(w.ms() * 1e-3);
  }
}

}  // namespace plumbago::bench

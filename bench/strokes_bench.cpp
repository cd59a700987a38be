// Stroke-based rendering at 800x800 (Kalnins et al. 2002, SPEC 4; the paper: 20 fps for a
// 5K-face cup on a GeForce3): the feature lines alone (CPU, shared by both backends), and
// whole frames of every object drawn with strokes (base coat, paper, ID image,
// visibility, strokes) on each backend. `plumbago render --stats` splits a frame by pass.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "bench/frame_timing.hpp"
#include "common/strokes.hpp"

namespace plumbago::bench {
namespace {

bool load_strokes_scene(benchmark::State& state, const std::string& model, Scene& scene) {
  if (!load_bench_scene(state, model, scene)) return false;
  for (SceneObject& o : scene.objects) o.style = Style::Strokes;
  scene.effects = {"basecoat", "strokes"};
  return true;
}

void count_lines(benchmark::State& state, const Scene& scene) {
  WindowLines lines = window_lines(scene, scene.params.get<StrokesParams>());
  double length = 0;
  for (const WindowPath& p : lines.paths) length += p.length_px;
  state.counters["faces"] = lines.face_count;
  state.counters["paths"] = double(lines.paths.size());
  state.counters["samples"] = length / scene.params.get<StrokesParams>().vis_step_px;
}

void feature_lines_cpu(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_strokes_scene(state, model, scene)) return;
  auto p = scene.params.get<StrokesParams>();
  for (auto _ : state) {
    Stopwatch w;
    benchmark::DoNotOptimize(window_lines(scene, p));
    state.SetIterationTime(w.ms() * 1e-3);
  }
  count_lines(state, scene);
}

void strokes_frame_gpu(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_strokes_scene(state, model, scene)) return;
  time_gpu_frames(state, scene);
  count_lines(state, scene);
}

void strokes_frame_reference(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_strokes_scene(state, model, scene)) return;
  time_reference_frames(state, scene);
  count_lines(state, scene);
}

const bool registered = [] {
  register_per_model("BM_StrokeFeatureLines", feature_lines_cpu);
  register_per_model("BM_StrokeFrameGpu", strokes_frame_gpu);
  register_per_model("BM_StrokeFrameReference", strokes_frame_reference);
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

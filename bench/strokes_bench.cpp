// Stroke-based rendering at 800x800 (Kalnins et al. 2002; the paper: 20 fps for a
// 5K-face cup on a GeForce3): the feature lines alone (CPU, shared by both backends), and
// whole frames of every object drawn with strokes (base coat, paper, ID image,
// visibility, strokes) on each backend; the GPU frame also reports each pass's GL timer
// (counters <pass>_gl_ms, the GPU side only), host_ms and readback_bytes (common/core/frame.hpp),
// alone and with the silhouette tables. And the readback A/B: Kalnins et al. read
// the whole ID image back every frame; Plumbago reads back only the sample flags.
#include <benchmark/benchmark.h>

#include <map>
#include "bench/bench_scenes.hpp"
#include "bench/frame_timing.hpp"

#include "common/strokes/strokes.hpp"
#include "gpu/gl/gl_objects.hpp"

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

// With `tables`, the frame also computes the silhouette tables (segments, chains, arcs).
void strokes_frame_gpu(benchmark::State& state, const std::string& model, bool tables) {
  Scene scene;
  if (!load_strokes_scene(state, model, scene)) return;
  if (tables) scene.effects.push_back("line_tables");
  gpu::Renderer renderer(scene);
  renderer.render();  // warm-up
  std::map<std::string, double> pass_ms;
  double host_ms = 0, readback_bytes = 0;
  for (auto _ : state) {
    Frame timing;
    state.SetIterationTime(renderer.render_frame(timing) * 1e-3);
    for (const PassTime& t : timing.ran) pass_ms[t.name] += t.ms;
    host_ms += timing.host_ms, readback_bytes += double(timing.readback_bytes);
  }
  for (const auto& [pass, ms] : pass_ms)
    state.counters[pass + "_gl_ms"] = benchmark::Counter(ms, benchmark::Counter::kAvgIterations);
  state.counters["host_ms"] = benchmark::Counter(host_ms, benchmark::Counter::kAvgIterations);
  state.counters["readback_bytes"] = benchmark::Counter(readback_bytes, benchmark::Counter::kAvgIterations);
  state.SetLabel(gpu::Context::get().renderer());
  count_lines(state, scene);
}

// What a frame reads back to decide visibility: the whole ID image (RG32UI at 800x800, as
// Kalnins et al.) against the flags of `samples` samples (one uint each, as Plumbago).
void readback(benchmark::State& state, bool whole_image) {
  gpu::Context& ctx = gpu::Context::get();
  const int side = 800, samples = int(state.range(0));
  gpu::Texture ids = gpu::make_texture(side, side, GL_RG32UI);
  gpu::Buffer flags = gpu::make_buffer(nullptr, size_t(samples) * sizeof(uint32_t));
  std::vector<uint32_t> read(static_cast<size_t>(samples));
  for (auto _ : state) {
    Stopwatch w;
    if (whole_image)
      benchmark::DoNotOptimize(gpu::download_texture_u32(ids, 2));
    else
      gpu::read_buffer(flags, read.data(), read.size() * sizeof(uint32_t));  // as gpu/strokes/visibility.cpp
    state.SetIterationTime(w.ms() * 1e-3);
  }
  ctx.check_errors("readback benchmark");
  state.SetLabel(ctx.renderer());
}

void strokes_frame_reference(benchmark::State& state, const std::string& model) {
  Scene scene;
  if (!load_strokes_scene(state, model, scene)) return;
  time_reference_frames(state, scene);
  count_lines(state, scene);
}

const bool registered = [] {
  register_per_model("BM_StrokeFeatureLines", feature_lines_cpu);
  for (bool tables : {false, true})
    register_per_model(
        tables ? "BM_StrokeFrameGpuWithTables" : "BM_StrokeFrameGpu",
        [tables](benchmark::State& s, const std::string& model) { strokes_frame_gpu(s, model, tables); });
  register_per_model("BM_StrokeFrameReference", strokes_frame_reference);
  for (bool whole : {true, false})
    benchmark::RegisterBenchmark(whole ? "BM_StrokeReadbackIdImage800" : "BM_StrokeReadbackFlags",
                                 [whole](benchmark::State& s) { readback(s, whole); })
        ->Arg(4096)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime();
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

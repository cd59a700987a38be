// Sketchy frames at 800x800 (Nienhaus & Döllner 2004; the paper: the Ogre at
// 20 fps, 800x800, GeForce FX 5600), one per style, every object drawn sketchy. The GPU
// frame ends with glFinish (no readback); the reference frame includes its ray-traced
// G-buffers. The noise textures are preprocessing, not part of a frame.
#include <benchmark/benchmark.h>

#include "bench/bench_scenes.hpp"
#include "bench/frame_timing.hpp"

namespace plumbago::bench {
namespace {

const char* const kStyles[] = {"default", "repeat", "rough", "object"};

bool load_sketchy_scene(benchmark::State& state, const std::string& model, const std::string& style, Scene& scene) {
  if (!load_bench_scene(state, model, scene)) return false;
  for (SceneObject& o : scene.objects) o.style = Style::Sketchy;
  scene.effects = {"sketchy"};
  scene.params.set("sketchy.style", style);
  return true;
}

void sketchy_frame_gpu(benchmark::State& state, const std::string& model, const std::string& style) {
  Scene scene;
  if (load_sketchy_scene(state, model, style, scene)) time_gpu_frames(state, scene);
}

void sketchy_frame_reference(benchmark::State& state, const std::string& model, const std::string& style) {
  Scene scene;
  if (load_sketchy_scene(state, model, style, scene)) time_reference_frames(state, scene);
}

const bool registered = [] {
  for (const char* style : kStyles) {
    std::string s = style;
    register_per_model("BM_SketchyFrameGpu_" + s,
                       [s](benchmark::State& st, const std::string& m) { sketchy_frame_gpu(st, m, s); });
    register_per_model("BM_SketchyFrameReference_" + s,
                       [s](benchmark::State& st, const std::string& m) { sketchy_frame_reference(st, m, s); });
  }
  return true;
}();

}  // namespace
}  // namespace plumbago::bench

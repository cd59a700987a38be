// Timing a scene's frames on one backend: `plumbago bench` and the Python module's
// Scene.bench (python/). Per pass: ms (GL timestamp queries on the GPU); per frame: the
// wall-clock ms of every pass up to the final image in GPU memory, ended by glFinish
// (readback is timed on its own). Reports; never asserts a speed.
#pragma once

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "common/scene/scene.hpp"
#include "common/util/image.hpp"

namespace plumbago {

// Difference of one buffer from the same buffer of an earlier run.
struct BufferError {
  double max_abs = 0, mean_abs = 0, rmse = 0, over_tolerance = 0;
};

struct BenchResult {
  std::string scene, backend;
  int faces = 0, width = 0, height = 0;
  double strokes = 0;  // the strokes a frame draws (Frame::counts "strokes"; of a path, its first frame)
  std::map<std::string, double> counts;  // what its stroke stages made (Frame::counts; of a path, its first frame)
  double frame_ms = 0;                   // median
  double host_ms = 0;                    // GPU: median CPU time of the GL thread per frame (Frame::host_ms)
  size_t readback_bytes = 0;             // GPU: the most a timed frame read back
  std::map<std::string, double> stages;  // mean ms per pass of a frame
  std::map<std::string, double> preprocessing;  // once per scene, not part of a frame
  std::map<std::string, BufferError> errors;    // bench --against
  std::vector<std::string> missing;             // bench --against: buffers with no saved counterpart
  // A camera path (Scene::animation): some of its frames (timed_path_frames) timed once, in order.
  int path_frames = 0, timed_path_frames = 0;
  double path_ms = 0, slowest_ms = 0;    // the timed frames' sum and the slowest
  double setup_ms = 0;                   // median per frame: moving the renderer there (GPU)
  std::map<std::string, double> limits;  // bench --limits: each probe's ms at the scene's size (GPU)
};

// After the timed frames, one more frame rendered with its intermediate buffers (the final
// image as "compose.color"), untimed, for a caller that saves or compares them.
using KeptBuffers = std::function<void(std::map<std::string, Image>, BenchResult&)>;

// `frames` frames of the scene's camera on one backend, after an untimed warm-up (GPU:
// shader compilation, first-use allocations).
BenchResult bench_reference(const Scene& scene, int frames, const KeptBuffers& keep = {});
BenchResult bench_gpu(const Scene& scene, int frames, const KeptBuffers& keep = {});
// The frames of a camera path of `count` frames timed under a cap of `cap`: every one, or
// `cap` of them spread evenly from the first to the last.
std::vector<int> timed_path_frames(int count, int cap);
// A scene with a camera path: timed_path_frames(its frames, cap) timed once each (frame_ms
// their median), after one untimed frame that runs the preprocessing and compiles the shaders.
BenchResult bench_path(const Scene& scene, const std::string& backend, int cap, const KeptBuffers& keep = {});
// bench_path (capped at `frames`) for a scene with a camera path, else bench_gpu or
// bench_reference ("gpu" or "reference").
BenchResult bench_scene(const Scene& scene, const std::string& backend, int frames, const KeptBuffers& keep = {});

// A pass's time as a multiple of its probe's (bench --limits), and the probe's name.
std::pair<double, std::string> probe_multiple(const BenchResult& r, const std::string& pass, double ms);
// What `plumbago bench --json` prints of one result.
nlohmann::json result_json(const BenchResult& r);

}  // namespace plumbago

#include "parity/bench.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/passes.hpp"
#include "common/pencil/compose.hpp"
#include "gpu/core/limits.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/core/stage.hpp"
#include "parity/path_frames.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago {
namespace {

void add_pass_times(const Frame& f, int frames, BenchResult& r) {
  for (const auto& p : f.ran) {
    if (is_preprocessing(p.name))
      r.preprocessing[p.name] = p.ms;
    else
      r.stages[p.name] += p.ms / frames;
  }
}

void set_counts(BenchResult& r, const Frame& f) {
  r.counts = f.counts;
  auto strokes = f.counts.find("strokes");
  r.strokes = strokes == f.counts.end() ? 0 : strokes->second;
}

BenchResult new_result(const Scene& scene, const std::string& backend) {
  BenchResult r;
  r.scene = scene.source;
  r.backend = backend;
  for (const auto& o : scene.objects) r.faces += int(o.mesh->triangles.size());
  r.width = scene.width;
  r.height = scene.height;
  return r;
}

// The buffers of the untimed extra frame, the final image included as "compose.color".
std::map<std::string, Image> kept_buffers(Frame f) {
  std::map<std::string, Image> out = std::move(f.buffers);
  out[kComposeColor.name] = std::move(f.color);
  return out;
}

}  // namespace

BenchResult bench_reference(const Scene& scene, int frames, const KeptBuffers& keep) {
  BenchResult r = new_result(scene, "reference");
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    Stopwatch w;
    Frame f = reference::render(scene);
    double total = w.ms();
    set_counts(r, f);
    for (const auto& p : f.ran) total -= is_preprocessing(p.name) ? p.ms : 0.0;  // a frame excludes preprocessing
    ms.push_back(total);
    add_pass_times(f, frames, r);
  }
  r.frame_ms = median(ms);
  if (keep) keep(kept_buffers(reference::render(scene, FrameOptions{true})), r);
  return r;
}

BenchResult bench_gpu(const Scene& scene, int frames, const KeptBuffers& keep) {
  BenchResult r = new_result(scene, "gpu");
  gpu::Renderer renderer(scene);
  Frame first = renderer.render();  // warm-up: shader compilation, first-use allocations
  for (const auto& p : first.ran)
    if (is_preprocessing(p.name)) r.preprocessing[p.name] = p.ms;
  set_counts(r, first);
  std::vector<double> ms, host;
  for (int i = 0; i < frames; ++i) {
    Frame f;
    ms.push_back(renderer.render_frame(f));
    host.push_back(f.host_ms);
    r.readback_bytes = std::max(r.readback_bytes, f.readback_bytes);
    add_pass_times(f, frames, r);
  }
  r.frame_ms = median(ms);
  r.host_ms = median(host);
  if (keep) keep(kept_buffers(renderer.render(FrameOptions{true})), r);
  return r;
}

std::vector<int> timed_path_frames(int count, int cap) {
  std::vector<int> out;
  int n = std::min(count, cap);
  for (int k = 0; k < n; ++k) out.push_back(n == 1 ? 0 : int(std::lround(double(k) * (count - 1) / (n - 1))));
  return out;
}

BenchResult bench_path(const Scene& scene, const std::string& backend, int cap, const KeptBuffers& keep) {
  BenchResult r = new_result(scene, backend);
  PathFrames path(scene, backend);
  Frame first = path.render(0);
  for (const auto& p : first.ran)
    if (is_preprocessing(p.name)) r.preprocessing[p.name] = p.ms;
  set_counts(r, first);
  std::vector<double> ms, setup, host;
  std::vector<int> timed = timed_path_frames(path.count(), cap);
  r.path_frames = path.count();
  r.timed_path_frames = int(timed.size());
  for (int i : timed) {
    Frame f;
    double setup_ms = 0;
    ms.push_back(path.timed(i, f, setup_ms));
    setup.push_back(setup_ms);
    host.push_back(f.host_ms);
    r.readback_bytes = std::max(r.readback_bytes, f.readback_bytes);
    add_pass_times(f, int(timed.size()), r);
    r.path_ms += ms.back();
    r.slowest_ms = std::max(r.slowest_ms, ms.back());
  }
  r.frame_ms = median(ms);
  r.setup_ms = median(setup);
  r.host_ms = median(host);
  if (keep) keep(kept_buffers(path.render(0, FrameOptions{true})), r);
  return r;
}

BenchResult bench_scene(const Scene& scene, const std::string& backend, int frames, const KeptBuffers& keep) {
  if (scene.animation) return bench_path(scene, backend, frames, keep);
  return backend == "gpu" ? bench_gpu(scene, frames, keep) : bench_reference(scene, frames, keep);
}

// A pass's time as a multiple of its probe's (--limits), and the probe's name.
std::pair<double, std::string> probe_multiple(const BenchResult& r, const std::string& pass, double ms) {
  std::string probe = gpu::probe_name(gpu::probe_of(pass));
  auto it = r.limits.find(probe);
  return {it == r.limits.end() || it->second <= 0 ? 0.0 : ms / it->second, probe};
}

nlohmann::json result_json(const BenchResult& r) {
  nlohmann::json j{{"scene", r.scene},       {"backend", r.backend},        {"faces", r.faces},
                   {"strokes", r.strokes},   {"size", {r.width, r.height}}, {"fps", 1000 / r.frame_ms},
                   {"frame_ms", r.frame_ms}, {"stages", r.stages},          {"preprocessing", r.preprocessing}};
  if (r.backend == "gpu") j["host_ms"] = r.host_ms, j["readback_bytes"] = r.readback_bytes;
  if (!r.counts.empty()) j["counts"] = r.counts;
  if (!r.limits.empty()) {
    j["limits"] = r.limits;
    for (const auto& [name, ms] : r.stages) {
      auto [multiple, probe] = probe_multiple(r, name, ms);
      j["probe_multiples"][name] = {{"probe", probe}, {"multiple", multiple}};
    }
  }
  if (r.path_frames)
    j["path"] = {{"frames", r.path_frames},
                 {"timed_frames", r.timed_path_frames},
                 {"ms", r.path_ms},
                 {"slowest_ms", r.slowest_ms},
                 {"setup_ms", r.setup_ms}};
  if (!r.errors.empty() || !r.missing.empty()) {
    nlohmann::json e = nlohmann::json::object();
    for (const auto& [name, x] : r.errors)
      e[name] = {
          {"max_abs", x.max_abs}, {"mean_abs", x.mean_abs}, {"rmse", x.rmse}, {"over_tolerance", x.over_tolerance}};
    j["errors"] = e;
    j["missing"] = r.missing;
  }
  return j;
}

}  // namespace plumbago

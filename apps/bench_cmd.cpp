// plumbago bench [SCENE ...] [--frames N] [--backend gpu|reference|both] [--json]
// Per backend: per-pass ms (GL timestamp queries on the GPU) and whole-frame fps, next to
// the papers' claims. A GPU frame is every pass up to the final image in GPU memory,
// ended by glFinish; readback is timed on its own. Reports; never asserts a speed.
#include <algorithm>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "apps/scene_options.hpp"
#include "bench/paper_claims.hpp"
#include "common/passes.hpp"
#include "gpu/context.hpp"
#include "gpu/pipeline.hpp"
#include "reference/pipeline.hpp"

namespace plumbago {
namespace {

struct BenchOptions {
  std::vector<std::string> scenes;
  std::vector<std::string> assignments;
  std::string size, backend = "both";
  int frames = 20;
  bool json = false;
};

struct BenchResult {
  std::string scene, backend;
  double frame_ms = 0;  // median
  std::map<std::string, double> stages;         // mean ms per pass of a frame
  std::map<std::string, double> preprocessing;  // once per scene, not part of a frame
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void add_pass_times(const Frame& f, int frames, BenchResult& r) {
  for (const auto& p : f.ran) {
    if (is_preprocessing(p.name)) r.preprocessing[p.name] = p.ms;
    else r.stages[p.name] += p.ms / frames;
  }
}

BenchResult bench_reference(const Scene& scene, int frames) {
  BenchResult r{scene.source, "reference", 0, {}, {}};
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    Stopwatch w;
    Frame f = reference::render(scene);
    double total = w.ms();
    for (const auto& p : f.ran) total -= is_preprocessing(p.name) ? p.ms : 0.0;  // a frame excludes preprocessing
    ms.push_back(total);
    add_pass_times(f, frames, r);
  }
  r.frame_ms = median(ms);
  return r;
}

BenchResult bench_gpu(const Scene& scene, int frames) {
  BenchResult r{scene.source, "gpu", 0, {}, {}};
  gpu::Renderer renderer(scene);
  for (const auto& p : renderer.render().ran)  // warm-up: shader compilation, first-use allocations
    if (is_preprocessing(p.name)) r.preprocessing[p.name] = p.ms;
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    Frame f;
    ms.push_back(renderer.render_frame(f));
    add_pass_times(f, frames, r);
  }
  r.frame_ms = median(ms);
  return r;
}

void print_text(const std::vector<BenchResult>& results) {
  std::printf("renderer: %s\n", gpu::Context::get().renderer().c_str());
  for (const auto& r : results) {
    std::printf("%s [%s]: %.2f ms/frame = %.1f fps\n", r.scene.c_str(), r.backend.c_str(), r.frame_ms, 1000 / r.frame_ms);
    for (const auto& [name, ms] : r.stages) std::printf("  %-24s %9.3f ms\n", name.c_str(), ms);
    for (const auto& [name, ms] : r.preprocessing) std::printf("  preprocessing %-10s %9.3f ms (once, not in the frame)\n", name.c_str(), ms);
  }
  std::printf("\npapers' claims (their hardware):\n");
  for (const auto& c : paper_claims())
    std::printf("  %-26s %-26s %7d faces  %-10s %g-%g fps  (%s)\n", c.paper.c_str(), c.scene.c_str(), c.faces,
                c.resolution.c_str(), c.fps_low, c.fps_high, c.hardware.c_str());
}

void print_json(const std::vector<BenchResult>& results) {
  nlohmann::json j{{"renderer", gpu::Context::get().renderer()}, {"results", nlohmann::json::array()}};
  for (const auto& r : results)
    j["results"].push_back({{"scene", r.scene}, {"backend", r.backend}, {"fps", 1000 / r.frame_ms},
                            {"frame_ms", r.frame_ms}, {"stages", r.stages}, {"preprocessing", r.preprocessing}});
  std::printf("%s\n", j.dump(2).c_str());
}

void run(const BenchOptions& o) {
  std::vector<BenchResult> results;
  std::vector<std::string> scenes = o.scenes.empty() ? std::vector<std::string>{""} : o.scenes;
  for (const auto& name : scenes) {
    SceneOptions so{name, o.size, o.assignments};
    Scene scene = so.load();
    if (o.backend != "reference") results.push_back(bench_gpu(scene, o.frames));
    if (o.backend != "gpu") results.push_back(bench_reference(scene, std::max(1, o.frames / 10)));
  }
  o.json ? print_json(results) : print_text(results);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("bench", "Frame rate and per-pass times on both backends, next to the papers' claims");
  cmd->add_option("scenes", o->scenes, "Scene files or builtin:NAME (default: the built-in CAD part)");
  cmd->add_option("--frames", o->frames, "Frames to time on the GPU (the reference times a tenth)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--backend", o->backend, "gpu, reference or both")
      ->check(CLI::IsMember({"gpu", "reference", "both"}))
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WxH");
  cmd->add_option("--set", o->assignments, "Override a parameter: stage.name=value");
  cmd->add_flag("--json", o->json, "One JSON object {results: [{scene, backend, fps, stages}]}");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago

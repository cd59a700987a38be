// plumbago bench [SCENE ...] [--frames N] [--reference-frames N] [--backend gpu|reference|both] [--json]
//                [--save DIR] [--against DIR] [--buffers a,b] [--tolerance T] [--paper]
// Per backend: per-pass ms (GL timestamp queries on the GPU) and whole-frame fps, next to
// the papers' claims. A GPU frame is every pass up to the final image in GPU memory,
// ended by glFinish; readback is timed on its own. Reports; never asserts a speed.
//
// Accuracy next to time (experiments/): after the timed frames, one more frame is
// rendered with its intermediate buffers kept (not timed). --save DIR writes them as
// DIR/<backend>/<buffer>.exr (the final image is "compose.color"); --against DIR compares
// them with DIR/<buffer>.exr saved by an earlier run (another backend, or the most
// accurate setting of a stage) and reports the difference per buffer.
//
// --limits: the machine's own limits at each scene's size (gpu/core/limits.hpp: trivial and
// 3x3-fetch passes as fragment and compute work, the scene's triangles rasterized, a
// readback), and each GPU pass as a multiple of the probe of its kind.
//
// --paper: the papers' claimed frame rates (bench/paper_claims.hpp) next to ours for the
// closest scene each claim names, with the machine and the GL renderer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "apps/command.hpp"
#include "apps/scene_options.hpp"
#include "bench/paper_claims.hpp"
#include "common/core/passes.hpp"
#include "common/util/image_compare.hpp"
#include "common/util/output_file.hpp"
#include "gpu/core/limits.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/gl/context.hpp"
#include "parity/bench.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

struct BenchOptions {
  std::vector<std::string> scenes;
  std::vector<std::string> assignments;
  std::string size, backend = "both";
  int frames = 20;
  int reference_frames = 0;  // 0: a tenth of --frames, at least 1
  bool json = false;
  bool paper = false;
  bool limits = false;
  std::string save_dir, against_dir;
  std::vector<std::string> buffers;  // empty: all
  double tolerance = 0.05;
};

bool wanted(const BenchOptions& o, const std::string& name) {
  return o.buffers.empty() || std::find(o.buffers.begin(), o.buffers.end(), name) != o.buffers.end();
}

BufferError buffer_error(const Image& a, const Image& b, double tolerance) {
  ImageDiff d = compare_images(a, b, tolerance);
  BufferError e{d.max_abs, 0, d.rmse, d.over_tolerance};
  double sum = 0;
  for (size_t i = 0; i < a.data.size(); ++i) sum += std::abs(double(a.data[i]) - double(b.data[i]));
  e.mean_abs = a.data.empty() ? 0 : sum / double(a.data.size());
  return e;
}

// --save: every target checked before the first is written, all committed by run().
void save(const std::map<std::string, Image>& buffers, const fs::path& dir, OutputFiles& out) {
  out.folder(dir.string());
  ImageFiles files;
  for (const auto& [name, img] : buffers) files.emplace_back((dir / (name + ".exr")).string(), [&img] { return img; });
  write_images(files, out);
}

void save_and_compare(const BenchOptions& o, std::map<std::string, Image> buffers, BenchResult& r, OutputFiles& out) {
  for (auto it = buffers.begin(); it != buffers.end();) it = wanted(o, it->first) ? std::next(it) : buffers.erase(it);
  if (!o.save_dir.empty()) save(buffers, fs::path(o.save_dir) / r.backend, out);
  if (!o.against_dir.empty()) {
    for (const auto& [name, img] : buffers) {
      fs::path p = fs::path(o.against_dir) / (name + ".exr");
      if (!fs::exists(p)) {
        r.missing.push_back(name);
        continue;
      }
      Image ref = read_image(p.string());
      if (ref.width != img.width || ref.height != img.height)
        throw std::invalid_argument("--against: " + p.string() + " is " + std::to_string(ref.width) + "x" +
                                    std::to_string(ref.height) + ", this run's " + name + " is " +
                                    std::to_string(img.width) + "x" + std::to_string(img.height));
      // EXR files hold 1, 3 or 4 channels; a 1-channel buffer may come back as 3 equal ones.
      if (ref.channels != img.channels) {
        Image same(ref.width, ref.height, img.channels);
        for (size_t i = 0; i < same.pixels(); ++i)
          for (int c = 0; c < img.channels; ++c)
            same.data[i * img.channels + c] = ref.data[i * ref.channels + std::min(c, ref.channels - 1)];
        ref = std::move(same);
      }
      r.errors[name] = buffer_error(img, ref, o.tolerance);
    }
  }
}

int reference_frames(const BenchOptions& o) {
  return o.reference_frames ? o.reference_frames : std::max(1, o.frames / 10);
}

// --save and --against: what to do with the untimed frame's buffers.
KeptBuffers kept(const BenchOptions& o, OutputFiles& out) {
  if (o.save_dir.empty() && o.against_dir.empty()) return {};
  return [&o, &out](std::map<std::string, Image> buffers, BenchResult& r) {
    save_and_compare(o, std::move(buffers), r, out);
  };
}

// --limits: the machine's limits at the scene's size, next to a GPU result of still frames.
BenchResult with_limits(const BenchOptions& o, const Scene& scene, BenchResult r) {
  if (o.limits && r.backend == "gpu" && !r.path_frames)
    for (const gpu::ProbeTime& p : gpu::measure_limits(scene)) r.limits[gpu::probe_name(p.probe)] = p.ms;
  return r;
}

// "AMD EPYC 7B13 (2 threads)": the first model name in /proc/cpuinfo and the hardware threads.
std::string machine_name() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      size_t colon = line.find(':');
      if (colon != std::string::npos) model = line.substr(line.find_first_not_of(" \t", colon + 1));
      break;
    }
  return model + " (" + std::to_string(std::thread::hardware_concurrency()) + " threads)";
}

std::string fps_range(const PaperClaim& c) {
  char buf[64];
  if (c.fps_low == c.fps_high)
    std::snprintf(buf, sizeof buf, "%g", c.fps_low);
  else
    std::snprintf(buf, sizeof buf, "%g-%g", c.fps_low, c.fps_high);
  return buf;
}

void print_text(const std::vector<BenchResult>& results) {
  std::printf("renderer: %s\n", gpu::Context::get().renderer().c_str());
  for (const auto& r : results) {
    std::printf("%s [%s]: %.2f ms/frame = %.1f fps\n", r.scene.c_str(), r.backend.c_str(), r.frame_ms,
                1000 / r.frame_ms);
    if (r.backend == "gpu")
      std::printf("  host %.2f ms (CPU time of the GL thread), read back %zu bytes a frame%s\n", r.host_ms,
                  r.readback_bytes,
                  r.path_frames && r.readback_bytes ? " (a path's frame sizes the stroke buffers again)" : "");
    std::string counts;
    for (const char* name : {"segments", "chains", "paths", "samples", "strokes"})
      if (auto it = r.counts.find(name); it != r.counts.end())
        counts += std::string(counts.empty() ? "" : ", ") + name + " " + std::to_string(int64_t(it->second));
    if (!counts.empty()) std::printf("  counts: %s\n", counts.c_str());
    if (r.path_frames)
      std::printf(
          "  camera path: %d of its %d frames in %.1f ms, slowest %.2f ms; moving the renderer there %.2f ms "
          "(not in the frame)\n",
          r.timed_path_frames, r.path_frames, r.path_ms, r.slowest_ms, r.setup_ms);
    for (const auto& [name, ms] : r.stages) {
      auto [multiple, probe] = probe_multiple(r, name, ms);
      if (r.limits.empty())
        std::printf("  %-24s %9.3f ms\n", name.c_str(), ms);
      else
        std::printf("  %-24s %9.3f ms = %7.1f x %s\n", name.c_str(), ms, multiple, probe.c_str());
    }
    for (const auto& [probe, ms] : r.limits) std::printf("  probe %-18s %9.3f ms\n", probe.c_str(), ms);
    for (const auto& [name, ms] : r.preprocessing)
      std::printf("  preprocessing %-10s %9.3f ms (once, not in the frame)\n", name.c_str(), ms);
    for (const auto& [name, e] : r.errors)
      std::printf("  error %-36s max %.4g  mean %.4g  rmse %.4g  over tolerance %.3g%%\n", name.c_str(), e.max_abs,
                  e.mean_abs, e.rmse, 100 * e.over_tolerance);
    for (const auto& name : r.missing) std::printf("  error %-36s (nothing saved to compare with)\n", name.c_str());
  }
  std::printf("\npapers' claims (their hardware; `plumbago bench --paper` runs ours next to them):\n");
  const PaperClaim* last = nullptr;
  for (const auto& c : paper_claims()) {
    if (last && last->paper == c.paper && last->scene == c.scene) continue;  // one claim, two of our scenes
    last = &c;
    std::printf("  %-26s %-26s %7d faces  %-10s %s fps  (%s)\n", c.paper.c_str(), c.scene.c_str(), c.faces,
                c.resolution.c_str(), fps_range(c).c_str(), c.hardware.c_str());
  }
}

void print_json(const BenchOptions& o, const std::vector<BenchResult>& results) {
  nlohmann::json j{
      {"renderer", gpu::Context::get().renderer()}, {"machine", machine_name()}, {"results", nlohmann::json::array()}};
  if (!o.against_dir.empty()) j["against"] = o.against_dir, j["tolerance"] = o.tolerance;
  for (const auto& r : results) j["results"].push_back(result_json(r));
  std::printf("%s\n", j.dump(2).c_str());
}

// --- the papers' claims next to ours ---------------------------------------------------

struct ClaimRun {
  const PaperClaim* claim;
  std::string ours;                     // scene file, "" when Plumbago has no such configuration
  std::optional<BenchResult> gpu, ref;  // absent when not run
  std::string note;                     // why not run
};

std::vector<ClaimRun> run_paper(const BenchOptions& o, OutputFiles& out) {
  std::vector<ClaimRun> runs;
  std::map<std::string, std::pair<std::optional<BenchResult>, std::optional<BenchResult>>> done;  // a scene is run once
  for (const auto& c : paper_claims()) {
    ClaimRun run{&c, c.plumbago_scene, {}, {}, c.plumbago_note};
    if (!c.plumbago_scene.empty()) {
      if (!done.count(c.plumbago_scene)) {
        std::optional<BenchResult> g, r;
        try {
          SceneOptions so{(fs::path(PLUMBAGO_SOURCE_DIR) / c.plumbago_scene).string(), o.size, o.assignments};
          Scene scene = so.load();
          scene.source = c.plumbago_scene;
          if (o.backend != "reference") g = with_limits(o, scene, bench_gpu(scene, o.frames, kept(o, out)));
          if (o.backend != "gpu") r = bench_reference(scene, reference_frames(o), kept(o, out));
        } catch (const std::exception& e) {
          run.note = std::string("not run: ") + e.what();
        }
        done[c.plumbago_scene] = {g, r};
      }
      std::tie(run.gpu, run.ref) = done[c.plumbago_scene];
    }
    runs.push_back(run);
  }
  return runs;
}

void print_paper(const BenchOptions& o, const std::vector<ClaimRun>& runs) {
  std::string renderer = gpu::Context::get().renderer(), machine = machine_name();
  if (o.json) {
    nlohmann::json j{{"machine", machine}, {"renderer", renderer}, {"claims", nlohmann::json::array()}};
    for (const auto& r : runs) {
      const PaperClaim& c = *r.claim;
      nlohmann::json x{
          {"paper", c.paper},     {"scene", c.scene},       {"faces", c.faces},       {"resolution", c.resolution},
          {"fps_low", c.fps_low}, {"fps_high", c.fps_high}, {"hardware", c.hardware}, {"style", c.style},
          {"ours_scene", r.ours}, {"note", r.note}};
      x["ours_gpu"] = r.gpu ? result_json(*r.gpu) : nlohmann::json();
      x["ours_reference"] = r.ref ? result_json(*r.ref) : nlohmann::json();
      j["claims"].push_back(x);
    }
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf("machine:     %s\nGL renderer: %s\n\n", machine.c_str(), renderer.c_str());
  std::printf("%-25s %-29s %7s %-11s %-9s | %-28s %7s %7s %-9s %8s %8s\n", "paper", "their scene", "faces",
              "resolution", "their fps", "our closest configuration", "faces", "strokes", "size", "GPU fps", "CPU fps");
  for (const auto& r : runs) {
    const PaperClaim& c = *r.claim;
    std::string faces = c.faces ? std::to_string(c.faces) : "?";
    std::printf("%-25s %-29s %7s %-11s %-9s | ", c.paper.c_str(), c.scene.c_str(), faces.c_str(), c.resolution.c_str(),
                fps_range(c).c_str());
    const std::optional<BenchResult>& any = r.gpu ? r.gpu : r.ref;
    if (!any) {
      std::printf("%-28s   (%s)\n", r.ours.empty() ? "none" : r.ours.c_str(), r.note.c_str());
      continue;
    }
    std::string size = std::to_string(any->width) + "x" + std::to_string(any->height);
    auto fps = [](const std::optional<BenchResult>& b) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.1f", b ? 1000 / b->frame_ms : 0.0);
      return b ? std::string(buf) : std::string("-");
    };
    std::printf("%-28s %7d %7.0f %-9s %8s %8s", r.ours.c_str(), any->faces, any->strokes, size.c_str(),
                fps(r.gpu).c_str(), fps(r.ref).c_str());
    std::printf("%s\n", r.note.empty() ? "" : ("  (" + r.note + ")").c_str());
  }
  std::printf("\nTheir fps were measured on their hardware; ours on the machine and renderer above.\n");
}

// Output and comparison folders are checked before anything runs.
void check_folders(const BenchOptions& o, OutputFiles& out) {
  if (!o.against_dir.empty() && !fs::is_directory(o.against_dir))
    throw std::invalid_argument("--against: folder '" + o.against_dir + "' does not exist");
  if (!o.save_dir.empty()) out.folder(o.save_dir);
}

void run(const BenchOptions& o) {
  OutputFiles out;
  check_folders(o, out);
  if (o.paper) {
    if (!o.scenes.empty())
      throw std::invalid_argument("--paper runs the scenes bench/paper_claims.hpp names; give no SCENE");
    auto runs = run_paper(o, out);
    out.commit();
    print_paper(o, runs);
    return;
  }
  std::vector<BenchResult> results;
  std::vector<std::string> scenes = o.scenes.empty() ? std::vector<std::string>{""} : o.scenes;
  for (const auto& name : scenes) {
    SceneOptions so{name, o.size, o.assignments};
    Scene scene = so.load();
    for (const char* backend : {"gpu", "reference"}) {
      if (o.backend != "both" && o.backend != backend) continue;
      int frames = backend == std::string("gpu") ? o.frames : reference_frames(o);
      results.push_back(with_limits(o, scene, bench_scene(scene, backend, frames, kept(o, out))));
    }
  }
  out.commit();
  o.json ? print_json(o, results) : print_text(results);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("bench", "Frame rate and per-pass times on both backends, next to the papers' claims");
  cmd->add_option("scenes", o->scenes,
                  "Scene files or builtin:NAME (default: builtin:pencil, the CAD part with every pencil effect)");
  cmd->add_option("--frames", o->frames,
                  "Frames to time on the GPU (the reference times a tenth); of a scene's camera path, at most "
                  "that many of its frames, spread from the first to the last")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--reference-frames", o->reference_frames,
                  "Frames to time on the reference (default: a tenth of --frames)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--backend", o->backend, "gpu, reference or both")
      ->check(CLI::IsMember({"gpu", "reference", "both"}))
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WxH");
  cmd->add_option("--set", o->assignments, "Override a parameter: stage.name=value");
  cmd->add_flag("--json", o->json,
                "One JSON object {machine, renderer, results: [{scene, backend, fps, stages, errors}]}");
  cmd->add_flag("--paper", o->paper,
                "The papers' claimed fps next to ours for the closest scenes (bench/paper_claims.hpp)");
  cmd->add_flag("--limits", o->limits,
                "Also time the machine's limits at each scene's size (gpu/core/limits.hpp) and print every GPU "
                "pass as a multiple of its probe");
  cmd->add_option("--save", o->save_dir, "After timing, write one frame's buffers as DIR/<backend>/<buffer>.exr");
  cmd->add_option("--against", o->against_dir, "After timing, compare one frame's buffers with DIR/<buffer>.exr");
  cmd->add_option("--buffers", o->buffers, "Only these buffers for --save/--against (e.g. compose.color)")
      ->delimiter(',');
  cmd->add_option("--tolerance", o->tolerance, "--against: a pixel differs where any channel differs by more")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago

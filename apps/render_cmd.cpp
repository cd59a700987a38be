// plumbago render [SCENE] [-o out.png | -o DIR] [--frame I] [--backend gpu|reference]
//                 [--size WxH] [--set k=v ...] [--stats] [--json] [--dump-stages DIR]
// --stats: the renderer, every pass with its time, the frame's counts and each object's
// mesh as loaded (vertices, triangles, and the duplicate and degenerate faces dropped).
#include <cstdio>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "apps/command.hpp"
#include "apps/scene_options.hpp"
#include "common/util/progress.hpp"
#include "common/util/visualize.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/gl/context.hpp"
#include "parity/path_frames.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago {
namespace {

struct RenderOptions {
  SceneOptions scene;
  std::string output = "plumbago.png";
  std::string backend = "gpu";
  std::string dump_dir;
  int frame = 0;  // of the scene's camera path
  bool stats = false, json = false;
};

void print_stats(const RenderOptions& o, const Scene& scene, const Frame& frame) {
  std::string renderer = o.backend == "gpu" ? gpu::Context::get().renderer() : "CPU reference (Embree)";
  std::vector<std::string> gl_messages;  // KHR_debug messages other than errors (those fail the run)
  if (o.backend == "gpu") gl_messages = gpu::Context::get().take_messages();
  if (o.json) {
    nlohmann::json j;
    j["scene"] = scene.source;
    j["backend"] = o.backend;
    j["renderer"] = renderer;
    j["size"] = {scene.width, scene.height};
    j["gl_messages"] = gl_messages;
    j["ran"] = nlohmann::json::array();
    for (const auto& p : frame.ran) {
      // A fused GPU pass "a+b" ran both stages in one shader: each is listed, the time
      // is the pass's, given once (on the first), and "gpu_pass" names the pass.
      size_t plus = p.name.find('+');
      if (plus == std::string::npos) {
        j["ran"].push_back({{"name", p.name}, {"ms", p.ms}});
        continue;
      }
      j["ran"].push_back({{"name", p.name.substr(0, plus)}, {"ms", p.ms}, {"gpu_pass", p.name}});
      j["ran"].push_back({{"name", p.name.substr(plus + 1)}, {"ms", 0.0}, {"gpu_pass", p.name}});
    }
    j["counts"] = frame.counts;
    j["objects"] = nlohmann::json::array();
    for (const SceneObject& object : scene.objects) {
      const Mesh& m = *object.mesh;
      j["objects"].push_back({{"mesh", m.name},
                              {"style", style_names()[size_t(object.style)]},
                              {"vertices", m.positions.size()},
                              {"triangles", m.triangles.size()},
                              {"welded_vertices", m.cleanup.merged_vertices},
                              {"degenerate_faces", m.cleanup.degenerate_faces},
                              {"duplicate_faces", m.cleanup.duplicate_faces}});
    }
    std::printf("%s\n", j.dump(2).c_str());
    return;
  }
  std::printf("scene     %s (%dx%d)\nbackend   %s\nrenderer  %s\n", scene.source.c_str(), scene.width, scene.height,
              o.backend.c_str(), renderer.c_str());
  for (const auto& p : frame.ran) std::printf("  %-24s %10.3f ms\n", p.name.c_str(), p.ms);
  for (const auto& [name, n] : frame.counts) std::printf("  %-24s %10.0f\n", name.c_str(), n);
  // Each object's mesh as loaded: what welding dropped (common/mesh/mesh.hpp, MeshCleanup).
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const Mesh& m = *scene.objects[i].mesh;
    std::printf(
        "object %zu  %s (%s): %zu vertices, %zu triangles; dropped %zu duplicate and %zu degenerate faces, "
        "welded %zu vertices\n",
        i, m.name.c_str(), style_names()[size_t(scene.objects[i].style)].c_str(), m.positions.size(),
        m.triangles.size(), m.cleanup.duplicate_faces, m.cleanup.degenerate_faces, m.cleanup.merged_vertices);
  }
  for (const auto& m : gl_messages) std::printf("GL: %s\n", m.c_str());
}

// `-o DIR` for a scene with a camera path: every frame as DIR/frame_0000.png, ...
void write_path(const RenderOptions& o, const Scene& scene) {
  if (o.frame != 0 || !o.dump_dir.empty())
    throw std::invalid_argument("-o " + o.output +
                                ": a folder takes every frame; --frame and --dump-stages take an image file");
  OutputFiles out;
  out.folder(o.output);
  PathFrames path(scene, o.backend);
  Progress progress(o.output + ": frames", size_t(path.count()), true);
  char name[32];
  for (int i = 0; i < path.count(); ++i, progress.advance(1)) {
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    write_image(path.render(i).color, out.add((std::filesystem::path(o.output) / name).string()));
  }
  out.commit();
}

// Every output location is checked before rendering; the image and the dumps are
// written under temporary names and put in place together, or not at all.
void run(const RenderOptions& o) {
  Scene scene = o.scene.load();
  int frames = scene.animation ? scene.animation->frames : 1;
  if (o.frame < 0 || o.frame >= frames)
    throw std::invalid_argument("--frame " + std::to_string(o.frame) + ": the scene has " + std::to_string(frames) +
                                " frame" + (frames > 1 ? "s (0.." + std::to_string(frames - 1) + ")" : " (0)"));
  if (scene.animation && std::filesystem::path(o.output).extension().empty()) return write_path(o, scene);
  check_image_extension(o.output);
  OutputFiles out;
  OutputFile& image = out.add(o.output);
  FrameOptions fo;
  fo.keep_buffers = !o.dump_dir.empty();
  if (fo.keep_buffers) out.folder(o.dump_dir);
  Frame frame = PathFrames(scene, o.backend).render(o.frame, fo);
  if (fo.keep_buffers) dump_buffers(frame.buffers, o.dump_dir, o.backend + ".", out);
  write_image(frame.color, image);
  out.commit();
  if (o.stats) print_stats(o, scene, frame);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand(
      "render", "Render a scene (default: builtin:pencil, the CAD part with every pencil effect) to an image");
  o->scene.add_to(cmd, false);
  cmd->add_option("-o,--output", o->output,
                  "Output image (.png or .exr), or a folder for every frame of the scene's animation")
      ->capture_default_str();
  cmd->add_option("--frame", o->frame, "The frame of the scene's animation to render into the image (0: its camera)");
  cmd->add_option("--backend", o->backend, "gpu (GLSL) or reference (CPU)")
      ->check(CLI::IsMember({"gpu", "reference"}))
      ->capture_default_str();
  cmd->add_flag("--stats", o->stats,
                "Print the renderer, every pass that ran with its time, and each object's mesh counts (duplicate and "
                "degenerate faces dropped)");
  cmd->add_flag("--json", o->json, "With --stats: one JSON object");
  cmd->add_option("--dump-stages", o->dump_dir, "Write every intermediate buffer (PNG + EXR) into DIR");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago

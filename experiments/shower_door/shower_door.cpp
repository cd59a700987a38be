// plumbago_shower_door: the shower-door effect of sketchy drawing, measured (issue 5;
// Nienhaus & Döllner 2004 §4, §4.3 claim the `object` style "significantly reduces" it).
// Renders a camera orbit and scores, per mode and per pair of consecutive frames, how
// much of the sketch's perturbation moves with the surface (experiments/shower_door/README.md).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "common/util/image.hpp"
#include "experiments/shower_door/coherence.hpp"
#include "experiments/shower_door/sketch_frames.hpp"
#include "experiments/shower_door/surface_motion.hpp"

using namespace plumbago;
using namespace plumbago::shower_door;

namespace {

struct Options {
  std::string scene_path, out = "shower_door.csv";
  std::string maps;  // folder for the per-pixel residuals of the first frame pair; empty = none
  int frames = 36, size = 400;
  float step_deg = 2.0f;
  std::vector<std::string> modes = all_mode_names();
  MotionParams motion;
};

// "0.123" or "" for NaN (a mode without that measure).
std::string number(double v) {
  if (std::isnan(v)) return "";
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

// Per-pixel residuals of the first frame pair as grayscale PNGs, 1 (white) = `full`:
// <mode>_A.png (attached), <mode>_B.png (screen-fixed), and the two sketches.
void write_maps(const std::string& dir, const std::string& mode, const Image& map, float full, const Image& sketch_prev,
                const Image& sketch_next) {
  for (int c = 0; c < 2; ++c) {
    Image gray(map.width, map.height, 1);
    for (size_t i = 0; i < gray.pixels(); ++i) gray.data[i] = std::min(1.0f, map.data[2 * i + c] / full);
    write_image(gray, dir + "/" + mode + (c == 0 ? "_A.png" : "_B.png"));
  }
  write_image(sketch_prev, dir + "/" + mode + "_sketch0.png");
  write_image(sketch_next, dir + "/" + mode + "_sketch1.png");
}

// Object styles: the field's residuals apart over the pixels whose enlarged surface is
// their own (own_shell) and the others, and the share of the first among the moving pixels.
struct ShellSplit {
  Residuals own, other;
  double own_share = 0;
};
ShellSplit split_by_shell(const Mode& m, const View& view, const Image& points, const Image& coordinates,
                          const Image& prev_field, const Image& field, const Image& motion) {
  Image own = own_shell(m, view, points, coordinates);
  Image own_motion = motion, other_motion = motion;
  for (size_t i = 0; i < own.pixels(); ++i) (own.data[i] != 0.0f ? other_motion : own_motion).data[3 * i + 2] = 0.0f;
  ShellSplit s{residuals(prev_field, field, own_motion, Sampling::Bilinear),
               residuals(prev_field, field, other_motion, Sampling::Bilinear), 0};
  s.own_share = double(s.own.pixels) / double(std::max<size_t>(1, s.own.pixels + s.other.pixels));
  return s;
}

struct Previous {
  Camera camera;
  Image points;
  std::map<std::string, ModeFrame> frames;
};

void run(const Options& o) {
  Scene scene = sketchy_objects(load_scene(o.scene_path));
  if (scene.objects.empty()) throw std::runtime_error(o.scene_path + ": no object has style sketchy");
  scene.width = scene.height = o.size;
  std::string meshes;
  for (const SceneObject& obj : scene.objects)
    meshes += (meshes.empty() ? "" : " ") + std::filesystem::path(obj.mesh->name).filename().string();
  std::printf("scene %s, meshes: %s\n%d frames, %g deg apart, %dx%d\n", o.scene_path.c_str(), meshes.c_str(), o.frames,
              o.step_deg, o.size, o.size);

  std::vector<Mode> modes;
  for (const std::string& name : o.modes) modes.push_back(make_mode(scene, name));
  std::vector<WorldObject> world = world_geometry(scene);  // fixed: only the camera moves

  std::ofstream csv(o.out);
  if (!csv) throw std::runtime_error("cannot write " + o.out);
  csv << "mesh,size,step_deg,min_motion_px,mode,pair,covered,pixels,field_A,field_B,field_coherence,field_A_nearest,"
         "field_coherence_nearest,image_A,image_B,image_coherence,own_shell_share,field_A_own_shell,field_A_other_"
         "shell\n";
  std::map<std::string, std::vector<double>> field_scores, image_scores;
  Previous prev;
  for (int t = 0; t < o.frames; ++t) {
    auto start = std::chrono::steady_clock::now();
    Camera camera = orbit(scene.camera, float(t) * o.step_deg);
    View view = trace_view(scene, camera);
    Image points = surface_points(world, view.gbuffer);
    Image motion = t > 0 ? surface_motion(prev.camera, prev.points, points, o.motion) : Image();
    size_t covered = 0;
    for (size_t i = 0; i < points.pixels(); ++i) covered += points.data[4 * i + 3] != 0.0f;
    std::map<std::string, ModeFrame> frames;
    for (const Mode& m : modes) {
      ModeFrame f = render_mode(m, view);
      if (t > 0) {
        const ModeFrame& before = prev.frames.at(m.name);
        Residuals field, nearest;
        if (m.perturbed) {
          field = residuals(before.field, f.field, motion, Sampling::Bilinear);
          nearest = residuals(before.field, f.field, motion, Sampling::Nearest);
          field_scores[m.name].push_back(field.coherence());
        }
        if (t == 1 && !o.maps.empty() && m.perturbed)
          write_maps(o.maps, m.name, residual_map(before.field, f.field, motion, Sampling::Bilinear), 0.1f,
                     before.sketch, f.sketch);
        Residuals image = residuals(before.sketch, f.sketch, motion, Sampling::Bilinear);
        image_scores[m.name].push_back(image.coherence());
        double none = std::nan("");
        csv << meshes << ',' << o.size << ',' << o.step_deg << ',' << o.motion.min_motion_px << ',' << m.name << ','
            << t - 1 << ',' << covered << ',' << image.pixels << ',' << number(m.perturbed ? field.attached : none)
            << ',' << number(m.perturbed ? field.fixed : none) << ',' << number(m.perturbed ? field.coherence() : none)
            << ',' << number(m.perturbed ? nearest.attached : none) << ','
            << number(m.perturbed ? nearest.coherence() : none) << ',' << number(image.attached) << ','
            << number(image.fixed) << ',' << number(image.coherence());
        if (!f.coordinates.empty()) {
          ShellSplit split = split_by_shell(m, view, points, f.coordinates, before.field, f.field, motion);
          csv << ',' << number(split.own_share) << ',' << number(split.own.attached) << ','
              << number(split.other.attached);
        } else {
          csv << ",,,";
        }
        csv << '\n';
      }
      frames[m.name] = std::move(f);
    }
    prev = {camera, std::move(points), std::move(frames)};
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "frame %d/%d: %.2f s\n", t + 1, o.frames, s);
  }

  auto mean = [](const std::vector<double>& v) {
    double sum = 0;
    for (double x : v) sum += x;
    return v.empty() ? std::nan("") : sum / double(v.size());
  };
  auto range = [](const std::vector<double>& v, bool lowest) {
    if (v.empty()) return std::nan("");
    return lowest ? *std::min_element(v.begin(), v.end()) : *std::max_element(v.begin(), v.end());
  };
  std::printf("\n%-16s %12s %8s %8s %12s\n", "mode", "field coh.", "min", "max", "image coh.");
  for (const Mode& m : modes) {
    const auto& f = field_scores[m.name];
    std::printf("%-16s %12s %8s %8s %12s\n", m.name.c_str(), number(mean(f)).c_str(), number(range(f, true)).c_str(),
                number(range(f, false)).c_str(), number(mean(image_scores[m.name])).c_str());
  }
  std::printf("(means over %d frame pairs; wrote %s)\n", o.frames - 1, o.out.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Shower-door effect of sketchy drawing, measured over a camera orbit"};
  app.add_option("scene", o.scene_path, "scene file; its sketchy objects are drawn")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--frames", o.frames, "frames of the orbit")->check(CLI::Range(2, 3600));
  app.add_option("--step-deg", o.step_deg, "orbit step between frames, degrees about the camera's up axis");
  app.add_option("--size", o.size, "image width and height, pixels")->check(CLI::Range(16, 8192));
  app.add_option("--out", o.out, "CSV, one row per mode and frame pair");
  app.add_option("--modes", o.modes, "modes to compare: default repeat rough object object_enlarge<E> unperturbed");
  app.add_option("--maps", o.maps, "folder for PNGs of the first pair's per-pixel field residuals (1 = 0.1)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--footprints", o.motion.footprints, "visibility tolerance, pixel sizes at the point's depth");
  app.add_option("--min-motion", o.motion.min_motion_px, "pixels whose surface moved less are left out");
  CLI11_PARSE(app, argc, argv);
  try {
    run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plumbago_shower_door: %s\n", e.what());
    return 1;
  }
  return 0;
}

// plumbago_temporal_coherence: the temporal coherence of stroke-based rendering over a
// camera path (issue 17; docs/conventions.md, "Temporal coherence"; Kalnins et al. 2002). Renders the
// path's frames on the CPU reference and writes, per pair of consecutive frames and per
// line kind, texture sliding along the strokes, strokes born and dying, the largest change
// of alpha and width, and the shower-door coherence of the stroke layer; and the same
// pooled over the pairs (experiments/temporal_coherence/README.md).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "common/util/image.hpp"
#include "experiments/shower_door/coherence.hpp"
#include "experiments/shower_door/surface_motion.hpp"
#include "experiments/temporal_coherence/measures.hpp"
#include "experiments/temporal_coherence/stroke_frames.hpp"

using namespace plumbago;
using namespace plumbago::temporal_coherence;

namespace {

struct Options {
  std::string scene_path, out = "temporal_coherence.csv", summary, layers;
  std::vector<std::string> sets;
  std::optional<double> orbit_step_deg;
  int frames = 0;
  MatchParams match;
  shower_door::MotionParams motion;
};

// The columns every row starts with, and the measures' columns (stat_cells).
const char* kScene = "scene,width,height,path,step";
const char* kStats =
    "slide_mean_px,slide_median_px,slide_p95_px,slide_max_px,alpha_change_p95,alpha_change_max,"
    "width_change_p95_px,width_change_max_px,offset_change_mean_px,offset_change_p95_px,stretch_median,stretch_p95";
const char* kPairColumns =
    "pair,kind,runs_prev,runs_next,length_prev_px,length_next_px,born,died,born_px,died_px,"
    "samples,matched";
const char* kLayerColumns = "image_pixels,image_A,image_B,image_coherence";
const char* kSummaryColumns =
    "pairs,kind,strokes_per_frame,length_per_frame_px,born_per_pair,died_per_pair,"
    "born_px_per_pair,died_px_per_pair,samples,matched";
const char* kSummaryLayer = "image_coherence_mean,image_coherence_min,image_coherence_max,coherence_ms";

// ",v" with 6 significant digits, or "," for NaN (nothing measured).
std::string cell(double v) {
  std::ostringstream s;
  s << ',';
  if (!std::isnan(v)) s << std::setprecision(6) << v;
  return s.str();
}

std::string scene_cells(const Scene& scene, const std::string& name) {
  const Animation& a = *scene.animation;
  const char* path = a.kind == Animation::Kind::Orbit ? "orbit" : "dolly";
  std::ostringstream s;
  s << name << ',' << scene.width << ',' << scene.height << ',' << path << cell(a.amount / std::max(1, a.frames - 1));
  return s.str();
}

std::string stat_cells(const PairMeasures& m) {
  Stats slide = stats(m.slide_px), alpha = stats(m.alpha_change), width = stats(m.width_change_px),
        offset = stats(m.offset_change_px), stretch = stats(m.stretch);
  return cell(slide.mean) + cell(slide.median) + cell(slide.p95) + cell(slide.max) + cell(alpha.p95) + cell(alpha.max) +
         cell(width.p95) + cell(width.max) + cell(offset.mean) + cell(offset.p95) + cell(stretch.median) +
         cell(stretch.p95);
}

// The measures of one kind in one pair; the stroke layer's residuals on the "all" row only.
std::string pair_row(const std::string& kind, const PairMeasures& m, const shower_door::Residuals* layer) {
  std::ostringstream s;
  s << ',' << kind << ',' << m.runs_prev << ',' << m.runs_next << cell(m.length_prev_px) << cell(m.length_next_px)
    << ',' << m.born << ',' << m.died << cell(m.born_px) << cell(m.died_px) << ',' << m.samples << ',' << m.matched
    << stat_cells(m);
  if (layer)
    s << ',' << layer->pixels << cell(layer->attached) << cell(layer->fixed) << cell(layer->coherence());
  else
    s << ",,,,";
  return s.str();
}

// The measures of one kind pooled over `pairs` pairs; the layer's scores and the coherent
// silhouettes' time a frame (median ms, NaN: not coherent) on "all" only.
std::string summary_row(const std::string& kind, const PairMeasures& m, int pairs, const std::vector<double>& layer,
                        double coherence_ms) {
  std::ostringstream s;
  double n = pairs;
  s << ',' << pairs << ',' << kind << cell(double(m.runs_next) / n) << cell(m.length_next_px / n)
    << cell(double(m.born) / n) << cell(double(m.died) / n) << cell(m.born_px / n) << cell(m.died_px / n) << ','
    << m.samples << ',' << m.matched << stat_cells(m);
  if (kind != "all") return s.str() + ",,,,";
  double least = layer.empty() ? NAN : *std::min_element(layer.begin(), layer.end());
  s << cell(stats(layer).mean) << cell(least) << cell(stats(layer).max) << cell(coherence_ms);
  return s.str();
}

// The measures pooled over the pairs: per kind (by name), and all kinds.
struct Pooled {
  std::map<std::string, PairMeasures> kinds;
  PairMeasures all;
  std::vector<double> layer;  // the stroke layer's coherence per pair, where defined

  void add(const std::string& kind, const PairMeasures& m) { accumulate(kind == "all" ? all : kinds[kind], m); }
};

void write_summary(const Options& o, const std::string& scene, const Pooled& pooled, int pairs, double coherence_ms) {
  std::ofstream csv(o.summary);
  if (!csv) throw std::runtime_error("cannot write " + o.summary);
  csv << kScene << ',' << kSummaryColumns << ',' << kStats << ',' << kSummaryLayer << '\n';
  for (const auto& [kind, m] : pooled.kinds)
    csv << scene << summary_row(kind, m, pairs, pooled.layer, coherence_ms) << '\n';
  csv << scene << summary_row("all", pooled.all, pairs, pooled.layer, coherence_ms) << '\n';
}

// A frame's stroke layer's file name: frame_007.png.
std::string frame_name(int t) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%03d.png", t);
  return name;
}

void run(const Options& o) {
  Scene scene = study_scene(o.scene_path, o.sets, o.orbit_step_deg, o.frames);
  std::string scene_columns = scene_cells(scene, std::filesystem::path(o.scene_path).stem().string());
  int frames = scene.animation->frames;
  std::printf("scene %s, %dx%d, %d frames\n", o.scene_path.c_str(), scene.width, scene.height, frames);
  std::ofstream csv(o.out);
  if (!csv) throw std::runtime_error("cannot write " + o.out);
  if (!o.layers.empty()) std::filesystem::create_directories(o.layers);
  csv << kScene << ',' << kPairColumns << ',' << kStats << ',' << kLayerColumns << '\n';
  Pooled pooled;
  StrokeFrame prev;
  Carry carry;
  std::vector<double> coherence_ms;  // per frame, where the brush_parameters stage ran
  for (int t = 0; t < frames; ++t) {
    auto start = std::chrono::steady_clock::now();
    StrokeFrame next = render_stroke_frame(scene, t, &carry);
    if (!std::isnan(next.coherence_ms)) coherence_ms.push_back(next.coherence_ms);
    if (t > 0) {
      Image motion = shower_door::surface_motion(prev.strokes.camera, prev.points, next.points, o.motion);
      shower_door::Residuals layer =
          shower_door::residuals(prev.layer, next.layer, motion, shower_door::Sampling::Bilinear);
      if (!std::isnan(layer.coherence())) pooled.layer.push_back(layer.coherence());
      for (const auto& [kind, m] : pair_measures(prev.strokes, next.strokes, o.match)) {
        csv << scene_columns << ',' << t - 1 << pair_row(kind, m, kind == "all" ? &layer : nullptr) << '\n';
        pooled.add(kind, m);
      }
    }
    if (!o.layers.empty()) write_image(next.layer, (std::filesystem::path(o.layers) / frame_name(t)).string());
    prev = std::move(next);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "frame %d/%d: %zu strokes, %.2f s\n", t + 1, frames, prev.strokes.runs.size(), s);
  }
  double coherent_ms = coherence_ms.empty() ? NAN : stats(coherence_ms).median;
  if (!coherence_ms.empty())
    std::printf(
        "coherent silhouettes (brush_parameters: votes, fits, brush samples): %.2f ms a frame (median; "
        "reference, wall)\n",
        coherent_ms);
  if (!o.summary.empty()) write_summary(o, scene_columns, pooled, frames - 1, coherent_ms);
  std::printf("wrote %s%s (%d frame pairs)\n", o.out.c_str(), o.summary.empty() ? "" : (" and " + o.summary).c_str(),
              frames - 1);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Temporal coherence of stroke-based rendering over a camera path (docs/conventions.md)"};
  app.add_option("scene", o.scene_path, "scene file with stroke objects")->required()->check(CLI::ExistingFile);
  app.add_option("--out", o.out, "CSV, one row per frame pair and line kind, and one for all kinds");
  app.add_option("--summary", o.summary, "CSV, one row per line kind and one for all: the pairs pooled");
  app.add_option("--orbit-step-deg", o.orbit_step_deg, "replace the scene's camera path by an orbit of this step");
  app.add_option("--frames", o.frames, "frames of that orbit (default: the scene's, else 36)")
      ->check(CLI::Range(2, 3600));
  app.add_option("--set", o.sets,
                 "stage.param=value, as for plumbago render (strokes.coherent=true: coherent silhouettes, Kalnins et "
                 "al. 2003, with their coherence.* parameters)");
  app.add_option("--layers", o.layers, "folder for each frame's stroke layer, frame_000.png on");
  app.add_option("--match-px", o.match.radius_px, "a reprojected sample lands on a stroke at most this far (px)");
  app.add_option("--depth-tolerance", o.match.depth_tolerance, "and at a depth within this share of its own");
  app.add_option("--min-motion", o.motion.min_motion_px, "stroke layer: pixels whose surface moved less are left out");
  CLI11_PARSE(app, argc, argv);
  try {
    run(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plumbago_temporal_coherence: %s\n", e.what());
    return 1;
  }
  return 0;
}

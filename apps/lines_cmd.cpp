// plumbago lines SCENE -o lines.json|lines.svg [--backend gpu|reference]: the feature
// lines of every object but the sketchy ones (Kalnins et al. 2002, §4.5) and the decals of the scene's
// stroke files (Kalnins et al. 2002, §3, §4.5, projected by the chosen backend), for the scene's camera, with
// their visibility from the chosen backend's ID image (Kalnins et al. 2002, §4.6); the silhouettes are
// that backend's own (the GPU's chained by the GPU, parity/lines.hpp). It prints how many
// paths there are, how many show (a visible run or more), and the visible runs drawn.
//   .json: every path, {"paths": [{"kind", "object", "closed", "points" (world),
//          "screen" (pixels, origin bottom-left), "visible" (per point); a hatch's also
//          "group", "hatching", its group's kind: "structured" or "free", and "mobile":
//          whether it moves on the surface (Kalnins et al. 2002, §6.3)}]};
//          With --truth also, per path, its window arc length at each point ("arc_px"),
//          the visible runs the strokes would draw ("runs": [[s0, s1], ...], arc px), and
//          what rays say ("truth": an Embree ray to the path every 0.5 px of arc,
//          reference/strokes/ray_visibility.hpp; a silhouette's passes over hits within two of
//          its face's longest edges, its own facets; a crease's, border's, decal's or hatch's
//          over the triangles the point lies on), and the frame's passes with their times
//          ("ran"): the accuracy study of experiments/stroke_visibility compares them;
//   .svg:  the visible runs as the strokes draw them: one <path> per run, the outline of
//          its variable-width ribbon (Kalnins et al. 2002, §4.1), filled with its style's color and alpha.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "apps/command.hpp"
#include "apps/scene_options.hpp"
#include "common/strokes/base_stroke.hpp"
#include "common/strokes/stroke.hpp"
#include "common/util/output_file.hpp"
#include "parity/lines.hpp"
#include "reference/strokes/ray_visibility.hpp"

namespace plumbago {
namespace {

struct LinesOptions {
  SceneOptions scene;
  std::string output = "lines.json";
  std::string backend = "gpu";
  bool truth = false;
};

constexpr double kTruthStepPx = 0.5;

// `origin`: the scene's (p.world is relative to it); the file has world space.
nlohmann::json path_json(const SceneLines& found, const WindowPath& p, glm::dvec3 origin) {
  const WindowLines& lines = found.lines;
  nlohmann::json points = nlohmann::json::array(), screen = nlohmann::json::array();
  for (size_t k = 0; k < p.window.size(); ++k) {
    glm::dvec3 world = glm::dvec3(p.world[k]) + origin;
    points.push_back({world.x, world.y, world.z});
    screen.push_back({p.window[k].x, p.window[k].y});
  }
  nlohmann::json j{{"kind", line_kind_name(p.kind)},     {"object", p.object}, {"closed", p.closed},
                   {"front_facing", p.front_facing},     {"points", points},   {"screen", screen},
                   {"visible", points_visible(p, found)}};
  if (p.kind == LineKind::Hatching) {  // its group (common/strokes/hatching.hpp) and the group's kind
    const HatchGroupState& g = lines.hatching.at(size_t(p.hatch_group));
    j["group"] = g.number, j["hatching"] = g.free ? "free" : "structured", j["mobile"] = g.mobile;
  }
  return j;
}

// The outline of each strip of a ribbon (its triangles in GL strip order, R0 L0 R1 L1 ...):
// the left side forwards, the right side back; a strip starts where a triangle shares no
// vertex with the one before.
std::string outline(const Ribbon& r, int height) {
  std::string d;
  std::vector<glm::vec2> left, right;
  auto flush = [&] {
    char xy[64];
    for (size_t k = 0; k < left.size() + right.size(); ++k) {
      glm::vec2 p = k < left.size() ? left[k] : right[right.size() - 1 - (k - left.size())];
      std::snprintf(xy, sizeof xy, "%c%.2f %.2f ", k == 0 ? 'M' : 'L', p.x, float(height) - p.y);
      d += xy;
    }
    if (!left.empty()) d += "Z ";
    left.clear(), right.clear();
  };
  auto add = [&](const RibbonVertex& v) {
    std::vector<glm::vec2>& side = v.uv.y > 0.5f ? left : right;
    if (side.empty() || side.back() != v.position) side.push_back(v.position);
  };
  for (size_t t = 0; t + 2 < r.triangles.size(); t += 3) {
    const RibbonVertex* v = &r.triangles[t];
    bool joined =
        t > 0 && (v[0].position == r.triangles[t - 1].position || v[1].position == r.triangles[t - 1].position);
    if (t > 0 && !joined) flush();
    for (int k = 0; k < 3; ++k) add(v[k]);
  }
  flush();
  return d;
}

std::string svg(const Scene& scene, const WindowLines& lines, const Visibility& v) {
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(scene.width) +
                    "\" height=\"" + std::to_string(scene.height) + "\" viewBox=\"0 0 " + std::to_string(scene.width) +
                    " " + std::to_string(scene.height) + "\">\n";
  // As the stroke stage draws a view alone: coherent silhouettes start new brush paths.
  std::vector<RunBrush> brushes;
  if (strokes_coherent(scene.params)) brushes.resize(v.runs.size());
  std::vector<StyledRun> runs = styled_runs(lines, v, scene.strokes, scene.seed, brushes);
  for (size_t i = 0; i < runs.size(); ++i) {
    const WindowPath& p = lines.paths[v.runs[i].path];
    const StrokeStyle& style = runs[i].style;
    std::string d = outline(base_stroke(runs[i].run, style), scene.height);
    if (d.empty()) continue;
    char fill[160];
    std::snprintf(fill, sizeof fill, "fill=\"rgb(%d,%d,%d)\" fill-opacity=\"%.3f\"", int(style.color_r * 255 + 0.5f),
                  int(style.color_g * 255 + 0.5f), int(style.color_b * 255 + 0.5f), style.alpha);
    out += "  <path class=\"" + std::string(line_kind_name(p.kind)) + "\" data-object=\"" + std::to_string(p.object) +
           "\" " + fill + " d=\"" + d + "\"/>\n";
  }
  return out + "</svg>\n";
}

// The longest edge of face f of an object, in world space.
double longest_edge(const SceneObject& o, uint32_t f) {
  glm::dvec3 p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = glm::dvec3(o.transform * glm::vec4(o.mesh->positions[o.mesh->triangles[f][k]], 1.0f));
  return std::max({glm::distance(p[0], p[1]), glm::distance(p[1], p[2]), glm::distance(p[2], p[0])});
}

// Where the rays aim along a path, every kTruthStepPx of arc, and how each tells its own
// surface from an occluder (reference/strokes/ray_visibility.hpp): a silhouette passes over hits
// within two of its face's longest edges, a line on the mesh over the triangles it lies on.
void add_targets(const Scene& scene, const WindowPath& p, std::vector<reference::RayTarget>& targets) {
  for (double s = 0; s <= p.length_px; s += kTruthStepPx) {
    double own = 0;
    if (p.kind == LineKind::Silhouette)
      own = 2 * longest_edge(scene.objects[p.object], p.surface[segment_at(p, s)].face);
    targets.push_back({world_at(p, s), own});
  }
}

// Adds "arc_px", "runs" and "truth" to each path's JSON.
void add_truth(const Scene& scene, const WindowLines& lines, const Visibility& v, nlohmann::json& paths) {
  std::vector<reference::RayTarget> targets;
  std::vector<size_t> first;
  for (const WindowPath& p : lines.paths) {
    first.push_back(targets.size());
    add_targets(scene, p, targets);
  }
  first.push_back(targets.size());
  std::vector<uint8_t> seen = reference::visible_by_rays(scene, targets);
  for (size_t i = 0; i < lines.paths.size(); ++i) {
    paths[i]["arc_px"] = lines.paths[i].arc_px;
    paths[i]["runs"] = nlohmann::json::array();
    paths[i]["truth"] = {
        {"step_px", kTruthStepPx},
        {"visible", std::vector<bool>(seen.begin() + long(first[i]), seen.begin() + long(first[i + 1]))}};
  }
  for (const VisibleRun& run : v.runs) paths[run.path]["runs"].push_back({run.s0, run.s1});
}

void run(const LinesOptions& o) {
  bool as_svg = o.output.ends_with(".svg");
  if (!as_svg && !o.output.ends_with(".json"))
    throw std::invalid_argument("lines: -o must end in .json or .svg, not '" + o.output + "'");
  SceneLines found = scene_lines(o.scene.load(), o.backend);
  const Scene& scene = found.scene;
  const WindowLines& lines = found.lines;
  const Visibility& visibility = found.visibility;
  std::string text;
  if (as_svg) {
    text = svg(scene, lines, visibility);
  } else {
    nlohmann::json paths = nlohmann::json::array();
    for (const WindowPath& path : lines.paths) paths.push_back(path_json(found, path, scene.origin));
    nlohmann::json j{{"paths", paths}};
    if (o.truth) {
      add_truth(scene, lines, visibility, j["paths"]);
      for (const PassTime& t : found.frame.ran) j["ran"].push_back({{"name", t.name}, {"ms", t.ms}});
    }
    text = j.dump() + "\n";
  }
  OutputFile file(o.output);
  std::ofstream(file.temporary_path()) << text;
  file.commit();
  std::set<size_t> shown;
  for (const VisibleRun& run : visibility.runs) shown.insert(run.path);
  std::printf("%zu paths, %zu shown, %zu visible runs -> %s\n", lines.paths.size(), shown.size(),
              visibility.runs.size(), o.output.c_str());
}

void setup(CLI::App& app) {
  auto o = std::make_shared<LinesOptions>();
  auto* cmd = app.add_subcommand("lines", "Write the scene's feature lines (JSON) or its visible strokes (SVG)");
  o->scene.add_to(cmd, true);
  cmd->add_option("-o,--output", o->output, "lines.json (every path) or lines.svg (the visible strokes)")
      ->capture_default_str();
  cmd->add_option("--backend", o->backend, "whose silhouettes and ID image: gpu or reference")
      ->check(CLI::IsMember({"gpu", "reference"}))
      ->capture_default_str();
  cmd->add_flag("--truth", o->truth,
                "JSON: add the visible runs and what Embree rays say every 0.5 px (accuracy studies)");
  cmd->callback([o] { run(*o); });
}

PLUMBAGO_COMMAND(setup);

}  // namespace
}  // namespace plumbago

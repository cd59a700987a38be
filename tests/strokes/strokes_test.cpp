// Stroke-based rendering (Kalnins et al. 2002, §4.1, §4.6): the ID image, visibility and the stroke raster on
// both backends, fed the same inputs; visibility against what is analytically hidden.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "common/mesh/procedural.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/visibility.hpp"
#include "gpu/core/pipeline.hpp"
#include "parity/lines.hpp"
#include "parity/parity.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const std::vector<std::string> kStrokeStages = {"id_image", "visibility", "stroke"};

void expect_stroke_parity(const Scene& scene, const std::string& label) {
  auto results = run_parity(scene, kStrokeStages);
  ASSERT_EQ(testing::names_of(results), (std::vector<std::string>{kIds.name, kCreaseIds.name, kFlags.name,
                                                                  kRunPaths.name, kRunEnds.name, kStrokeColor.name}));
  for (const StageParity& r : results) {
    std::printf("[strokes %s] %s  [%s]\n", label.c_str(), format_diff(r.name, r.diff).c_str(), r.note.c_str());
    EXPECT_TRUE(r.pass) << label << " " << r.name << ": " << r.note;
  }
}

class StrokeParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

class StrokeParityNear : public testing::GlTest {};

// The ID image's ids are compared exactly: the GPU draws its lines from the frame's path table
// (gpu/strokes/id_lines.hpp, shaders/strokes/id_lines.geom), the reference its triangles
// (common/strokes/id_image.cpp id_line_triangles); a key off by one bit, or silhouette pieces
// 8 px long instead of 1, fail every builtin here.
TEST_P(StrokeParity, Builtins) {
  expect_stroke_parity(testing::drawn_with_strokes(testing::builtin_at(GetParam(), 320, 240)), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, StrokeParity, ::testing::Values("torus", "sphere", "cad"));

// The ID image's faces of a sketchy object are not in the G-buffer: the GPU pulls them from the
// meshes it keeps (gpu/scene/mesh_buffers.hpp) and clips them at the near plane itself
// (shaders/strokes/id_faces.vert), where the reference clips in world space. A sketchy torus
// seen from just outside its tube, nearer to it than the near plane, around a stroke
// sphere: the plane cuts a hole in the middle of the image through which the tube's inside
// shows.
TEST_F(StrokeParityNear, SketchyFacesCutByTheNearPlane) {
  Scene s = testing::one_stroke_object(make_procedural("torus"), glm::vec3(1.65f, 0.0f, 0.0f));
  s.camera.near = 0.3f;
  s.objects[0].style = Style::Sketchy;
  Mesh sphere = make_procedural("sphere");
  compute_normals(sphere);
  s.objects.push_back({std::make_shared<const Mesh>(std::move(sphere))});
  s.objects.back().style = Style::Strokes;
  s.objects.back().transform = glm::scale(glm::mat4(1.0f), glm::vec3(0.4f));
  s.effects.push_back("sketchy");
  const Mesh& torus = *s.objects[0].mesh;
  const glm::vec3 forward = glm::normalize(s.camera.target - s.camera.eye);
  size_t cut = 0;
  for (const auto& t : torus.triangles) {
    int nearer = 0;
    for (int k = 0; k < 3; ++k) nearer += glm::dot(torus.positions[t[k]] - s.camera.eye, forward) < s.camera.near;
    cut += nearer == 1 || nearer == 2;
  }
  std::printf("torus seen from 0.25 of its tube: %zu faces cut by the near plane\n", cut);
  ASSERT_GT(cut, 20u);
  expect_stroke_parity(s, "sketchy, near plane");
}

// Lines that run out of the window: the first round's edge samples where a path leaves and
// enters the 4 px margin, closed loops cut by it, and whole paths off it (one sample each).
TEST_F(StrokeParityNear, LinesLeavingTheWindow) {
  Scene s = testing::one_stroke_object(make_procedural("torus"), glm::vec3(0.3f, 0.9f, 1.0f));
  WindowLines lines = window_lines(s, s.params.get<StrokesParams>());
  auto outside = [&](glm::dvec2 w) { return w.x < -4 || w.y < -4 || w.x > s.width + 4 || w.y > s.height + 4; };
  size_t leaving = 0, off = 0;
  for (const WindowPath& p : lines.paths) {
    size_t out = size_t(std::count_if(p.window.begin(), p.window.end(), outside));
    leaving += out > 0 && out < p.window.size(), off += out == p.window.size();
  }
  std::printf("%zu paths, %zu leaving the window, %zu off it\n", lines.paths.size(), leaving, off);
  ASSERT_GE(leaving, 1u);
  ASSERT_GE(off, 1u);
  expect_stroke_parity(s, "leaving the window");
}

// strokes.keep_back_facing keeps the back-facing silhouettes as paths: both backends test
// their samples and draw their runs alike. (The ID image leaves them out, rule 3 of
// common/strokes/id_image.hpp; on a closed mesh the surface in front hides them anyway, so
// drawing them there changes no pixel of this view.)
TEST_F(StrokeParityNear, BackFacingSilhouettesKept) {
  Scene s = testing::one_stroke_object(make_procedural("torus", 3.0f), glm::vec3(0.3f, 2.5f, 1.2f));
  s.params.set("strokes.keep_back_facing", 1.0);
  size_t back = 0;
  for (const WindowPath& p : window_lines(s, s.params.get<StrokesParams>()).paths)
    back += p.kind == LineKind::Silhouette && !p.front_facing;
  std::printf("fine torus: %zu back-facing silhouette paths kept\n", back);
  ASSERT_GT(back, 0u);
  expect_stroke_parity(s, "back-facing kept");
}

// `plumbago lines --backend gpu` lists the runs the GPU frame found, on the paths it tested:
// the same runs as the reference's bisection in double finds on those paths from that
// frame's ID image, ends and polylines within double rounding (both locate each change in
// double from the same samples).
TEST_F(StrokeParityNear, GpuLinesAreTheRunsItsFrameListed) {
  for (const std::string name : {"torus", "cad"}) {
    SCOPED_TRACE(name);
    SceneLines gpu = scene_lines(testing::builtin_at(name, 320, 240), "gpu");
    auto test = [&](const std::vector<VisibilitySample>& batch) {
      std::vector<uint8_t> flags;
      for (const VisibilitySample& s : batch)
        flags.push_back(sample_visible(gpu.keys, gpu.crease_keys ? &*gpu.crease_keys : nullptr, s));
      return flags;
    };
    Visibility cpu = visible_runs(gpu.lines, gpu.scene.params.get<StrokesParams>(), test);
    ASSERT_EQ(gpu.visibility.runs.size(), cpu.runs.size());
    ASSERT_GT(cpu.runs.size(), 0u);
    double worst = 0;
    for (size_t k = 0; k < cpu.runs.size(); ++k) {
      const VisibleRun &g = gpu.visibility.runs[k], &c = cpu.runs[k];
      EXPECT_EQ(g.path, c.path) << k;
      worst = std::max({worst, std::abs(g.s0 - c.s0), std::abs(g.s1 - c.s1)});
      ASSERT_EQ(g.window.size(), c.window.size()) << k;
      for (size_t q = 0; q < c.window.size(); ++q) worst = std::max(worst, glm::distance(g.window[q], c.window[q]));
    }
    std::printf("[lines --backend gpu %s] %zu runs, ends and polylines within %.3g px of the reference's\n",
                name.c_str(), cpu.runs.size(), worst);
    EXPECT_LT(worst, 1e-6);
  }
}

// A view of the Ogre, one of 48 random ones, where a multiple of the visibility step fell
// between a.s + |ab| in float and the next point's arc length b.s: the GPU's first round gave
// that sample to neither segment, and every later flag moved by one (3.4% differed) while the
// runs agreed. Each segment that does not leave the window now ends at b.s.
TEST_F(StrokeParityNear, OgreViewWhereAStepFellBetweenTwoSegments) {
  PLUMBAGO_REQUIRE_MODEL("ogre.obj");
  Scene s = parse_scene(R"({"objects": [{"mesh": ")" + testing::model_path("ogre.obj") + R"(", "style": "strokes"}],
      "camera": {"view_direction": [-0.638547240152125, 0.1632003273249325, 0.2778269378523681],
                 "fov_deg": 31.17192628177194},
      "resolution": [400, 400], "effects": ["strokes"]})",
                        "ogre view", ".");
  expect_stroke_parity(s, "ogre view");
}

class StrokeModelParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(StrokeModelParity, SharedModels) {
  PLUMBAGO_REQUIRE_MODEL(GetParam());
  expect_stroke_parity(testing::drawn_with_strokes(testing::model_scene(GetParam(), 400, 400)), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Models, StrokeModelParity,
                         ::testing::Values("fandisk.obj", "ogre.obj", "stanford-bunny.obj", "teapot.obj", "spot.obj",
                                           "cow.obj", "rocker-arm.obj", "igea.ply"));

// The arc the visible runs of `lines` cover on paths of `kinds` (px).
double visible_px(const SceneLines& lines, std::initializer_list<LineKind> kinds) {
  double px = 0;
  for (const VisibleRun& r : lines.visibility.runs) {
    const WindowPath& p = lines.lines.paths.at(r.path);
    if (std::find(kinds.begin(), kinds.end(), p.kind) != kinds.end()) px += r.closed ? p.length_px : r.s1 - r.s0;
  }
  return px;
}
// The backends agree on `on` (a parameter set), and each shows more arc of `kinds` on it than
// on `off` (the same scene without it).
void expect_parity_and_more_arc(const Scene& on, const Scene& off, std::initializer_list<LineKind> kinds,
                                const std::string& label) {
  expect_stroke_parity(on, label);
  for (const std::string backend : {"reference", "gpu"}) {
    double with = visible_px(scene_lines(on, backend), kinds), without = visible_px(scene_lines(off, backend), kinds);
    std::printf("%s, %s: visible arc %.1f px, %.1f px without\n", label.c_str(), backend.c_str(), with, without);
    EXPECT_GT(with, without + 10) << backend;
  }
}

// strokes.crease_under_silhouettes on the cow (5.8K faces), whose creases run beside its
// silhouettes along the legs: the backends agree with it on, and each shows more crease arc
// with it than without (experiments/stroke_visibility measures it against rays).
TEST_F(StrokeParityNear, CreasesUnderSilhouettesOnTheCow) {
  PLUMBAGO_REQUIRE_MODEL("cow.obj");
  Scene on = testing::drawn_with_strokes(testing::model_scene("cow.obj", 400, 400)), off = on;
  on.params.set("strokes.crease_under_silhouettes", 1.0);
  expect_parity_and_more_arc(on, off, {LineKind::Crease, LineKind::Border}, "cow, creases under silhouettes");
}

// strokes.id_silhouette_lift on the bunny decimated to 2000 faces, whose smooth silhouettes lie
// about a face off the facets that graze them: the backends agree with it on (its quads placed
// in double from the same world lengths), and each shows more silhouette arc with it than
// without (experiments/stroke_visibility measures it against rays).
TEST_F(StrokeParityNear, LiftedSilhouettesOnADecimatedBunny) {
  PLUMBAGO_REQUIRE_MODEL("stanford-bunny.obj");
  Scene off = parse_scene(R"({"objects": [{"mesh": {"file": ")" + testing::model_path("stanford-bunny.obj") +
                              R"(", "decimate_to": 2000}, "style": "strokes"}],
      "resolution": [400, 400], "effects": ["strokes"]})",
                          "decimated bunny", "."),
        on = off;
  on.params.set("strokes.id_silhouette_lift", 2.0);
  expect_parity_and_more_arc(on, off, {LineKind::Silhouette}, "decimated bunny, lifted silhouettes");
}

// A unit cube seen from a generic direction near a corner: 12 crease paths (docs/conventions.md), of which
// the 9 around the three faces that face the eye are visible and the 3 meeting at the far
// corner are hidden, on both backends' ID images.
Scene cube_from_a_corner() {
  return testing::drawn_with_strokes(parse_scene(R"({"mesh": {"procedural": "cube"}, "resolution": [320, 240],
      "camera": {"eye": [2.2, 1.7, 2.6], "target": [0, 0, 0], "up": [0, 1, 0]}})",
                                                 "cube", "."));
}

std::vector<double> visible_share_per_path(const ImageU32& keys, const WindowLines& lines) {
  std::vector<double> share;
  for (const WindowPath& p : lines.paths) {
    int seen = 0, n = 32;
    for (int k = 0; k < n; ++k) seen += sample_visible(keys, sample_at(p, p.length_px * (k + 0.5) / n));
    share.push_back(double(seen) / n);
  }
  return share;
}

class StrokeVisibility : public testing::GlTest {};

TEST_F(StrokeVisibility, ACubeShowsNineOfItsTwelveEdges) {
  Scene scene = cube_from_a_corner();
  WindowLines lines = window_lines(scene, scene.params.get<StrokesParams>());
  ASSERT_EQ(lines.paths.size(), 12u);  // no silhouette of its own: a cube's outline is crease edges
  FrameOptions keep{true};
  for (const Frame& f : {reference::render(scene, keep), gpu::Renderer(scene).render(keep)}) {
    std::vector<double> share = visible_share_per_path(keys_from_channels(f.buffers.at(kIds.name)), lines);
    int visible = 0, hidden = 0;
    for (double s : share) visible += s == 1.0, hidden += s == 0.0;
    EXPECT_EQ(visible, 9);
    EXPECT_EQ(hidden, 3);
  }
}

// A sphere behind a plane that covers the lower half of the window, the plane drawn in
// `plane_style` (a sketchy plane is not in the G-buffer: the ID image draws its faces itself).
Scene sphere_behind_a_plane(const std::string& plane_style = "pencil") {
  return parse_scene(R"({"objects": [
      {"mesh": {"procedural": "sphere"}, "style": "strokes"},
      {"mesh": {"procedural": "plane"}, "style": ")" +
                         plane_style + R"(",
       "transform": [2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 1.5, 1]}],
      "resolution": [320, 240], "effects": ["strokes"],
      "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40}})",
                     "sphere behind", ".");
}

// The plane's top edge in the window (y = 0 at z = 1.5; the camera is relative to the
// scene's origin).
double plane_edge_y(const Scene& scene) {
  return WindowProjection(scene.camera, scene.width, scene.height)(glm::dvec3(0, 0, 1.5) - scene.origin).y;
}

// The sphere's silhouette samples are visible above the plane's top edge and hidden below.
void expect_half_hidden(const Scene& scene) {
  WindowLines lines = window_lines(scene, scene.params.get<StrokesParams>());
  ASSERT_EQ(lines.paths.size(), 1u);
  double edge_y = plane_edge_y(scene);
  FrameOptions keep{true};
  for (const Frame& f : {reference::render(scene, keep), gpu::Renderer(scene).render(keep)}) {
    ImageU32 keys = keys_from_channels(f.buffers.at(kIds.name));
    const WindowPath& p = lines.paths[0];
    int checked = 0;
    for (int k = 0; k < 200; ++k) {
      VisibilitySample s = sample_at(p, p.length_px * k / 200.0);
      if (std::abs(s.window.y - edge_y) < 3) continue;  // the 3x3 test reaches across the edge
      EXPECT_EQ(sample_visible(keys, s), s.window.y > edge_y) << "at y " << s.window.y << ", edge " << edge_y;
      ++checked;
    }
    EXPECT_GT(checked, 150);
  }
}

TEST_F(StrokeVisibility, AHiddenHalfOfASilhouette) {
  for (const std::string style : {"pencil", "sketchy"}) {
    SCOPED_TRACE(style);
    expect_half_hidden(sphere_behind_a_plane(style));
  }
}

// The runs end where the silhouette goes behind the plane, within the 1 px of the bisection
// (Kalnins et al. 2002, §4.1), and those ends are occlusion ends (they get the halo).
TEST_F(StrokeVisibility, RunsEndAtTheOccluderWithinAPixel) {
  Scene scene = sphere_behind_a_plane();
  auto p = scene.params.get<StrokesParams>();
  WindowLines lines = window_lines(scene, p);
  double edge_y = plane_edge_y(scene);
  FrameOptions keep{true};
  ImageU32 keys = keys_from_channels(reference::render(scene, keep).buffers.at(kIds.name));
  auto test = [&](const std::vector<VisibilitySample>& batch) {
    std::vector<uint8_t> flags;
    for (const VisibilitySample& s : batch) flags.push_back(sample_visible(keys, s));
    return flags;
  };
  Visibility v = visible_runs(lines, p, test);
  ASSERT_EQ(v.runs.size(), 1u);
  const VisibleRun& run = v.runs[0];
  EXPECT_TRUE(run.occluded_start && run.occluded_end);
  // The ID test flips where the 3x3 box leaves the plane's pixels: 1.5 px above its edge
  // (+ the pixel the edge falls in), then located within 1 px.
  for (glm::dvec2 end : {run.window.front(), run.window.back()}) EXPECT_NEAR(end.y, edge_y, 3.0);
}

}  // namespace
}  // namespace plumbago

namespace plumbago {
namespace {

// A style whose offsets the Markov chain synthesizes (Kalnins et al. 2002, §4.3, §5, App. A): the same seed draws the
// same strokes, another seed other ones, and both backends draw them alike.
TEST(StrokeSynthesis, SeededDeterministicAndOnBothBackends) {
  auto scene_with_seed = [](uint32_t seed) {
    Scene s =
        parse_scene(R"({"objects": [{"mesh": {"procedural": "torus"}, "style": "strokes"}], "resolution": [200, 150],
        "effects": ["strokes"], "strokes": {"silhouette": "sketchy_pencil"}})",
                    "synthesis", ".");
    s.seed = seed;
    return s;
  };
  gpu::Context::get();
  Image a = gpu::Renderer(scene_with_seed(1)).render().color, b = gpu::Renderer(scene_with_seed(1)).render().color;
  Image c = gpu::Renderer(scene_with_seed(2)).render().color;
  EXPECT_EQ(a.data, b.data);
  EXPECT_NE(a.data, c.data);
  auto results = run_parity(scene_with_seed(1), {"stroke"});
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(results[0].pass) << results[0].note;
}

}  // namespace
}  // namespace plumbago

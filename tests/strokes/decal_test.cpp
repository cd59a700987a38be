// Stroke files and decals (Kalnins et al. 2002, §3, §4.5): the file's reading and refusals, the two backends'
// projections onto the surface, decal parity, decals hidden behind the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "common/strokes/decal.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/visibility.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/strokes/decal.hpp"
#include "parity/parity.hpp"
#include "reference/core/pipeline.hpp"
#include "reference/scene/ray_scene.hpp"
#include "reference/strokes/decal.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const char* kFile = R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40,
  "near": 1, "far": 10}, "resolution": [320, 240], "style": "pencil", "strokes": [
  {"role": "decal", "points": [[10, 10, 1], [20, 20, 0.5]]},
  {"role": "decal", "style": "ink", "points": [[10, 10, 1], [20, 20, 0.5]]},
  {"role": "crease", "points": [[0, 0, 1], [5, 0, 1]]},
  {"role": "silhouette", "points": [[0, 0, 1], [5, 0, 1]]},
  {"role": "hatching", "group": 3, "points": [[0, 0, 1], [5, 0, 1]]}]})";

TEST(StrokeFile, EveryRoleIsKept) {
  StrokeFile f = parse_stroke_file(kFile, "f.json", ".", glm::dvec3(0, 0, 1));
  ASSERT_EQ(f.strokes.size(), 5u);
  EXPECT_EQ(f.width, 320);
  EXPECT_FLOAT_EQ(f.camera.eye.z, 4.0f);  // relative to the scene's origin
  EXPECT_EQ(f.strokes[0].style_name, "pencil");
  EXPECT_EQ(f.strokes[1].style_name, "ink");
  ASSERT_TRUE(f.strokes[1].style.has_value());
  EXPECT_EQ(f.strokes[2].role, StrokeRole::Crease);
  EXPECT_EQ(f.strokes[3].role, StrokeRole::Silhouette);
  EXPECT_EQ(f.strokes[4].role, StrokeRole::Hatching);
  EXPECT_EQ(f.strokes[4].group, 3);
  EXPECT_EQ(f.strokes[4].style_name, "pencil");  // the file's
  EXPECT_TRUE(f.strokes[4].style.has_value());
  EXPECT_FALSE(f.strokes[4].free);
  StrokeFile again = parse_stroke_file(stroke_file_json(f, glm::dvec3(0, 0, 1)), "g.json", ".", glm::dvec3(0, 0, 1));
  EXPECT_EQ(again.strokes.size(), 5u);
  EXPECT_EQ(again.strokes[1].style_name, "ink");
  EXPECT_DOUBLE_EQ(again.strokes[0].points[1].pressure, 0.5);
}

std::string refusal(const std::string& from, const std::string& to) {
  std::string text = kFile;
  size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    parse_stroke_file(text, "bad.json", ".", glm::dvec3(0));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(StrokeFile, RefusalsNameTheFileAndThePath) {
  EXPECT_EQ(refusal("[20, 20, 0.5]]},\n  {\"role\": \"decal\", \"style\"",
                    "[20, 20, 1.5]]},\n  {\"role\": \"decal\", \"style\""),
            "bad.json: /strokes/0/points/1/2: pressure must be in [0, 1]");
  EXPECT_NE(refusal("\"crease\"", "\"outline\"").find("bad.json: /strokes/2/role: expected one of"), std::string::npos);
  EXPECT_EQ(refusal("\"group\": 3, ", ""), "bad.json: /strokes/4/group: missing (a hatching stroke's group)");
  EXPECT_NE(refusal("\"style\": \"ink\"", "\"style\": \"no_such\"").find("bad.json: /strokes/1/style: "),
            std::string::npos);
  EXPECT_NE(refusal("\"near\": 1", "\"near\": 1,").find("bad.json: line 2, column"), std::string::npos);
  EXPECT_EQ(refusal("\"resolution\": [320, 240]", "\"resolution\": [320]"),
            "bad.json: /resolution: expected [width, height] in pixels");
  EXPECT_NE(refusal("\"fov_deg\": 40,", "").find("bad.json: /camera/fov_deg: missing"), std::string::npos);
  EXPECT_NE(refusal("[[0, 0, 1], [5, 0, 1]]}]", "[[0, 0, 1]]}]").find("bad.json: /strokes/4/points: expected"),
            std::string::npos);
  // The last stroke made as long as the bound on a file's points allows (8 in the others), then one point longer.
  auto points = [](size_t n) {
    std::string text = "[[0, 0, 1]";
    for (size_t k = 1; k < n; ++k) text += ", [1, 0, 1]";
    return text + "]}]";
  };
  EXPECT_EQ(refusal("[[0, 0, 1], [5, 0, 1]]}]", points(kMaxDrawnPoints - 8)), "(accepted)");
  EXPECT_EQ(refusal("[[0, 0, 1], [5, 0, 1]]}]", points(kMaxDrawnPoints - 7)),
            "bad.json: /strokes/4/points: the strokes hold over 250000 points, the most a stroke file may");
}

TEST(StrokeFile, ScenesListThemRelativeToTheirFolder) {
  testing::TempDir dir;
  dir.write("s.strokes.json", kFile);
  std::string scene =
      R"({"objects": [{"mesh": {"procedural": "sphere"}, "style": "strokes"}], "stroke_files": ["s.strokes.json"]})";
  Scene s = load_scene(dir.write("scene.json", scene));
  ASSERT_EQ(s.stroke_files.size(), 1u);
  EXPECT_TRUE(has_decals(s));
  try {
    load_scene(dir.write("bad.json", R"({"mesh": {"procedural": "sphere"}, "stroke_files": ["none.json"]})"));
    FAIL() << "a missing stroke file was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("none.json: cannot read the stroke file"), std::string::npos) << e.what();
  }
}

// A crease example drawn in a stroke file becomes the creases' offsets (Kalnins et al. 2002, §3, §4.3, §5):
// measured from its chord, to the left of its direction of travel, its pressure kept; the
// rubber stamp takes the drawn examples in turn along a path, the Markov chain draws from them.
TEST(StrokeFile, DrawnExamplesStyleTheCreases) {
  testing::TempDir dir;
  std::string wave;
  for (int k = 0; k <= 40; ++k)
    wave += (k ? ", [" : "[") + std::to_string(100 + 2.5 * k) + ", " +
            std::to_string(50 + 3 * std::sin(k * std::numbers::pi / 10)) + ", 0.5]";
  dir.write("e.strokes.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0],
      "fov_deg": 40, "near": 1, "far": 10}, "resolution": [320, 240], "strokes": [
      {"role": "crease", "points": [)" +
                                  wave + R"(]}, {"role": "crease", "points": [[0, 0, 1], [0, 30, 1]]}]})");
  Scene s = load_scene(dir.write("scene.json", R"({"objects": [{"mesh": {"procedural": "cube"}, "style": "strokes"}],
      "stroke_files": ["e.strokes.json"]})"));
  ASSERT_EQ(s.strokes.crease_examples.size(), 2u);
  EXPECT_TRUE(s.strokes.silhouette_examples.empty());
  const OffsetExample& e = s.strokes.crease_examples[0];
  EXPECT_NEAR(e.length_px, 100.0, 1e-9);
  ASSERT_EQ(e.offsets.size(), 41u);
  for (size_t k = 0; k < e.offsets.size(); ++k) {
    EXPECT_NEAR(e.offsets[k].t, k / 40.0, 1e-6);
    EXPECT_NEAR(e.offsets[k].displacement_px, 3 * std::sin(k * std::numbers::pi / 10), 1e-5);  // to_string: 6 decimals
    EXPECT_DOUBLE_EQ(e.offsets[k].pressure, 0.5);
  }
  WindowPath path{LineKind::Crease, 0, false, true, 7, {}, {}, {}, {}, {}, {}, 0, {}, 0};
  VisibleRun run{0, 0, 80, false, false, false, {}};
  RunStyles stamp(s.strokes, 1, {});
  size_t first = stamp.of(path, run, 0).offsets->offsets.size();  // in turn, run after run along the path
  EXPECT_EQ(first + stamp.of(path, run, 1).offsets->offsets.size(), 43u);
  EXPECT_EQ(stamp.of(path, run, 2).offsets->offsets.size(), first);
  s.strokes.crease.synthesis = OffsetSynthesis::Markov;
  RunStyles markov(s.strokes, 1, {});
  StrokeStyle synthesized = markov.of(path, run, 0);
  for (const StrokeOffset& o : synthesized.offsets->offsets) EXPECT_LE(std::abs(o.displacement_px), 3.3);
  dir.write("e.strokes.json", R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0],
      "fov_deg": 40, "near": 1, "far": 10}, "resolution": [320, 240], "strokes": [
      {"role": "silhouette", "points": [[5, 5, 1], [9, 9, 1], [5.2, 5, 1]]}]})");
  try {
    load_scene(dir.path("scene.json"));
    FAIL() << "an example whose ends meet was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("e.strokes.json: /strokes/0/points: a crease or silhouette stroke is an "
                                         "offsets example: its ends must be 1 px apart or more"),
              std::string::npos)
        << e.what();
  }
}

// The stroke files' JSON Schema names the program's roles, and the stroke files of scenes/
// use only the keys it lists.
TEST(StrokeFile, SchemaMatchesTheReaderAndTheFiles) {
  std::ifstream in(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/stroke_file.schema.json");
  nlohmann::json schema = nlohmann::json::parse(in), stroke = schema["properties"]["strokes"]["items"];
  EXPECT_EQ(stroke["properties"]["role"]["enum"].get<std::vector<std::string>>(), stroke_role_names());
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/drawn")) {
    if (!e.path().string().ends_with(".strokes.json")) continue;
    ++files;
    nlohmann::json f = nlohmann::json::parse(std::ifstream(e.path()));
    for (const auto& item : f.items()) EXPECT_TRUE(schema["properties"].contains(item.key())) << e.path() << item.key();
    for (const nlohmann::json& s : f["strokes"])
      for (const auto& item : s.items())
        EXPECT_TRUE(stroke["properties"].contains(item.key())) << e.path() << item.key();
  }
  EXPECT_GE(files, 2u);
}

// A scene with strokes drawn over its own render: horizontal strokes every 12 px across the
// whole window, which cross the objects' silhouettes and the background.
Scene with_drawn_grid(Scene s) {
  s = testing::drawn_with_strokes(s);
  StrokeFile f;
  f.source = "grid";
  f.camera = s.camera, f.width = s.width, f.height = s.height;
  for (int y = 6; y < s.height; y += 12) {
    DrawnStroke stroke;
    stroke.points = {{{3.0, y + 0.37}, 1.0}, {{s.width - 3.0, y + 4.37}, 0.5}};
    stroke.style = load_stroke_style("ink");
    f.strokes.push_back(stroke);
  }
  s.stroke_files = {f};
  return s;
}

// Whether window point p of `file` lies within a pixel of a silhouette: one of 8 rays 1 px
// around it misses, meets another object, or meets a point farther than 3 pixel footprints
// from its own (a depth step).
std::vector<uint8_t> near_silhouette(const Scene& scene, const std::vector<DecalSamples>& samples) {
  std::vector<WorldObject> world = world_geometry(scene);
  reference::RayScene rays(world);
  auto at = [&](const DecalPoint& d) {
    const WorldObject& o = world[d.object];
    const glm::uvec3& t = o.triangles[d.face];
    return d.bary.x * glm::dvec3(o.positions[t[0]]) + d.bary.y * glm::dvec3(o.positions[t[1]]) +
           d.bary.z * glm::dvec3(o.positions[t[2]]);
  };
  std::vector<uint8_t> out;
  for (const DecalSamples& d : samples)
    for (const DrawnPoint& p : d.samples) {
      DecalPoint c = reference::first_surface_hit(rays.get(), *d.file, p);
      double footprint = c.object == kMissed
                             ? 0.0
                             : glm::distance(at(c), glm::dvec3(d.file->camera.eye)) * 2 *
                                   std::tan(glm::radians(double(d.file->camera.fov_deg)) / 2) / d.file->height;
      bool near = false;
      for (int k = 0; k < 8 && !near; ++k) {
        glm::dvec2 offset(std::cos(k * std::numbers::pi / 4), std::sin(k * std::numbers::pi / 4));
        DecalPoint q = reference::first_surface_hit(rays.get(), *d.file, {p.window + offset, 1.0});
        near = q.object != c.object || (c.object != kMissed && glm::distance(at(q), at(c)) > 3 * footprint);
      }
      out.push_back(near);
    }
  return out;
}

class DecalProjection : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

// The GPU's projection through the G-buffer and the reference's through Embree rays put the
// same samples on the same faces, except within a pixel of a silhouette.
TEST_P(DecalProjection, BackendsAgree) {
  Scene scene = with_drawn_grid(GetParam() == "teapot" ? load_scene(PLUMBAGO_SOURCE_DIR "/scenes/teapot_decals.json")
                                                       : testing::builtin_at(GetParam(), 320, 240));
  if (GetParam() == "teapot")
    scene.stroke_files.push_back(load_scene(PLUMBAGO_SOURCE_DIR "/scenes/teapot_decals.json").stroke_files[0]);
  std::vector<DecalSamples> samples = decal_samples(scene);
  DecalSurface gpu = gpu::project_decals_through_gbuffer(scene), ref = reference::project_decals_by_rays(scene);
  ProjectionAgreement a = compare_projections(gpu, ref, near_silhouette(scene, samples));
  size_t on_surface = 0;
  for (const ProjectedDecal& d : ref)
    for (const DecalPoint& p : d.points) on_surface += p.object != kMissed;
  std::printf(
      "[decal projection %s] %zu points (%zu on the surface): %.4f%% on the same face, max |bary diff| %.3g; "
      "%zu differ on a shared edge, %zu within 1 px of a silhouette, %zu elsewhere\n",
      GetParam().c_str(), a.points, on_surface, 100.0 * double(a.same_face) / double(a.points), a.max_bary_difference,
      a.differ_on_edge, a.differ_near_silhouette, a.differ_elsewhere);
  ASSERT_GT(on_surface, a.points / 10);    // the grid crosses the objects
  EXPECT_LE(a.max_bary_difference, 1e-3);  // Embree's float u, v against double (measured 4.6e-4, teapot)
  EXPECT_LE(a.differ_on_edge, a.points / 100);
  EXPECT_LE(a.differ_near_silhouette, a.points / 100);
  // Measured 0 on all four since the GPU tries the faces around those it sees; before, 6
  // (torus), 12 (cad, 0.38%) and 9 (teapot): slivers that cover no pixel center.
  EXPECT_LE(a.differ_elsewhere, a.points / 2000);
}

INSTANTIATE_TEST_SUITE_P(Scenes, DecalProjection, ::testing::Values("sphere", "torus", "cad", "teapot"));

class DecalStrokes : public testing::GlTest {};

// Decals through the ID image, visibility and the stroke raster, fed the same inputs.
TEST_F(DecalStrokes, Parity) {
  for (const char* name : {"sphere", "torus"}) {
    Scene scene = with_drawn_grid(testing::builtin_at(name, 320, 240));
    DecalSurface surface = reference::project_decals_by_rays(scene);
    const SurfaceStrokes strokes = surface_strokes(scene, surface);
    WindowLines lines = window_lines(scene, scene.params.get<StrokesParams>(), LineObjects::Strokes, nullptr, &strokes);
    size_t decals = 0;
    for (const WindowPath& p : lines.paths) decals += p.kind == LineKind::Decal;
    ASSERT_GT(decals, 5u) << name;
    auto results = run_parity(scene, {"id_image", "visibility", "stroke"});
    ASSERT_EQ(testing::names_of(results), (std::vector<std::string>{kIds.name, kCreaseIds.name, kFlags.name,
                                                                    kRunPaths.name, kRunEnds.name, kStrokeColor.name}));
    for (const StageParity& r : results) {
      std::printf("[decals %s] %s  [%s]\n", name, format_diff(r.name, r.diff).c_str(), r.note.c_str());
      EXPECT_TRUE(r.pass) << name << " " << r.name << ": " << r.note;
    }
  }
}

// The share of each decal path's length visible in the ID image of `scene`'s reference frame.
double visible_decal_share(const Scene& scene, const DecalSurface& surface) {
  const SurfaceStrokes strokes = surface_strokes(scene, surface);
  WindowLines lines = window_lines(scene, scene.params.get<StrokesParams>(), LineObjects::Strokes, nullptr, &strokes);
  ImageU32 keys = keys_from_channels(reference::render(scene, FrameOptions{true}).buffers.at(kIds.name));
  int seen = 0, n = 0;
  for (const WindowPath& p : lines.paths)
    if (p.kind == LineKind::Decal)
      for (int k = 0; k < 32; ++k, ++n) seen += sample_visible(keys, sample_at(p, p.length_px * (k + 0.5) / 32));
  return n ? double(seen) / n : 0.0;
}

// Decals drawn on a sphere's front are seen from the front and hidden from behind.
TEST(Decals, StayOnTheSurfaceAndHideBehindIt) {
  Scene scene = with_drawn_grid(testing::builtin_at("sphere", 320, 240));
  for (DrawnStroke& s : scene.stroke_files[0].strokes)  // only the middle of the window: on the sphere
    s.points = {{{130, s.points[0].window.y}, 1}, {{190, s.points[0].window.y}, 1}};
  scene.stroke_files[0].strokes.resize(8);
  for (size_t i = 0; i < 8; ++i)
    for (DrawnPoint& p : scene.stroke_files[0].strokes[i].points) p.window.y = 84 + 9.0 * double(i);
  DecalSurface surface = reference::project_decals_by_rays(scene);
  double front = visible_decal_share(scene, surface);
  scene.camera.eye = 2.0f * scene.camera.target - scene.camera.eye;
  double back = visible_decal_share(scene, surface);
  std::printf("[decals] visible share from the front %.3f, from behind %.3f\n", front, back);
  EXPECT_GE(front, 0.98);
  EXPECT_EQ(back, 0.0);
}

TEST(StrokeFileCommand, SvgOverTheRenderBecomesAStrokeFile) {
  testing::TempDir dir;
  dir.write("d.svg", R"(<svg xmlns="http://www.w3.org/2000/svg" width="400" height="300" viewBox="0 0 800 600">
    <polyline stroke-width="4" points="100,100 200,150 300,100"/>
    <path stroke-width="2" data-style="pencil" d="M 10 20 l 30 0 v 10 Z"/>
    <polyline data-role="hatching" data-group="2" data-pressure="0.5" points="0,0 10,10"/></svg>)");
  auto run = testing::run_cli(
      "strokefile builtin:torus --size 800x600 " + dir.path("d.svg") + " -o " + dir.path("s.json") + " --style ink",
      dir);
  ASSERT_EQ(run.code, 0) << run.err;
  Scene scene = testing::builtin_at("torus", 800, 600);
  StrokeFile f = load_stroke_file(dir.path("s.json"), scene.origin);
  ASSERT_EQ(f.strokes.size(), 3u);
  EXPECT_EQ(f.width, 800);
  EXPECT_NEAR(glm::distance(glm::dvec3(f.camera.eye), glm::dvec3(scene.camera.eye)), 0.0, 1e-5);
  EXPECT_EQ(f.strokes[0].points[1].window, glm::dvec2(200, 450));  // y flipped: docs/conventions.md's window
  EXPECT_DOUBLE_EQ(f.strokes[0].points[0].pressure, 1.0);          // the widest stroke
  EXPECT_EQ(f.strokes[0].style_name, "ink");
  ASSERT_EQ(f.strokes[1].points.size(), 4u);  // M, l, v, Z back to the start
  EXPECT_DOUBLE_EQ(f.strokes[1].points[0].pressure, 0.5);
  EXPECT_EQ(f.strokes[1].points[2].window, glm::dvec2(40, 570));
  EXPECT_EQ(f.strokes[1].style_name, "pencil");
  EXPECT_EQ(f.strokes[2].role, StrokeRole::Hatching);
  EXPECT_EQ(f.strokes[2].group, 2);

  dir.write("curve.svg", R"(<svg width="800" height="600"><path d="M 0 0 C 10 10 20 20 30 0"/></svg>)");
  auto curve = testing::run_cli("strokefile builtin:torus " + dir.path("curve.svg") + " -o " + dir.path("c.json"), dir);
  EXPECT_EQ(curve.code, 2);
  EXPECT_NE(curve.err.find("curve.svg: <path> #1: d: path command 'C' is not a straight segment"), std::string::npos)
      << curve.err;
}

}  // namespace
}  // namespace plumbago

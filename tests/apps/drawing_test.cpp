// Drawing on the model without a window (apps/viewer/drawing.hpp, the script's "draw"
// action): strokes grouped into stroke files by the view they were drawn in, undo, redo and
// erase, the files saved and read back, the scene saved with them. The viewer's own tests
// (tests/apps/viewer_test.cpp) draw through the window and render what was saved.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "apps/viewer/drawing.hpp"
#include "apps/viewer/script.hpp"
#include "common/strokes/strokes.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

const std::string kTorus = std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/torus_strokes.json";

DrawRequest request(StrokeRole role, std::vector<glm::dvec2> points, const std::string& style = "ink") {
  DrawRequest r;
  r.role = role, r.style = style;
  for (glm::dvec2 p : points) r.points.push_back({p, 0.5});
  return r;
}

// Adds a decal along `points` in `scene`'s view.
void draw(Drawing& d, const Scene& scene, std::vector<glm::dvec2> points, const std::string& style = "ink") {
  d.add(scene, drawn_stroke(scene, request(StrokeRole::Decal, std::move(points), style)));
}

Scene orbited(Scene s) {
  s.camera.eye.x += 0.5f;
  return s;
}

TEST(Drawing, StrokesOfOneViewShareAFile) {
  Scene scene = load_scene(kTorus), moved = orbited(scene);
  Drawing d;
  draw(d, scene, {{10, 10}, {20, 12}});
  draw(d, scene, {{30, 10}, {40, 12}});
  draw(d, moved, {{50, 10}, {60, 12}});
  draw(d, scene, {{70, 10}, {80, 12}});  // back in the first view: a file of its own, after
  std::vector<StrokeFile> files = d.files();
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].strokes.size(), 2u);
  EXPECT_EQ(files[1].strokes.size(), 1u);
  EXPECT_EQ(files[1].camera.eye, moved.camera.eye);
  EXPECT_EQ(files[2].strokes.at(0).points.at(0).window, glm::dvec2(70, 10));
  EXPECT_EQ(files[0].width, scene.width);
  EXPECT_EQ(files[1].source, "(drawn in view 2, not saved)");
  EXPECT_FALSE(d.saved());
}

TEST(Drawing, UndoRedoAndEraseFollowTheOrderDrawn) {
  Scene scene = load_scene(kTorus);
  Drawing d;
  EXPECT_FALSE(d.undo());
  draw(d, scene, {{10, 10}, {20, 12}});
  draw(d, scene, {{30, 10}, {40, 12}});
  ASSERT_TRUE(d.undo());
  EXPECT_EQ(d.size(), 1u);
  ASSERT_TRUE(d.redo());
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d.stroke(1).points.at(0).window, glm::dvec2(30, 10));
  EXPECT_FALSE(d.redo()) << "nothing undone";
  d.undo();
  draw(d, scene, {{50, 10}, {60, 12}});
  EXPECT_FALSE(d.redo()) << "a new stroke drops what was undone";
  d.erase(0);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.stroke(0).points.at(0).window, glm::dvec2(50, 10));
}

TEST(Drawing, SavedFilesReadBackAsDrawn) {
  testing::TempDir tmp;
  Scene scene = load_scene(kTorus), moved = orbited(scene);
  Drawing d;
  draw(d, scene, {{10, 10}, {20, 12}, {25, 30}}, "pencil");
  DrawRequest hatch = request(StrokeRole::Hatching, {{5, 5}, {9, 7}});
  hatch.group = 3, hatch.free = true;
  d.add(moved, drawn_stroke(moved, hatch));
  std::vector<std::string> paths = d.save(tmp.path("drawn.strokes.json"), scene.origin);
  ASSERT_EQ(paths, (std::vector<std::string>{tmp.path("drawn.strokes.json"), tmp.path("drawn.strokes-2.json")}));
  EXPECT_TRUE(d.saved());
  std::vector<StrokeFile> files = d.files();
  for (size_t i = 0; i < files.size(); ++i) {
    EXPECT_EQ(files[i].source, paths[i]);
    StrokeFile read = load_stroke_file(paths[i], scene.origin);
    ASSERT_EQ(read.strokes.size(), files[i].strokes.size());
    const DrawnStroke &a = read.strokes[0], &b = files[i].strokes[0];
    EXPECT_EQ(a.role, b.role);
    EXPECT_EQ(a.group, b.group);
    EXPECT_EQ(a.free, b.free);
    EXPECT_EQ(a.style_name, b.style_name);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (size_t k = 0; k < a.points.size(); ++k) {
      EXPECT_EQ(a.points[k].window, b.points[k].window);
      EXPECT_EQ(a.points[k].pressure, 0.5);
    }
    EXPECT_NEAR(glm::distance(read.camera.eye, files[i].camera.eye), 0.0f, 1e-5f);
  }
  d.undo();
  EXPECT_FALSE(d.saved());
  EXPECT_EQ(d.files().at(0).source, "(drawn in view 1, not saved)") << "changed since it was written";
}

TEST(Drawing, SaveRefusesNothingDrawnAndWritesNothing) {
  testing::TempDir tmp;
  Drawing d;
  EXPECT_THROW(d.save(tmp.path("none.json"), glm::dvec3(0.0)), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(tmp.path("none.json")));
}

TEST(Drawing, StyleFileIsWrittenRelativeToTheStrokeFile) {
  testing::TempDir tmp;
  std::filesystem::create_directories(tmp.path("styles"));
  std::filesystem::create_directories(tmp.path("out"));
  std::filesystem::copy_file(stroke_style_dir() + "/ink.json", tmp.path("styles/mine.json"));
  Scene scene = load_scene(kTorus);
  Drawing d;
  draw(d, scene, {{10, 10}, {20, 12}}, tmp.path("styles/mine.json"));
  d.save(tmp.path("out/s.json"), scene.origin);
  StrokeFile read = load_stroke_file(tmp.path("out/s.json"), scene.origin);
  EXPECT_EQ(read.strokes.at(0).style_name, "../styles/mine.json");
  EXPECT_TRUE(read.strokes.at(0).style.has_value());
}

DecalPoint on_face(uint32_t face) { return {0, face, glm::dvec3(1.0 / 3)}; }

TEST(Drawing, SurfaceSplitsWhereAPointMissedAndNamesItsObject) {
  Scene scene = load_scene(kTorus);
  DecalPoint missed;
  DecalSurface projected{{default_stroke_style(), {on_face(0), missed, on_face(5), on_face(6)}, {}}};
  DrawnSurface s = drawn_surface(scene, projected);
  ASSERT_EQ(s.polylines.size(), 2u);
  EXPECT_EQ(s.polylines[0].size(), 1u);
  EXPECT_EQ(s.polylines[1].size(), 2u);
  EXPECT_EQ(s.object, 0u);
  scene.objects[0].style = Style::Pencil;  // decals show on stroke objects only
  EXPECT_EQ(drawn_surface(scene, projected).object, kMissed);
}

TEST(Drawing, EraserPicksTheStrokeUnderTheCursorInThisView) {
  Scene scene = load_scene(kTorus);
  Drawing d;
  DrawnSurface first = drawn_surface(scene, {{default_stroke_style(), {on_face(0), on_face(40)}, {}}});
  DrawnSurface second = drawn_surface(scene, {{default_stroke_style(), {on_face(900), on_face(1200)}, {}}});
  d.add(scene, drawn_stroke(scene, request(StrokeRole::Decal, {{1, 1}, {2, 2}})), first);
  d.add(scene, drawn_stroke(scene, request(StrokeRole::Silhouette, {{1, 1}, {9, 2}})));  // on no surface
  d.add(scene, drawn_stroke(scene, request(StrokeRole::Decal, {{1, 1}, {2, 2}})), second);
  const WindowProjection project(scene.camera, scene.width, scene.height);
  auto window = [&](const DecalPoint& p) { return glm::dvec2(project(decal_point_world(scene, p))); };
  glm::dvec2 a = window(on_face(900)), b = window(on_face(1200)),
             normal = glm::normalize(glm::dvec2(a.y - b.y, b.x - a.x));
  ASSERT_GT(glm::distance(a, b), 20.0) << "a segment long enough to pick along";
  EXPECT_EQ(d.stroke_near(scene, (a + b) * 0.5 + 3.0 * normal, 6), std::optional<size_t>(2));
  EXPECT_EQ(d.stroke_near(scene, window(on_face(40)), 6), std::optional<size_t>(0));
  EXPECT_EQ(d.stroke_near(scene, glm::dvec2(-100, -100), 6), std::nullopt);
  Scene moved = orbited(scene);  // the surface points move with the view
  EXPECT_NE(d.stroke_near(moved, (a + b) * 0.5, 0.5), std::optional<size_t>(2));
}

TEST(Drawing, StrokesAreRefusedAsStrokeFilesRefuseThem) {
  Scene scene = load_scene(kTorus);
  EXPECT_THROW(drawn_stroke(scene, request(StrokeRole::Crease, {{10, 10}, {10.2, 10}})), SceneError)
      << "an offsets example's ends under 1 px apart";
  EXPECT_THROW(drawn_stroke(scene, request(StrokeRole::Decal, {{10, 10}, {20, 10}}, "no_such_style")), SceneError);
  DrawRequest far = request(StrokeRole::Decal, {{10, 10}, {2 * kMaxDrawnPixel, 10}});
  EXPECT_THROW(drawn_stroke(scene, far), SceneError);
  DrawnStroke example = drawn_stroke(scene, request(StrokeRole::Silhouette, {{10, 10}, {20, 14}, {40, 10}}));
  EXPECT_TRUE(example.style_name.empty()) << "an example has no style of its own";
}

TEST(Drawing, SavedSceneListsTheDrawnFilesAndTheirExamples) {
  testing::TempDir tmp;
  Scene scene = load_scene(kTorus);
  Drawing d;
  draw(d, scene, {{10, 10}, {20, 12}});
  d.add(scene, drawn_stroke(scene, request(StrokeRole::Silhouette, {{10, 10}, {20, 14}, {40, 10}})));
  std::filesystem::create_directories(tmp.path("strokes"));
  d.save(tmp.path("strokes/drawn.json"), scene.origin);
  for (const StrokeFile& f : d.files()) scene.stroke_files.push_back(f);
  set_drawn_examples(scene);
  EXPECT_EQ(scene.strokes.silhouette_examples.size(), 1u);
  std::filesystem::create_directories(tmp.path("scenes"));
  save_scene(scene, tmp.path("scenes/saved.json"));
  Scene read = load_scene(tmp.path("scenes/saved.json"));
  ASSERT_EQ(read.stroke_files.size(), 1u);
  EXPECT_EQ(read.stroke_files[0].strokes.size(), 2u);
  EXPECT_EQ(read.strokes.silhouette_examples.size(), 1u);
  std::ifstream text(tmp.path("scenes/saved.json"));
  std::string doc((std::istreambuf_iterator<char>(text)), {});
  EXPECT_NE(doc.find("\"../strokes/drawn.json\""), std::string::npos) << doc;
}

TEST(Drawing, SceneWithStrokesNeverWrittenIsNotSaved) {
  testing::TempDir tmp;
  Scene scene = load_scene(kTorus);
  Drawing d;
  draw(d, scene, {{10, 10}, {20, 12}});
  scene.stroke_files = d.files();
  EXPECT_THROW(save_scene(scene, tmp.path("saved.json")), SceneError);
  EXPECT_FALSE(std::filesystem::exists(tmp.path("saved.json")));
}

TEST(DrawScript, ChecksTheStrokeItDraws) {
  using nlohmann::json;
  DrawRequest r = draw_request(
      json::parse(R"({"kind": "hatching", "group": 2, "free": true, "points": [[1, 2], [3, 4]], "pressure": [0, 1]})"));
  EXPECT_EQ(r.role, StrokeRole::Hatching);
  EXPECT_EQ(r.group, 2);
  EXPECT_TRUE(r.free);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[1].window, glm::dvec2(3, 4));
  EXPECT_EQ(r.points[1].pressure, 1.0);
  EXPECT_EQ(draw_request(json::parse(R"({"kind": "decal", "points": [[1, 2], [3, 4]]})")).style, kDefaultDecalStyle);
  for (const char* bad :
       {R"({"kind": "mobile", "points": [[1, 2], [3, 4]]})", R"({"kind": "decal", "points": [[1, 2]]})",
        R"({"kind": "decal", "points": [[1, 2], [3, "x"]]})",
        R"({"kind": "decal", "points": [[1, 2], [3, 4]], "pressure": [1]})",
        R"({"kind": "decal", "points": [[1, 2], [3, 4]], "pressure": [1, 1.5]})",
        R"({"kind": "hatching", "group": -1, "points": [[1, 2], [3, 4]]})",
        R"({"kind": "decal", "points": [[1, 2], [3, 4]], "colour": 1})"})
    EXPECT_THROW(draw_request(json::parse(bad)), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace plumbago

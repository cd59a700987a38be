// `plumbago view` without a person: under Xvfb (xvfb-run) with Mesa's llvmpipe, the
// viewer draws N frames, writes what its window shows and exits; that must be what
// `plumbago render` writes for the same scene. Skipped, saying why, when the viewer was
// not built (no GLFW or Dear ImGui) or xvfb-run is missing (Debian package xvfb).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/scene/orbit.hpp"
#include "common/scene/scene.hpp"
#include "common/util/image_compare.hpp"
#include "gpu/core/pipeline.hpp"
#include "tests/support/cli_run.hpp"

namespace plumbago {
namespace {

// The viewer shows the frame the pipeline read back, blitted 1:1 into an 8-bit window:
// the PNGs can differ by the rounding of one conversion to 8 bits.
constexpr double kTolerance = 2.0 / 255;

class Viewer : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!PLUMBAGO_VIEWER) GTEST_SKIP() << "plumbago was built without the viewer (libglfw3-dev, libimgui-dev missing)";
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
      GTEST_SKIP() << "xvfb-run is missing (Debian package xvfb): no X server for the viewer";
  }

  // `plumbago view ARGS` under a fresh Xvfb; each test process asks for its own server
  // number (-n, then -a finds a free one from there), so parallel tests do not race.
  testing::CliRun view(const std::string& args, const std::string& before = "") const {
    std::string server = std::to_string(100 + ::getpid() % 800);
    return run("view " + args, before + "xvfb-run -a -n " + server + " -s '-screen 0 1600x1200x24' ");
  }
  testing::CliRun run(const std::string& args, const std::string& wrapper = "") const {
    return testing::run_cli(args, tmp_, wrapper);
  }
  std::string path(const std::string& name) const { return tmp_.path(name); }
  // A --script file of `actions` (JSON text).
  std::string script(const std::string& actions) const {
    std::ofstream(path("script.json")) << actions;
    return path("script.json");
  }
  // `plumbago view SCENE --no-ui --frames 1 --script ...` at kSize; asserts it succeeded.
  void view_script(const std::string& scene, const std::string& actions) const {
    testing::CliRun v = view(scene + kSize + " --no-ui --frames 1 --script " + script(actions));
    ASSERT_EQ(v.code, 0) << v.err;
  }
  // The largest difference between two PNGs in the first channels both have.
  double png_difference(const std::string& a, const std::string& b) const {
    Image x = read_image(a), y = read_image(b);
    EXPECT_EQ(x.width, y.width);
    EXPECT_EQ(x.height, y.height);
    double most = 0;
    for (int yy = 0; yy < std::min(x.height, y.height); ++yy)
      for (int xx = 0; xx < std::min(x.width, y.width); ++xx)
        for (int c = 0; c < std::min(x.channels, y.channels); ++c)
          most = std::max(most, double(std::abs(x.at(xx, yy, c) - y.at(xx, yy, c))));
    return most;
  }

  static constexpr const char* kSize = " --size 160x120";

  testing::TempDir tmp_;
};

TEST_F(Viewer, ScreenshotWithoutPanelEqualsRender) {
  const std::string scene =
      std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/sketchy_mixed.json --size 320x240 --set contour.copies=2";
  testing::CliRun v = view(scene + " --frames 3 --no-ui --screenshot " + path("view.png"));
  ASSERT_EQ(v.code, 0) << v.err;
  testing::CliRun r = run("render " + scene + " -o " + path("render.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  Image shown = read_image(path("view.png")), rendered = read_image(path("render.png"));
  ASSERT_EQ(shown.width, 320);
  ASSERT_EQ(shown.height, 240);
  ImageDiff d = compare_images(shown, rendered, kTolerance);
  EXPECT_LE(d.max_abs, kTolerance) << format_diff("view vs render", d);
}

const std::string kMixed = std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/sketchy_mixed.json";

TEST_F(Viewer, ScriptedParameterChangesTheImageAsRenderSetDoes) {
  view_script(kMixed, R"([{"screenshot": ")" + path("before.png") + R"("}, {"set": {"contour.copies": 1}},
                          {"screenshot": ")" +
                          path("after.png") + R"("}])");
  testing::CliRun r = run("render " + kMixed + kSize + " --set contour.copies=1 -o " + path("render.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(png_difference(path("before.png"), path("after.png")), 0.25) << "the parameter changed the image";
  EXPECT_LE(png_difference(path("after.png"), path("render.png")), kTolerance);
}

// Toggling an effect and saving: `render` of the saved scene draws what the viewer showed.
TEST_F(Viewer, ScriptedEffectToggleSavedRendersTheSame) {
  view_script(kMixed, R"([{"screenshot": ")" + path("before.png") + R"("}, {"effect": {"interior": false}},
                          {"save": ")" +
                          path("saved.json") + R"("}, {"screenshot": ")" + path("after.png") + R"("}])");
  Scene saved = load_scene(path("saved.json"));
  EXPECT_EQ(std::count(saved.effects.begin(), saved.effects.end(), "interior"), 0);
  testing::CliRun r = run("render " + path("saved.json") + " -o " + path("render.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(png_difference(path("before.png"), path("after.png")), 0.25) << "the effect changed the image";
  EXPECT_LE(png_difference(path("after.png"), path("render.png")), kTolerance);
}

const std::string kTorusStrokes = std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/torus_strokes.json";

// Drawing on the model (Kalnins et al. 2002): a decal drawn by script shows at once, a
// silhouette example restyles the silhouettes, a mobile hatching group of two strokes is
// drawn, undo and the eraser take strokes back; the strokes and
// the scene saved, `render` of the saved scene draws what the viewer showed, and
// `compare` finds both backends agreeing on it. Coherent silhouettes off: the viewer's frames
// each carry the last one's brush parameters, which a still render (arc length) cannot know.
TEST_F(Viewer, DrawnStrokesSavedRenderTheSameOnBothBackends) {
  view_script(kTorusStrokes + " --set strokes.coherent=false", R"([{"screenshot": ")" + path("before.png") + R"("},
      {"draw": {"kind": "decal", "style": "ink", "points": [[55, 35], [75, 41], [100, 31]], "pressure": [0.3, 1, 0.6]}},
      {"draw": {"kind": "decal", "style": "pencil", "points": [[60, 80], [100, 85]]}}, {"undo": ""},
      {"draw": {"kind": "decal", "style": "pencil", "points": [[60, 90], [100, 95]]}}, {"erase": [80, 93]},
      {"screenshot": ")" + path("decal.png") +
                                                                   R"("},
      {"draw": {"kind": "silhouette", "points": [[0, 0], [10, 8], [20, -8], [30, 8], [40, 0]]}},
      {"draw": {"kind": "hatching", "group": 0, "mobile": true, "points": [[62, 52], [65, 70]]}},
      {"draw": {"kind": "hatching", "group": 0, "mobile": true, "points": [[67, 52], [70, 70]]}},
      {"save_strokes": ")" + path("drawn.strokes.json") + R"("}, {"save": ")" +
                                                                   path("saved.json") + R"("},
      {"screenshot": ")" + path("after.png") + R"("}])");
  EXPECT_GT(png_difference(path("before.png"), path("decal.png")), 0.25) << "the decal shows";
  EXPECT_GT(png_difference(path("decal.png"), path("after.png")), 0.25) << "the example restyles the silhouettes";
  StrokeFile saved = load_stroke_file(path("drawn.strokes.json"), glm::dvec3(0.0));
  ASSERT_EQ(saved.strokes.size(), 4u) << "the undone stroke and the erased one are not saved";
  EXPECT_EQ(saved.strokes[1].role, StrokeRole::Silhouette);
  EXPECT_TRUE(saved.strokes[3].mobile) << "a structured group of two strokes drawn in one view, mobile";
  testing::CliRun r = run("render " + path("saved.json") + " -o " + path("render.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_LE(png_difference(path("after.png"), path("render.png")), kTolerance);
  testing::CliRun c = run("compare " + path("saved.json"));
  EXPECT_EQ(c.code, 0) << c.out << c.err;
}

// What a new user does first: a decal drawn on the teapot (../shared/models), saved with
// the scene, renders as the viewer showed it, and both backends agree on it.
TEST_F(Viewer, DecalDrawnOnTheTeapotRendersAsShown) {
  const std::string teapot = std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/teapot_strokes.json";
  if (!std::filesystem::exists(std::string(PLUMBAGO_MODELS_DIR) + "/teapot.obj"))
    GTEST_SKIP() << "../shared/models/teapot.obj is missing";
  view_script(teapot, R"([{"draw": {"kind": "decal", "points": [[58, 50], [70, 55], [82, 49], [96, 54]]}},
      {"save_strokes": ")" +
                          path("teapot.strokes.json") + R"("}, {"save": ")" + path("teapot.json") + R"("},
      {"screenshot": ")" + path("shown.png") +
                          R"("}])");
  testing::CliRun r = run("render " + path("teapot.json") + " -o " + path("render.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  testing::CliRun plain = run("render " + teapot + kSize + " -o " + path("plain.png"));
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_GT(png_difference(path("plain.png"), path("shown.png")), 0.25) << "the decal shows";
  EXPECT_LE(png_difference(path("shown.png"), path("render.png")), kTolerance);
  testing::CliRun c = run("compare " + path("teapot.json"));
  EXPECT_EQ(c.code, 0) << c.out << c.err;
}

// A decal that lies on no object is refused, naming the action, and nothing is saved.
TEST_F(Viewer, StrokeMissingTheModelIsRefusedAndNothingSaved) {
  testing::CliRun v = view(kTorusStrokes + kSize + " --no-ui --frames 1 --script " +
                           script(R"([{"draw": {"kind": "decal", "points": [[2, 2], [20, 6]]}},
                                      {"save_strokes": ")" +
                                  path("drawn.strokes.json") + R"("}])"));
  EXPECT_NE(v.code, 0);
  EXPECT_NE(v.err.find("action 0 (draw): the stroke misses the model"), std::string::npos) << v.err;
  EXPECT_FALSE(std::filesystem::exists(path("drawn.strokes.json")));
}

TEST_F(Viewer, StageViewShowsTheBufferAsDumpStagesDoes) {
  const std::string buffer = "edge_detect.contour_darkness";
  view_script(kMixed, R"([{"orbit": [25, 10]}, {"stage": ")" + buffer + R"("},
                          {"save": ")" +
                          path("saved.json") + R"("}, {"screenshot": ")" + path("stage.png") + R"("}])");
  testing::CliRun r = run("render " + path("saved.json") + " --dump-stages " + path("dump") + " -o " + path("r.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_LE(png_difference(path("stage.png"), path("dump/gpu." + buffer + ".png")), kTolerance);
  EXPECT_GT(png_difference(path("stage.png"), path("r.png")), 0.25) << "the buffer is shown, not the frame";
}

// The check reports, stage by stage, the numbers `plumbago compare` prints.
TEST_F(Viewer, ReferenceCheckReportsWhatCompareDoes) {
  const std::string scene = "builtin:torus --size 96x72";
  testing::CliRun v =
      view(scene + " --no-ui --frames 1 --script " + script(R"([{"check": ")" + path("check.json") + R"("}])"));
  ASSERT_EQ(v.code, 0) << v.err;
  testing::CliRun c = run("compare " + scene + " --json");
  ASSERT_EQ(c.code, 0) << c.err << c.out;
  nlohmann::json viewer = nlohmann::json::parse(testing::slurp(path("check.json")));
  nlohmann::json compare = nlohmann::json::parse(c.out);
  ASSERT_EQ(viewer["stages"].size(), compare["stages"].size());
  ASSERT_GT(viewer["stages"].size(), 3u);
  for (size_t i = 0; i < compare["stages"].size(); ++i) {
    const nlohmann::json &a = viewer["stages"][i], &b = compare["stages"][i];
    EXPECT_EQ(a["name"], b["name"]);
    EXPECT_EQ(a["pass"], b["pass"]) << b["name"];
    for (const char* metric : {"max_abs", "rmse", "over_tolerance"})
      EXPECT_NEAR(a[metric].get<double>(), b[metric].get<double>(), 1e-6) << b["name"] << " " << metric;
  }
  EXPECT_TRUE(viewer["pass"].get<bool>());
}

// The scene file edited on disk while the viewer runs: it reloads it, keeping the camera.
TEST_F(Viewer, ReloadsAnEditedSceneKeepingTheCamera) {
  std::filesystem::copy_file(kMixed, path("scene.json"));
  nlohmann::json edited = nlohmann::json::parse(testing::slurp(kMixed));
  edited["effects"] = {"contours", "sketchy"};
  std::ofstream(path("edited.json")) << edited.dump();
  std::string actions = R"([{"orbit": [30, 0]}, {"screenshot": ")" + path("before.png") + R"("}, {"reload": true},
                            {"save": ")" +
                        path("saved.json") + R"("},
                            {"screenshot": ")" +
                        path("after.png") + R"("}])";
  // The file is replaced (atomically, as editors save) once the first screenshot is written.
  std::string edit = "(for i in $(seq 600); do [ -e " + path("before.png") + " ] && break; sleep 0.1; done; mv " +
                     path("edited.json") + " " + path("scene.json") + ") & timeout 60 ";
  testing::CliRun v = view(path("scene.json") + kSize + " --no-ui --frames 1 --script " + script(actions), edit);
  ASSERT_EQ(v.code, 0) << v.err;
  Scene saved = load_scene(path("saved.json")), original = load_scene(kMixed);
  EXPECT_EQ(saved.effects, std::vector<std::string>({"contours", "sketchy"}));
  EXPECT_NE(saved.camera.eye, original.camera.eye) << "the orbited camera stays";
  testing::CliRun r = run("render " + path("saved.json") + " -o " + path("render.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(png_difference(path("before.png"), path("after.png")), 0.25);
  EXPECT_LE(png_difference(path("after.png"), path("render.png")), kTolerance);
}

TEST(ViewerScript, MalformedIsRefusedNamingTheAction) {
  testing::TempDir tmp;
  std::ofstream(tmp.path("bad.json")) << R"([{"orbit": [10, 5]}, {"set": {"edge.no_such_thing": 3}}])";
  testing::CliRun r = testing::run_cli("view --frames 1 --script " + tmp.path("bad.json"), tmp);
  EXPECT_EQ(r.code, 2) << r.err;
  if (PLUMBAGO_VIEWER) {
    EXPECT_NE(r.err.find(tmp.path("bad.json") + ": action 1 (set)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("edge.no_such_thing"), std::string::npos) << r.err;
  }
}

TEST_F(Viewer, PanelLeavesTheFrameWhole) {
  testing::CliRun v = view("builtin:torus --size 200x150 --frames 2 --screenshot " + path("window.png"));
  ASSERT_EQ(v.code, 0) << v.err;
  testing::CliRun r = run("render builtin:torus --size 200x150 -o " + path("render.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  Image window = read_image(path("window.png")), rendered = read_image(path("render.png"));
  ASSERT_GT(window.width, 200) << "the panel is beside the frame";
  // The frame sits 1:1 at the left, centered vertically in the window.
  Image frame(200, 150, 3);
  int y0 = (window.height - 150) / 2;
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 200; ++x)
      for (int c = 0; c < 3; ++c) frame.at(x, y, c) = window.at(x, y0 + y, c);
  ImageDiff d = compare_images(frame, rendered, kTolerance);
  EXPECT_LE(d.max_abs, kTolerance) << format_diff("frame in the window vs render", d);
}

// What the viewer's "Save scene" writes (save_scene), `render` draws exactly as the
// viewer drew the edited scene.
TEST(ViewerSavedScene, RendersWhatTheViewerDrew) {
  testing::TempDir tmp;
  Scene s = load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/sketchy_mixed.json");
  s.width = 240;
  s.height = 180;
  glm::vec3 center;
  float radius;
  scene_bounds(s, center, radius);
  OrbitCamera orbit(s.camera, center, radius);
  orbit.orbit(35, 20);
  orbit.zoom(0.8f);
  s.camera = orbit.camera();
  s.lights = default_lights(s.camera);
  s.params.set("edge.depth_scale", 14.25);
  s.objects[0].style = Style::Pencil;
  match_effects_to_styles(s);
  save_scene(s, tmp.path("saved.json"));
  testing::CliRun r = testing::run_cli("render " + tmp.path("saved.json") + " -o " + tmp.path("saved.png"), tmp);
  ASSERT_EQ(r.code, 0) << r.err;
  Image drawn = gpu::Renderer(s).render().color;
  write_image(drawn, tmp.path("drawn.png"));  // the same 8-bit rounding as the file's
  ImageDiff d = compare_images(read_image(tmp.path("saved.png")), read_image(tmp.path("drawn.png")), 0);
  EXPECT_EQ(d.max_abs, 0) << format_diff("render of the saved scene vs the edited scene", d);
}

TEST(ViewerWithoutDisplay, ExitsTwoSayingSo) {
  testing::TempDir tmp;
  testing::CliRun r =
      testing::run_cli("view --frames 1 --screenshot " + tmp.path("x.png"), tmp, "env -u DISPLAY -u WAYLAND_DISPLAY ");
  EXPECT_EQ(r.code, 2) << r.err;
  const char* says = PLUMBAGO_VIEWER ? "cannot open a window" : "built without the viewer";
  EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path("x.png")));
}

}  // namespace
}  // namespace plumbago

// `plumbago view` without a person: under Xvfb (xvfb-run) with Mesa's llvmpipe, the
// viewer draws N frames, writes what its window shows and exits; that must be what
// `plumbago render` writes for the same scene. Skipped, saying why, when the viewer was
// not built (no GLFW or Dear ImGui) or xvfb-run is missing (Debian package xvfb).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>

#include "common/image_compare.hpp"
#include "common/orbit.hpp"
#include "common/scene.hpp"
#include "gpu/pipeline.hpp"
#include "tests/cli_run.hpp"

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
  testing::CliRun view(const std::string& args) const {
    std::string server = std::to_string(100 + ::getpid() % 800);
    return run("view " + args, "xvfb-run -a -n " + server + " -s '-screen 0 1600x1200x24' ");
  }
  testing::CliRun run(const std::string& args, const std::string& wrapper = "") const {
    return testing::run_cli(args, tmp_, wrapper);
  }
  std::string path(const std::string& name) const { return tmp_.path(name); }

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
  testing::CliRun r = testing::run_cli("view --frames 1 --screenshot " + tmp.path("x.png"), tmp,
                                       "env -u DISPLAY -u WAYLAND_DISPLAY ");
  EXPECT_EQ(r.code, 2) << r.err;
  const char* says = PLUMBAGO_VIEWER ? "cannot open a window" : "built without the viewer";
  EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path("x.png")));
}

}  // namespace
}  // namespace plumbago

// Whole frames: pass selection by effect, determinism, numerical stability.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "common/core/passes.hpp"
#include "gpu/core/pipeline.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

std::vector<std::string> names(const Frame& f) {
  std::vector<std::string> out;
  for (const auto& p : f.ran) out.push_back(p.name);
  return out;
}

// `pass` ran, alone or fused with others into one GPU pass ("a+b").
bool ran(const Frame& f, const std::string& pass) {
  for (const auto& n : names(f))
    if (n == pass || n.rfind(pass + "+", 0) == 0 || n.find("+" + pass) != std::string::npos) return true;
  return false;
}

TEST(PassTable, ContoursNeedOnlyGBufferEdgesAndComposition) {
  EXPECT_EQ(passes_for({"contours"}),
            (std::vector<std::string>{"distortion", "contour_texture", "gbuffer", "edge_detect", "contour_light",
                                      "multi_contour", "compose"}));
  EXPECT_THROW(passes_for({"watercolor"}), std::invalid_argument);
}

class Frames : public testing::GlTest {};

TEST_F(Frames, ContoursOnlySceneRunsNoCurvaturePencilOrPaperWork) {
  Scene scene = testing::builtin_at("cad", 160, 120);
  scene.effects = {"contours"};
  for (const Frame& f : {reference::render(scene), gpu::Renderer(scene).render()}) {
    for (const auto& p : f.ran) {
      EXPECT_EQ(p.name.find("curvature"), std::string::npos);
      EXPECT_EQ(p.name.find("pencil"), std::string::npos);
      EXPECT_EQ(p.name.find("paper"), std::string::npos);
    }
    EXPECT_TRUE(ran(f, "gbuffer"));
    EXPECT_TRUE(ran(f, "edge_detect"));
  }
}

TEST_F(Frames, TwoRunsAreBitIdenticalOnEachBackend) {
  Scene scene = testing::builtin_at("torus", 200, 150);
  EXPECT_EQ(reference::render(scene).color.data, reference::render(scene).color.data);
  EXPECT_EQ(gpu::Renderer(scene).render().color.data, gpu::Renderer(scene).render().color.data);
}

// A frame writes only the G-buffer channels its stages read, leaves those read only on
// the objects uncleared on the background, clears the others only where the edge filter
// reads (gpu/scene/gbuffer.hpp), and composes only around the contours and objects, copying
// the blank page elsewhere (gpu/pencil/compose.hpp); a dump writes, clears and composes
// everything. The images may not differ, in either order (a clear region one pixel
// short, or a composition region without the contours' reach, fails here).
TEST_F(Frames, AFrameDrawsTheSameImageAsADump) {
  for (const std::string& name : builtin_scene_names()) {
    Scene scene = testing::builtin_at(name, 160, 120);
    scene.effects = {"contours", "interior", "crosshatch", "paper"};
    gpu::Renderer renderer(scene);
    Image frame = renderer.render().color;
    EXPECT_EQ(frame.data, renderer.render(FrameOptions{true}).color.data) << name;
    EXPECT_EQ(frame.data, renderer.render().color.data) << name;
  }
}

std::set<std::string> buffer_names(const Frame& f) {
  std::set<std::string> out;
  for (const auto& [name, img] : f.buffers) out.insert(name);
  return out;
}

// Both backends keep the same buffers, at least the G-buffer, the passes of the scene's
// effects and the color, each the window's size and finite. The built-in scenes with
// their own effects (contours) and with every pencil effect, and a sketchy torus crossed
// by an ordinary plane.
TEST_F(Frames, EveryBufferIsFiniteOnBothBackends) {
  FrameOptions keep{true};
  struct Case {
    std::string label;
    Scene scene;
    std::vector<std::string> expected;  // buffers the frame must have
  };
  std::vector<Case> cases;
  const std::vector<std::string> gbuffer = {"gbuffer.depth", "gbuffer.normal",  "gbuffer.face_normal",
                                            "gbuffer.bary",  "gbuffer.gouraud", "gbuffer.ids"};
  auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<std::string> contours =
      with(gbuffer, {"edge_detect.contour_darkness", "contour_light.lit_contour_darkness",
                     "multi_contour.contour_darkness", "compose.color"});
  for (const std::string& name : builtin_scene_names()) {
    Scene scene = testing::builtin_at(name, 160, 120);
    cases.push_back({name, scene, contours});
    scene.effects = {"contours", "interior", "crosshatch", "paper"};
    cases.push_back({name + " with every pencil effect", scene,
                     with(contours, {"gbuffer.theta_min", "gbuffer.theta_max", "interior_intensity.intensity",
                                     "pencil_interior.interior_darkness"})});
  }
  cases.push_back({"sketchy torus and a plane",
                   parse_scene(R"({"objects": [{"mesh": {"procedural": "torus"}, "style": "sketchy"},
                                               {"mesh": {"procedural": "plane"},
                                                "transform": [1.5,0,0,0, 0,1.3,-0.75,0, 0,0.75,1.3,0, 0,0,0,1]}],
                                  "resolution": [160, 120]})",
                               "test:sketchy and plane", "."),
                   with(gbuffer, {"edge_detect.contour_darkness", "sketchy_gbuffer.depth", "sketchy_maps.edge",
                                  "sketchy_maps.shade", "sketchy_composite.depth", "sketchy_composite.color"})});
  ASSERT_EQ(cases.size(), 2 * builtin_scene_names().size() + 1);
  for (const Case& c : cases) {
    Frame ref = reference::render(c.scene, keep), gpu = gpu::Renderer(c.scene).render(keep);
    EXPECT_EQ(buffer_names(ref), buffer_names(gpu)) << c.label << ": the backends keep different buffers";
    for (const Frame* f : {&ref, &gpu}) {
      const char* backend = f == &ref ? "reference" : "gpu";
      for (const std::string& name : c.expected)
        EXPECT_EQ(f->buffers.count(name), 1u) << c.label << " " << backend << ": no " << name;
      for (const auto& [buffer, img] : f->buffers) {
        EXPECT_EQ(img.width, c.scene.width) << c.label << " " << backend << " " << buffer;
        EXPECT_EQ(img.height, c.scene.height) << c.label << " " << backend << " " << buffer;
        EXPECT_FALSE(img.empty()) << c.label << " " << backend << " " << buffer;
        EXPECT_FALSE(has_non_finite(img)) << c.label << " " << backend << " " << buffer;
      }
    }
  }
}

// No effect: nothing runs, and the image is the blank page on both backends (the GPU's
// used to be its color target's uninitialized memory).
TEST_F(Frames, NoEffectDrawsTheBlankPage) {
  Scene scene = testing::builtin_at("torus", 64, 48);
  scene.effects = {};
  for (const Frame& f : {reference::render(scene), gpu::Renderer(scene).render()}) {
    ASSERT_EQ(f.color.pixels(), 64u * 48u);
    for (float v : f.color.data) ASSERT_EQ(v, 1.0f);
  }
}

TEST_F(Frames, ContoursAreDrawnWhereTheSilhouetteIs) {
  Scene scene = testing::builtin_at("sphere", 200, 200);
  for (const Frame& f : {reference::render(scene), gpu::Renderer(scene).render()}) {
    float darkest = 1, corner = f.color.at(0, 0, 0);
    for (size_t i = 0; i < f.color.pixels(); ++i) darkest = std::min(darkest, f.color.data[i * 3]);
    EXPECT_LT(darkest, 0.2f) << "no dark contour pixel";
    EXPECT_FLOAT_EQ(corner, 1.0f) << "background is not white paper";
    EXPECT_GT(f.color.at(100, 100, 0), 0.9f) << "the sphere's middle is not blank";
  }
}

}  // namespace
}  // namespace plumbago

// Whole frames: pass selection by effect, determinism, numerical stability.
#include <gtest/gtest.h>

#include <algorithm>

#include "common/passes.hpp"
#include "gpu/pipeline.hpp"
#include "reference/pipeline.hpp"
#include "tests/test_scenes.hpp"

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
  EXPECT_EQ(passes_for({"contours"}), (std::vector<std::string>{"distortion", "contour_texture", "gbuffer", "edge_detect",
                                                               "contour_light", "multi_contour", "compose"}));
  EXPECT_THROW(passes_for({"watercolor"}), std::invalid_argument);
}

TEST(PassTable, EveryPassComesAfterWhatItNeeds) {
  const auto& table = pass_table();
  for (size_t i = 0; i < table.size(); ++i)
    for (const auto& need : table[i].needs) {
      auto it = std::find_if(table.begin(), table.end(), [&](const PassDef& p) { return p.name == need; });
      ASSERT_NE(it, table.end()) << table[i].name << " needs unknown " << need;
      EXPECT_LT(size_t(it - table.begin()), i) << table[i].name << " before " << need;
    }
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
// reads (gpu/gbuffer.hpp), and composes only around the contours and objects, copying
// the blank page elsewhere (gpu/compose.hpp); a dump writes, clears and composes
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

TEST_F(Frames, EveryBufferIsFiniteOnBothBackends) {
  FrameOptions keep{true};
  for (const std::string& name : builtin_scene_names()) {
    Scene scene = testing::builtin_at(name, 160, 120);
    for (const Frame& f : {reference::render(scene, keep), gpu::Renderer(scene).render(keep)})
      for (const auto& [buffer, img] : f.buffers) EXPECT_FALSE(has_non_finite(img)) << name << " " << buffer;
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

// Sketchy drawing (Nienhaus & Döllner 2004): stage parity per style, occlusion against ordinary objects
// both ways on both backends, the effect's passes, and the scene rules.
#include <gtest/gtest.h>

#include "common/core/passes.hpp"
#include "common/sketchy/sketchy.hpp"
#include "gpu/core/pipeline.hpp"
#include "parity/parity.hpp"
#include "reference/core/pipeline.hpp"
#include "reference/scene/gbuffer.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const std::vector<std::string> kSketchyResults = {"sketchy_maps.edge", "sketchy_maps.shade", "sketchy_composite.color",
                                                  "sketchy_composite.depth"};
const std::vector<std::string> kObjectStyleResults = {"sketchy_enlarged.noise_coordinates", "sketchy_maps.edge",
                                                      "sketchy_maps.shade", "sketchy_composite.color",
                                                      "sketchy_composite.depth"};

// A sketchy torus alone (`style`), or crossed by an ordinary plane tilted 30 degrees
// through it, so that the torus is in front of the plane at the top and behind it below.
Scene sketchy_scene(const std::string& style, bool mixed, int width = 240, int height = 180) {
  std::string objects = R"({"mesh": {"procedural": "torus"}, "style": "sketchy", "color": [0.9, 0.35, 0.2]})";
  if (mixed)
    objects += R"(, {"mesh": {"procedural": "plane"}, "style": "pencil",
                     "transform": [1.5, 0, 0, 0,  0, 1.3, -0.75, 0,  0, 0.75, 1.3, 0,  0, 0, 0, 1]})";
  std::string json = R"({"objects": [)" + objects + R"(], "resolution": [)" + std::to_string(width) + ", " +
                     std::to_string(height) + R"(], "params": {"sketchy.style": ")" + style + R"("}})";
  return parse_scene(json, "test:sketchy", ".");
}

class SketchyParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SketchyParity, EveryStageMatchesTheReference) {
  Scene scene = sketchy_scene(GetParam(), false);
  auto results = run_parity(scene, {"sketchy_enlarged", "sketchy_maps", "sketchy_composite"});
  ASSERT_EQ(testing::names_of(results), (GetParam() == "object" ? kObjectStyleResults : kSketchyResults));
  for (const auto& r : results) {
    std::printf("[sketchy %s] %s\n", GetParam().c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name << ": " << r.note;
  }
}

INSTANTIATE_TEST_SUITE_P(Styles, SketchyParity, ::testing::Values("default", "repeat", "rough", "object"));

// A small sketchy square facing the camera, off to one side of a larger ordinary torus:
// the GPU draws the sketch's maps and composite only inside the rectangles of
// common/sketchy/sketchy.hpp, and for a square seen face-on its projected corners give its exact
// outline, so a margin too small shows in the parity.
Scene small_sketchy_scene(const std::string& style) {
  std::string json = R"({"objects": [
      {"mesh": {"procedural": "plane"}, "style": "sketchy",
       "transform": [0.3, 0, 0, 0,  0, 0.3, 0, 0,  0, 0, 0.3, 0,  0.9, 0.5, 0.2, 1]},
      {"mesh": {"procedural": "torus"}}],
    "camera": {"view_direction": [0, 0, 1]},
    "resolution": [240, 180], "params": {"sketchy.style": ")" +
                     style + R"("}})";
  return parse_scene(json, "test:small", ".");
}

TEST(SketchyBounds, CoveredRectHoldsEveryCoveredPixelAndClipsTheRest) {
  Scene scene = sketchy_objects(small_sketchy_scene("default"));
  PixelRect r = covered_rect(scene, scene.width, scene.height, 0);
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  int covered = 0;
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x)
      if (!g.background(x, y)) {
        ++covered;
        EXPECT_TRUE(x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) << x << "," << y;
      }
  EXPECT_GT(covered, 100);
  EXPECT_LT((r.x1 - r.x0) * (r.y1 - r.y0), scene.width * scene.height / 4);  // it does clip
  PixelRect grown = covered_rect(scene, scene.width, scene.height, 5);
  EXPECT_EQ(grown.x0, std::max(0, r.x0 - 5));
  EXPECT_EQ(grown.y1, std::min(scene.height, r.y1 + 5));
}

TEST(SketchyBounds, ABoxReachingBehindTheEyeGivesTheWholeWindow) {
  Scene scene = sketchy_objects(small_sketchy_scene("default"));
  scene.camera.eye = glm::vec3(0.9f, 0.5f, 0.5f);  // in front of the square, looking past it
  scene.camera.target = glm::vec3(0.9f, 0.5f, 1.5f);
  PixelRect r = covered_rect(scene, scene.width, scene.height, 0);
  EXPECT_EQ(r.x0, 0);
  EXPECT_EQ(r.y0, 0);
  EXPECT_EQ(r.x1, scene.width);
  EXPECT_EQ(r.y1, scene.height);
}

TEST(SketchyBounds, ReachBoundsTheOffsetsOfEveryStyle) {
  ParamSet params;
  auto p = params.get<SketchyParams>();
  float reach = sketch_reach(p);  // M_s = [[10, 3], [-3, 10]]: ||M_s||_F = 14.6, |(u, v)| <= 1.5 sqrt 2
  EXPECT_NEAR(reach, 1.5f * std::sqrt(2.0f) * std::sqrt(218.0f), 1e-4f);
  for (glm::vec2 uv : {glm::vec2(1.5f, 1.5f), glm::vec2(-0.5f, 1.5f), glm::vec2(1.5f, -0.5f)}) {
    EXPECT_LE(glm::length(shade_matrix(p) * uv), reach);
    for (int k = 0; k < 8; ++k) EXPECT_LE(glm::length(copy_matrix(p, k) * uv), reach + 1e-4f);
  }
  p.style = SketchyStyle::Rough;
  EXPECT_NEAR(sketch_reach(p), reach / 3, 1e-4f);
}

class SketchyBoundsParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SketchyBoundsParity, ClippedPassesMatchTheReferenceEverywhere) {
  auto results = run_parity(small_sketchy_scene(GetParam()), {"sketchy_maps", "sketchy_composite"});
  ASSERT_EQ(testing::names_of(results), kSketchyResults);
  for (const auto& r : results) {
    std::printf("[sketchy small %s] %s\n", GetParam().c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name << ": " << r.note;
  }
}

INSTANTIATE_TEST_SUITE_P(Styles, SketchyBoundsParity, ::testing::Values("default", "rough"));

// True when every pixel of the square of side 2r + 1 around p satisfies `ok`.
bool whole_square(glm::ivec2 p, int r, const std::function<bool(int, int)>& ok) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (!ok(p.x + dx, p.y + dy)) return false;
  return true;
}

// Probe pixels that the sketch's offsets (under r pixels) cannot carry across an
// occlusion boundary. In front: both objects cover the square around p and the sketchy
// one is nearer all over it. Behind: both cover p, and every sketchy depth the composite
// could fetch (shade within r, edge depth within r + 1) is farther than the ordinary
// object at p.
std::vector<glm::ivec2> pixels_where(const GBuffer& sketchy, const GBuffer& ordinary, bool sketchy_in_front, int r) {
  std::vector<glm::ivec2> out;
  int w = sketchy.depth.width, h = sketchy.depth.height, m = r + 1;
  for (int y = m; y < h - m; y += 3)
    for (int x = m; x < w - m; x += 3) {
      glm::ivec2 p(x, y);
      if (sketchy.background(x, y) || ordinary.background(x, y)) continue;
      float plane = ordinary.depth.at(x, y);
      bool probe = sketchy_in_front ? whole_square(p, r,
                                                   [&](int i, int j) {
                                                     return !sketchy.background(i, j) && !ordinary.background(i, j) &&
                                                            sketchy.depth.at(i, j) < ordinary.depth.at(i, j);
                                                   })
                                    : whole_square(p, m, [&](int i, int j) {
                                        return sketchy.background(i, j) || sketchy.depth.at(i, j) > plane;
                                      });
      if (probe) out.push_back(p);
    }
  return out;
}

float max_difference(const Image& a, const Image& b, glm::ivec2 p) {
  float d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.at(p.x, p.y, c) - b.at(p.x, p.y, c)));
  return d;
}

// Where the sketchy torus is in front, the frame is what the sketch draws alone; where
// the plane is, what the plane's own pipeline draws without the torus. The two differ at
// the probes, so a frame that drew either object everywhere would fail.
void expect_occlusion_both_ways(const std::function<Image(const Scene&)>& render, const char* backend) {
  Scene scene = sketchy_scene("default", true, 480, 360);
  scene.effects = {"contours", "interior", "sketchy"};
  Scene ordinary = ordinary_objects(scene), sketchy = sketchy_objects(scene);
  ordinary.effects = {"contours", "interior"};
  sketchy.effects = {"sketchy"};
  GBuffer gs = reference::trace_gbuffer(sketchy, scene.width, scene.height);
  GBuffer go = reference::trace_gbuffer(ordinary, scene.width, scene.height);
  const int reach = 16;  // > the largest offset of the default matrices, |M (u, v)| <= 10.4 * 1.5
  auto front = pixels_where(gs, go, true, reach), behind = pixels_where(gs, go, false, reach);
  std::printf("[occlusion %s] %zu probe pixels with the sketch in front, %zu behind\n", backend, front.size(),
              behind.size());
  ASSERT_GE(front.size(), 10u);
  ASSERT_GE(behind.size(), 10u);
  Image frame = render(scene), sketch_alone = render(sketchy), ordinary_alone = render(ordinary);
  const float tol = 2.0f / 255.0f;
  auto check = [&](const std::vector<glm::ivec2>& probes, const Image& shown, const Image& hidden, const char* where) {
    for (glm::ivec2 p : probes) {
      EXPECT_LE(max_difference(frame, shown, p), tol) << backend << " " << where << " at " << p.x << "," << p.y;
      EXPECT_GT(max_difference(shown, hidden, p), 0.1f) << backend << " " << where << " at " << p.x << "," << p.y;
    }
  };
  check(front, sketch_alone, ordinary_alone, "sketch in front");
  check(behind, ordinary_alone, sketch_alone, "sketch behind");
}

class SketchyOcclusion : public testing::GlTest {};

TEST_F(SketchyOcclusion, ReferenceShowsWhicheverIsNearer) {
  expect_occlusion_both_ways([](const Scene& s) { return reference::render(s).color; }, "reference");
}

TEST_F(SketchyOcclusion, GpuShowsWhicheverIsNearer) {
  expect_occlusion_both_ways([](const Scene& s) { return gpu::Renderer(s).render().color; }, "gpu");
}

TEST_F(SketchyOcclusion, MixedSceneEndToEnd) {
  Scene scene = sketchy_scene("default", true, 320, 240);
  scene.effects = {"contours", "interior", "sketchy"};
  auto r = run_parity(scene, {"end_to_end"}).at(0);
  std::printf("[end_to_end sketchy+pencil] within 2/255: %.2f%% of pixels; %s\n", 100 * (1 - r.diff.over_tolerance),
              format_diff(r.name, r.diff).c_str());
  EXPECT_TRUE(r.pass);
}

TEST(SketchyPasses, OnlyTheObjectStyleTracesTheEnlargedGeometry) {
  ParamSet params;
  auto passes = passes_for({"sketchy"}, params);
  EXPECT_EQ(passes,
            (std::vector<std::string>{"sketchy_noise", "sketchy_gbuffer", "sketchy_maps", "sketchy_composite"}));
  params.set("sketchy.style", "object");
  passes = passes_for({"sketchy"}, params);
  EXPECT_NE(std::find(passes.begin(), passes.end(), "sketchy_enlarged"), passes.end());
}

TEST(SketchyScene, SketchyObjectsTurnTheEffectOnAndAreDrawnOnlyByIt) {
  Scene alone = sketchy_scene("default", false);
  EXPECT_EQ(alone.effects, std::vector<std::string>{"sketchy"});  // nothing else is drawn
  Scene mixed = sketchy_scene("default", true);
  EXPECT_EQ(mixed.effects, (std::vector<std::string>{"contours", "sketchy"}));
  EXPECT_EQ(sketchy_objects(mixed).objects.size(), 1u);
  EXPECT_EQ(ordinary_objects(mixed).objects.size(), 1u);
}

TEST(SketchyScene, TheEffectWithoutSketchyObjectsIsRefusedNamingTheKey) {
  std::string json = R"({"mesh": {"procedural": "torus"}, "effects": ["contours", "sketchy"]})";
  try {
    parse_scene(json, "plain.json", ".");
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("plain.json: /effects"), std::string::npos) << e.what();
  }
}

TEST(SketchyGeometry, EnlargedMeshMovesEveryVertexAlongItsNormal) {
  Scene s = sketchy_scene("object", false);
  const Mesh& m = *s.objects[0].mesh;
  Mesh e = enlarged_mesh(m, 0.1f);
  ASSERT_EQ(e.positions.size(), m.positions.size());
  for (size_t v = 0; v < m.positions.size(); v += 97)
    EXPECT_NEAR(glm::length(e.positions[v] - m.positions[v] - 0.1f * m.normals[v]), 0.0f, 1e-6f);
  for (const glm::vec3& q : noise_coordinates(e)) EXPECT_LE(glm::length(q), 1.0f);
}

TEST(SketchyMatrices, CopiesTurnTheEdgeMatrixAndGoFromBlackToTheCopyInk) {
  ParamSet params;
  params.set("sketchy.edge_copies", 3.0);
  auto p = params.get<SketchyParams>();
  glm::vec2 u(1, 0);
  EXPECT_NEAR(glm::length(copy_matrix(p, 0) * u - edge_matrix(p) * u), 0.0f, 1e-6f);
  glm::vec2 turned = copy_matrix(p, 1) * u;  // M_e = 6 I turned by 90 degrees
  EXPECT_NEAR(turned.x, 0.0f, 1e-5f);
  EXPECT_NEAR(turned.y, 6.0f, 1e-5f);
  EXPECT_EQ(copy_ink(p, 0), glm::vec3(0.0f));
  EXPECT_EQ(copy_ink(p, 2), glm::vec3(p.copy_red, p.copy_green, p.copy_blue));
  glm::vec2 s = shade_matrix(p) * glm::vec2(0, 1);  // second column of [[10, 3], [-3, 10]]
  EXPECT_FLOAT_EQ(s.x, 3.0f);
  EXPECT_FLOAT_EQ(s.y, 10.0f);
}

class SketchyFrames : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

// Each style draws something, stays finite on both backends, and looks unlike the others.
TEST_P(SketchyFrames, StyleDrawsFiniteDistinctImages) {
  Scene scene = sketchy_scene(GetParam(), false);
  FrameOptions keep{true};
  for (const Frame& f : {reference::render(scene, keep), gpu::Renderer(scene).render(keep)}) {
    for (const auto& [name, img] : f.buffers) EXPECT_FALSE(has_non_finite(img)) << name;
    double ink = 0;
    for (float v : f.color.data) ink += 1.0 - v;
    EXPECT_GT(ink / double(f.color.data.size()), 0.01) << "nearly blank";
  }
  if (GetParam() == "default") return;
  Scene base = sketchy_scene("default", false);
  auto d = compare_images(reference::render(base).color, reference::render(scene).color, 2.0 / 255.0, nullptr);
  EXPECT_GT(d.over_tolerance, 0.02) << "looks like the default style";
}

INSTANTIATE_TEST_SUITE_P(Styles, SketchyFrames, ::testing::Values("default", "repeat", "rough", "object"));

}  // namespace
}  // namespace plumbago

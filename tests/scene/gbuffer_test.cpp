// G-buffer parity, raster (gpu/scene/gbuffer.cpp) vs ray tracing (reference/scene/gbuffer.cpp),
// docs/conventions.md: interior pixels agree within 1e-4 in depth and 1e-3 in normals; differences
// only in the one-pixel band along depth discontinuities, whose share is printed.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

#include "common/core/passes.hpp"
#include "common/curvature/curvature.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/scene/gbuffer.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

std::vector<StageParity> expect_gbuffer_parity(const Scene& scene, const std::string& label) {
  auto results = run_parity(scene, {"gbuffer"});
  EXPECT_EQ(testing::names_of(results), (std::vector<std::string>{"gbuffer.normal", "gbuffer.face_normal",
                                                                  "gbuffer.depth", "gbuffer.bary", "gbuffer.gouraud"}));
  for (const StageParity& r : results) {
    std::printf("[gbuffer %s] %s  [%s]\n", label.c_str(), format_diff(r.name, r.diff).c_str(), r.note.c_str());
    EXPECT_GT(r.diff.compared, scene.width * scene.height / 20)
        << r.name << ": too few interior pixels to mean anything";
    EXPECT_TRUE(r.pass) << r.name;
    EXPECT_FALSE(has_non_finite(r.gpu)) << r.name;
    EXPECT_FALSE(has_non_finite(r.reference)) << r.name;
  }
  return results;
}

class GBufferParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(GBufferParity, BuiltinScene) { expect_gbuffer_parity(testing::builtin_at(GetParam(), 400, 300), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Builtin, GBufferParity, ::testing::Values("torus", "sphere", "cad"));

TEST_F(GBufferParity, Fandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  expect_gbuffer_parity(testing::model_scene("fandisk.obj", 800, 800), "fandisk");
}

TEST_F(GBufferParity, StanfordBunny) {
  PLUMBAGO_REQUIRE_MODEL("stanford-bunny.obj");
  expect_gbuffer_parity(testing::model_scene("stanford-bunny.obj", 800, 800), "stanford-bunny");
}

// Views found by a random-view sweep where the edge of a sliver on a silhouette (the Ogre's
// loincloth over its body; the cow) passed within a subpixel of a pixel center, and the
// raster and the ray gave the pixel to different layers less than a depth discontinuity
// apart (up to 0.8 in Gouraud): the derived bound leaves such pixels out
// (reference/scene/gbuffer_bounds.cpp).
TEST_F(GBufferParity, ViewsWhereAnOccludingSliverEdgeMeetsAPixelCenter) {
  struct View {
    const char* model;
    const char* direction;
    const char* fov_deg;
  };
  const View views[] = {
      {"ogre.obj", "-0.7669840247205888, -0.15848876550715807, -0.5742686539818211", "28.09384931571795"},
      {"ogre.obj", "-0.6186311694192679, 0.46378843142870063, -0.7380658325667606", "39.31145371133501"},
      {"cow.obj", "-0.5948511731863824, -0.6607856936190832, 0.8114431998509803", "39.79970014027538"}};
  for (const View& v : views) {
    PLUMBAGO_REQUIRE_MODEL(v.model);
    std::string json = std::string(R"({"objects": [{"mesh": ")") + v.model +
                       R"(", "style": "strokes"}], "camera": {"view_direction": [)" + v.direction +
                       R"(], "fov_deg": )" + v.fov_deg + R"(}, "resolution": [400, 400], "effects": ["strokes"]})";
    expect_gbuffer_parity(parse_scene(json, std::string("test:") + v.model, PLUMBAGO_MODELS_DIR), v.model);
  }
}

// A polygon of n sides on the unit circle, triangulated as a fan from its first corner, as
// a mesh reader makes it: slivers a hundredth of a pixel wide.
Mesh polygon_fan(int n) {
  Mesh m;
  for (int k = 0; k < n; ++k) {
    double a = 2 * std::numbers::pi * k / n;
    m.positions.push_back({float(std::cos(a)), float(std::sin(a)), 0.0f});
  }
  for (int k = 1; k + 1 < n; ++k) m.triangles.push_back({0u, unsigned(k), unsigned(k + 1)});
  return m;
}

// n thin fins on one edge, the z axis, their tips around the unit circle: non-manifold,
// and many seen edge-on.
Mesh fan_of_fins(int n) {
  Mesh m;
  m.positions = {{0, 0, -1}, {0, 0, 1}};
  for (int k = 0; k < n; ++k) {
    double a = 2 * std::numbers::pi * k / n;
    m.positions.push_back({float(std::cos(a)), float(std::sin(a)), 0.0f});
    m.triangles.push_back({0u, 1u, unsigned(k + 2)});
  }
  return m;
}

// Slivers in the window: the raster's snapped corners move their barycentrics by up to
// 5 sqrt(2) / 32 px x longest edge / doubled area (reference/scene/gbuffer_bounds.cpp). Both
// shapes failed compare by the declared tolerances alone (the 100,000-gon's barycentrics by
// 0.034, the fins' normals by 0.029); each must pass within the derived bound, and need it.
TEST_F(GBufferParity, SliversAgreeWithinTheBoundTheirShapeDerives) {
  const std::pair<const char*, Scene> cases[] = {
      {"100000-gon", testing::one_stroke_object(polygon_fan(100000), {0.6f, -1.2f, 2.0f})},
      {"2000 fins", testing::one_stroke_object(fan_of_fins(2000), {2.4f, 1.0f, 1.4f})}};
  for (const auto& [label, scene] : cases) {
    size_t bounded = 0;
    for (const StageParity& r : expect_gbuffer_parity(scene, label)) bounded += r.bounded;
    EXPECT_GT(bounded, 0u) << label << ": no pixel needed the derived bound";
  }
}

// The raster G-buffer with and without culling the faces gpu/scene/gbuffer.cpp takes for hidden.
struct CulledAndNot {
  GBuffer culled, whole;
  int culled_objects = 0;
};

CulledAndNot render_culled_and_not(const Scene& scene) {
  gpu::GBufferTargets targets = gpu::make_gbuffer_targets(scene.width, scene.height, GBufferFormat::RGBA32F);
  gpu::GBufferPass pass(scene);
  CulledAndNot out;
  pass.render(scene, targets);
  out.culled = gpu::download_gbuffer(targets);
  out.culled_objects = pass.culled_objects();
  pass.set_culling(false);
  pass.render(scene, targets);
  out.whole = gpu::download_gbuffer(targets);
  EXPECT_EQ(pass.culled_objects(), 0);
  return out;
}

// Culling may change which of two faces wins a pixel only where their depths tie (along
// silhouettes, where a back face meets the front face it folds into); it never uncovers
// or covers a pixel. Returns how many pixels changed face.
int expect_same_surface(const CulledAndNot& r, const std::string& label) {
  int changed = 0, uncovered_or_covered = 0, not_tied = 0;
  const GBuffer &a = r.culled, &b = r.whole;
  for (int y = 0; y < a.ids.height; ++y)
    for (int x = 0; x < a.ids.width; ++x) {
      uncovered_or_covered += a.ids.at(x, y, 0) != b.ids.at(x, y, 0);
      if (a.ids.at(x, y, 1) == b.ids.at(x, y, 1)) continue;
      ++changed;
      not_tied += std::abs(a.depth.at(x, y) - b.depth.at(x, y)) > 1e-4f * b.depth.at(x, y);
    }
  std::printf("[gbuffer culling %s] %d culled object(s); %d of %d pixels show another face (depth tie)\n",
              label.c_str(), r.culled_objects, changed, a.ids.width * a.ids.height);
  EXPECT_EQ(uncovered_or_covered, 0) << label << ": pixels whose object changed";
  EXPECT_EQ(not_tied, 0) << label << ": pixels that show another face at another depth";
  EXPECT_LE(changed, a.ids.width * a.ids.height / 1000) << label;
  return changed;
}

Scene builtin_with_mesh(const std::string& name, Mesh mesh) {
  Scene s = testing::builtin_at(name, 400, 300);
  s.objects.at(0).mesh = std::make_shared<const Mesh>(std::move(mesh));
  return s;
}

using GBufferCulling = testing::GlTest;

TEST_F(GBufferCulling, ClosedObjectsSeenFromOutsideLoseOnlyHiddenFaces) {
  for (const char* name : {"sphere", "torus", "cad"}) {
    CulledAndNot r = render_culled_and_not(testing::builtin_at(name, 400, 300));
    EXPECT_EQ(r.culled_objects, 1) << name;
    expect_same_surface(r, name);
  }
  // Triangles turning clockwise seen from outside (negative volume): the other faces hide.
  Scene inside_out = testing::builtin_at("sphere", 400, 300);
  Mesh flipped = *inside_out.objects[0].mesh;
  for (glm::uvec3& t : flipped.triangles) std::swap(t[1], t[2]);
  CulledAndNot r = render_culled_and_not(builtin_with_mesh("sphere", flipped));
  EXPECT_EQ(r.culled_objects, 1);
  expect_same_surface(r, "sphere, clockwise triangles");
  // A mirroring transform turns counter-clockwise triangles clockwise in the world.
  Scene mirrored = testing::builtin_at("torus", 400, 300);
  mirrored.objects[0].transform = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1)) * mirrored.objects[0].transform;
  r = render_culled_and_not(mirrored);
  EXPECT_EQ(r.culled_objects, 1);
  expect_same_surface(r, "torus, mirrored");
}

TEST_F(GBufferCulling, Fandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  CulledAndNot r = render_culled_and_not(testing::model_scene("fandisk.obj", 800, 800));
  EXPECT_EQ(r.culled_objects, 1);
  expect_same_surface(r, "fandisk");
}

TEST_F(GBufferCulling, NothingIsCulledWhereTheInsideCanShow) {
  // The camera inside a closed sphere: every face it sees is a back face.
  Scene inside = testing::builtin_at("sphere", 400, 300);
  inside.camera.eye = inside.camera.target + 0.1f * (inside.camera.eye - inside.camera.target) /
                                                 glm::length(inside.camera.eye - inside.camera.target);
  inside.camera.near = 0.01f;
  CulledAndNot r = render_culled_and_not(inside);
  EXPECT_EQ(r.culled_objects, 0);
  EXPECT_EQ(expect_same_surface(r, "camera inside the sphere"), 0);
  // An open mesh: the sphere without one triangle.
  Mesh open = *testing::builtin_at("sphere", 400, 300).objects[0].mesh;
  open.triangles.pop_back();
  r = render_culled_and_not(builtin_with_mesh("sphere", open));
  EXPECT_EQ(r.culled_objects, 0);
}

// Renders the sphere, then the same sphere from a camera moved sideways, into the same
// targets: the pixels the first render covered and the second does not must hold the
// background values (docs/stages.md, gbuffer) again. Returns how many such pixels there were.
int expect_second_render_leaves_no_trace(const gpu::GBufferChannels& channels, const std::string& label) {
  Scene scene = testing::builtin_at("sphere", 200, 150);
  gpu::GBufferTargets targets = gpu::make_gbuffer_targets(scene.width, scene.height, GBufferFormat::RGBA32F);
  gpu::GBufferPass pass(scene);
  pass.render(scene, targets, channels);
  ImageU32 first_ids = gpu::download_texture_u32(targets.ids, 2);
  glm::vec3 side = glm::normalize(glm::cross(scene.camera.forward(), scene.camera.up));
  float shift = 0.4f * glm::length(scene.camera.eye - scene.camera.target);
  scene.camera.eye += shift * side;
  scene.camera.target += shift * side;
  pass.render(scene, targets, channels);
  GBuffer g = gpu::download_gbuffer(targets);
  Image normal = gpu::download_texture(targets.normal, 4), face_normal = gpu::download_texture(targets.face_normal, 4);
  const PixelRect& r = channels.read_region;
  int uncovered = 0, wrong = 0;
  for (int y = std::max(r.y0, 0); y < std::min(r.y1, scene.height); ++y)
    for (int x = std::max(r.x0, 0); x < std::min(r.x1, scene.width); ++x) {
      if (g.ids.at(x, y, 0) != 0) continue;
      uncovered += first_ids.at(x, y, 0) != 0;
      for (int c = 0; c < 3; ++c)
        wrong += (channels.normal && normal.at(x, y, c) != 0) + (channels.face_normal && face_normal.at(x, y, c) != 0);
      wrong +=
          (channels.normal && normal.at(x, y, 3) != g.far) + (channels.face_normal && face_normal.at(x, y, 3) != g.far);
      if (!channels.object_only_background) continue;
      for (int c = 0; c < 3; ++c)
        wrong += (g.bary.at(x, y, c) != 0) + (g.theta_min.at(x, y, c) != 0) + (g.theta_max.at(x, y, c) != 0);
      wrong += (g.depth.at(x, y) != g.far) + (g.gouraud.at(x, y) != 1.0f);
    }
  std::printf("[gbuffer background %s] %d pixels covered only by the first render\n", label.c_str(), uncovered);
  EXPECT_GT(uncovered, 100) << label << ": the camera did not move the sphere off enough pixels to test";
  EXPECT_EQ(wrong, 0) << label << ": channel values of the first render left on the background";
  return uncovered;
}

using GBufferBackground = testing::GlTest;

TEST_F(GBufferBackground, ASecondRenderLeavesNoTraceOfTheFirstOnTheBackground) {
  expect_second_render_leaves_no_trace(gpu::GBufferChannels{}, "every channel, whole window (a dump)");
  Scene scene = testing::builtin_at("sphere", 200, 150);
  scene.effects = {"contours", "interior", "crosshatch", "paper"};
  gpu::GBufferChannels frame = gpu::Renderer(scene).frame_channels("gbuffer");
  frame.read_region = {0, 0, scene.width, scene.height};  // the moved sphere's region is elsewhere
  expect_second_render_leaves_no_trace(frame, "a frame's channels");
}

// A flat grid of more vertices and triangles than one dispatch reaches, 65535 groups of 64
// (GL's least maximum per dimension, which llvmpipe keeps), with one stroke direction
// everywhere (Lee et al. 2006, §5.3): the corner angles go in chunks, so the last
// triangles' records hold their angles as the first's do. (A 4.5M-triangle mesh drawn with
// crosshatching failed with GL_INVALID_VALUE in glDispatchCompute before.)
using GBufferAngles = testing::GlTest;

TEST_F(GBufferAngles, EveryTriangleOfAMeshBeyondOneDispatchGetsItsAngles) {
  const uint32_t n = 1450;  // 2(n - 1)^2 = 4,199,202 triangles, 2,102,500 vertices
  Mesh grid;
  grid.name = "test:grid";
  for (uint32_t r = 0; r < n; ++r)
    for (uint32_t c = 0; c < n; ++c) grid.positions.push_back({2.0f * c / (n - 1) - 1, 2.0f * r / (n - 1) - 1, 0});
  grid.normals.assign(grid.positions.size(), glm::vec3(0, 0, 1));
  for (uint32_t r = 0; r + 1 < n; ++r)
    for (uint32_t c = 0; c + 1 < n; ++c) {
      uint32_t i = r * n + c;
      grid.triangles.push_back({i, i + 1, i + n});
      grid.triangles.push_back({i + 1, i + n + 1, i + n});
    }
  const size_t triangles = grid.triangles.size(), vertices = grid.positions.size();
  ASSERT_GT(triangles, 64u * 65535u);
  Curvature c{std::vector<float>(vertices, 0.0f), std::vector<float>(vertices, 1.0f),
              std::vector<glm::vec3>(vertices, glm::vec3(0, 0, 1)),
              std::vector<glm::vec3>(vertices, glm::normalize(glm::vec3(1, 2, 0))),
              std::vector<glm::vec3>(vertices, glm::normalize(glm::vec3(-2, 1, 0)))};
  Scene scene = builtin_with_mesh("sphere", std::move(grid));
  scene.camera.eye = {0.3f, -1.5f, 2.5f};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  gpu::GBufferTargets targets = gpu::make_gbuffer_targets(scene.width, scene.height, GBufferFormat::RGBA32F);
  gpu::GBufferPass pass(scene, {c});
  pass.render(scene, targets);
  const size_t checked = 100000;  // the first and the last triangles' records: vec4 theta_min, vec4 theta_max
  std::vector<glm::vec4> first(2 * checked), last(2 * checked);
  gpu::read_buffer(pass.triangle_angles().angles, first.data(), first.size() * sizeof(glm::vec4));
  gpu::read_buffer(pass.triangle_angles().angles, last.data(), last.size() * sizeof(glm::vec4),
                   2 * (triangles - checked) * sizeof(glm::vec4));
  size_t unset = 0;
  for (const std::vector<glm::vec4>* records : {&first, &last})
    for (const glm::vec4& r : *records)
      for (int k = 0; k < 3; ++k) unset += !(std::isfinite(r[k]) && r[k] != 0.0f);
  EXPECT_EQ(unset, 0u) << "corner angles left at 0 or not finite";
}

}  // namespace
}  // namespace plumbago

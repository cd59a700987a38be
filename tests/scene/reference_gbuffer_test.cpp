// The ray-traced G-buffer (reference/scene/gbuffer.cpp) on hand-made scenes with known answers:
// depth, barycentrics, normals, ids, background values, edge cases, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "common/mesh/procedural.hpp"
#include "reference/scene/gbuffer.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

Scene scene_of(std::vector<SceneObject> objects, Camera camera, int width, int height) {
  Scene s;
  s.source = "test:reference_gbuffer";
  s.objects = std::move(objects);
  s.camera = camera;
  s.width = width;
  s.height = height;
  return s;
}

SceneObject object_of(Mesh mesh, bool flat = false) {
  SceneObject o;
  o.mesh = std::make_shared<const Mesh>(std::move(mesh));
  o.flat = flat;
  return o;
}

// A quad of two triangles (0,1,2) and (0,2,3) with corners c0..c3, counter-clockwise seen
// from the side its normals point to; vertex normals `normals` (face normal if empty).
Mesh quad(glm::vec3 c0, glm::vec3 c1, glm::vec3 c2, glm::vec3 c3, std::vector<glm::vec3> normals = {}) {
  Mesh m;
  m.name = "test:quad";
  m.positions = {c0, c1, c2, c3};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  if (normals.empty()) normals.assign(4, glm::normalize(glm::cross(c1 - c0, c2 - c0)));
  m.normals = std::move(normals);
  return m;
}

// A camera looking from `eye` at `target`, unit distances, near/far well outside the scenes.
Camera camera_at(glm::vec3 eye, glm::vec3 target) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.near = 0.5f;
  c.far = 50.0f;
  return c;
}

glm::vec3 get3(const Image& img, int x, int y) { return {img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)}; }

size_t covered_pixels(const GBuffer& g) {
  size_t n = 0;
  for (int y = 0; y < g.ids.height; ++y)
    for (int x = 0; x < g.ids.width; ++x) n += !g.background(x, y);
  return n;
}

void expect_all_finite(const GBuffer& g) {
  for (const Image* img : {&g.normal, &g.face_normal, &g.depth, &g.bary, &g.gouraud, &g.theta_min, &g.theta_max})
    EXPECT_FALSE(has_non_finite(*img));
}

// The hit point sum_k w_k p_k of each covered pixel lies on the pixel-center ray at the
// stored depth; the weights sum to 1 and are never far outside the triangle.
void expect_barycentrics_reproduce_hits(const Scene& scene, const GBuffer& g) {
  std::vector<WorldObject> world = world_geometry(scene);
  PrimaryRays rays(scene.camera, g.depth.width, g.depth.height);
  glm::vec3 forward = scene.camera.forward();
  for (int y = 0; y < g.depth.height; ++y)
    for (int x = 0; x < g.depth.width; ++x) {
      if (g.background(x, y)) continue;
      const WorldObject& obj = world.at(g.ids.at(x, y, 0) - 1);
      const glm::uvec3& tri = obj.triangles.at(g.ids.at(x, y, 1));
      glm::vec3 w = get3(g.bary, x, y);
      ASSERT_NEAR(w[0] + w[1] + w[2], 1.0f, 1e-6f) << x << "," << y;
      for (int k = 0; k < 3; ++k) ASSERT_GT(w[k], -1e-5f) << x << "," << y;
      glm::vec3 hit = w[0] * obj.positions[tri[0]] + w[1] * obj.positions[tri[1]] + w[2] * obj.positions[tri[2]];
      glm::vec3 dir = rays.direction(float(x) + 0.5f, float(y) + 0.5f);
      glm::vec3 on_ray = scene.camera.eye + dir * (g.depth.at(x, y) / glm::dot(dir, forward));
      ASSERT_LT(glm::length(hit - on_ray), 1e-4f) << x << "," << y;
      float gouraud = w[0] * obj.gouraud[tri[0]] + w[1] * obj.gouraud[tri[1]] + w[2] * obj.gouraud[tri[2]];
      ASSERT_NEAR(g.gouraud.at(x, y), gouraud, 1e-6f) << x << "," << y;
    }
}

// A square of half-size `half` through `center`, perpendicular to the camera's view axis,
// counter-clockwise seen from the camera.
Mesh square_facing(const Camera& cam, glm::vec3 center, float half) {
  glm::mat3 to_world = glm::transpose(glm::mat3(cam.view()));  // columns: right, up, back
  glm::vec3 r = to_world[0] * half, u = to_world[1] * half;
  return quad(center - r - u, center + r - u, center + r + u, center - r + u);
}

TEST(ReferenceGBuffer, PlaneAtKnownDistanceHasExactDepthEverywhere) {
  Camera cam = camera_at({3, 2, 4}, {0.5f, -0.25f, 0});  // off-axis: depth is not the ray length
  float distance = glm::length(cam.target - cam.eye);
  Scene scene = scene_of({object_of(square_facing(cam, cam.target, 20))}, cam, 61, 47);
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  ASSERT_EQ(covered_pixels(g), g.ids.pixels());  // the square fills the view
  for (int y = 0; y < g.depth.height; ++y)
    for (int x = 0; x < g.depth.width; ++x) {
      EXPECT_NEAR(g.depth.at(x, y), distance, 1e-5f) << x << "," << y;
      EXPECT_EQ(g.ids.at(x, y, 0), 1u);
      EXPECT_LT(g.ids.at(x, y, 1), 2u);
      EXPECT_NEAR(glm::distance(get3(g.face_normal, x, y), glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::distance(get3(g.normal, x, y), glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
    }
  EXPECT_EQ(g.near, cam.near);
  EXPECT_EQ(g.far, cam.far);
  expect_barycentrics_reproduce_hits(scene, g);
  expect_all_finite(g);
}

TEST(ReferenceGBuffer, BackgroundPixelsHoldTheDocumentedValues) {
  Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  Scene scene =
      scene_of({object_of(quad({-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}))}, cam, 40, 30);
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  size_t covered = covered_pixels(g);
  ASSERT_GT(covered, 0u);
  ASSERT_LT(covered, g.ids.pixels() / 2);
  for (int y = 0; y < g.depth.height; ++y)
    for (int x = 0; x < g.depth.width; ++x) {
      if (!g.background(x, y)) continue;
      EXPECT_EQ(get3(g.normal, x, y), glm::vec3(0));
      EXPECT_EQ(get3(g.face_normal, x, y), glm::vec3(0));
      EXPECT_EQ(get3(g.bary, x, y), glm::vec3(0));
      EXPECT_EQ(g.depth.at(x, y), cam.far);
      EXPECT_EQ(g.gouraud.at(x, y), 1.0f);
      EXPECT_EQ(g.ids.at(x, y, 1), 0u);
      EXPECT_EQ(get3(g.theta_min, x, y), glm::vec3(0));
      EXPECT_EQ(get3(g.theta_max, x, y), glm::vec3(0));
    }
  EXPECT_TRUE(g.background(0, 0));
  EXPECT_FALSE(g.background(20, 15));
}

TEST(ReferenceGBuffer, ShadingNormalsInterpolateAndFlatObjectsUseTheFaceNormal) {
  Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  // Vertex normals tilted outwards, as on a dome: the shading normal varies, the face does not.
  std::vector<glm::vec3> normals = {glm::normalize(glm::vec3(-1, -1, 2)), glm::normalize(glm::vec3(1, -1, 2)),
                                    glm::normalize(glm::vec3(1, 1, 2)), glm::normalize(glm::vec3(-1, 1, 2))};
  Mesh m = quad({-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}, normals);
  for (bool flat : {false, true}) {
    Scene scene = scene_of({object_of(m, flat)}, cam, 33, 33);
    GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
    ASSERT_EQ(covered_pixels(g), g.ids.pixels());
    for (int y = 0; y < 33; ++y)
      for (int x = 0; x < 33; ++x) {
        glm::vec3 n = get3(g.normal, x, y), w = get3(g.bary, x, y);
        const glm::uvec3& tri = m.triangles[g.ids.at(x, y, 1)];
        glm::vec3 expected = flat ? glm::vec3(0, 0, 1)
                                  : glm::normalize(w[0] * normals[tri[0]] + w[1] * normals[tri[1]] +
                                                   w[2] * normals[tri[2]]);  // view = world here
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
        EXPECT_LT(glm::distance(n, expected), 1e-5f) << x << "," << y << (flat ? " flat" : "");
        EXPECT_LT(glm::distance(get3(g.face_normal, x, y), glm::vec3(0, 0, 1)), 1e-6f);
      }
    // Left of center the normals lean left (-x), right of center right.
    if (!flat) {
      EXPECT_LT(g.normal.at(2, 16, 0), -0.1f);
      EXPECT_GT(g.normal.at(30, 16, 0), 0.1f);
    }
    expect_barycentrics_reproduce_hits(scene, g);
  }
}

TEST(ReferenceGBuffer, BackFacesKeepTheMeshOrientation) {
  Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  // Clockwise seen from the camera: its normals point away (-z).
  Scene scene = scene_of({object_of(quad({-4, -4, 0}, {-4, 4, 0}, {4, 4, 0}, {4, -4, 0}))}, cam, 16, 16);
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  ASSERT_EQ(covered_pixels(g), g.ids.pixels());
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      EXPECT_LT(glm::distance(get3(g.face_normal, x, y), glm::vec3(0, 0, -1)), 1e-6f);
      EXPECT_LT(glm::distance(get3(g.normal, x, y), glm::vec3(0, 0, -1)), 1e-6f);
    }
}

TEST(ReferenceGBuffer, IdsNameTheNearestObjectAndItsTriangle) {
  Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  Mesh back = quad({-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1});
  Mesh front = quad({0, -4, 1}, {4, -4, 1}, {4, 4, 1}, {0, 4, 1});  // covers the right half, closer
  Scene scene = scene_of({object_of(back), object_of(front)}, cam, 32, 32);
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  PrimaryRays rays(cam, 32, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      bool right = x >= 16;
      EXPECT_EQ(g.ids.at(x, y, 0), right ? 2u : 1u) << x << "," << y;
      EXPECT_NEAR(g.depth.at(x, y), right ? 4.0f : 6.0f, 1e-5f);
      // Triangle 0 = (c0, c1, c2) lies below the diagonal c0-c2.
      glm::vec2 lo = right ? glm::vec2(0, -4) : glm::vec2(-4, -4), hi(4, 4);
      glm::vec3 dir = rays.direction(x + 0.5f, y + 0.5f);
      glm::vec3 p = cam.eye + dir * (g.depth.at(x, y) / -dir.z);
      float side = (p.x - lo.x) * (hi.y - lo.y) - (p.y - lo.y) * (hi.x - lo.x);  // > 0: below the diagonal
      if (std::abs(side) > 1e-3f) {
        EXPECT_EQ(g.ids.at(x, y, 1), side > 0 ? 0u : 1u) << x << "," << y;
      }
    }
  expect_barycentrics_reproduce_hits(scene, g);
}

TEST(ReferenceGBuffer, PixelCentersOnSharedEdgesAreCoveredOnceAndDeterministically) {
  Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  // Two objects meeting at x = 0, which the middle column of an odd-width image hits
  // exactly; each quad's diagonal passes through pixel centers on the image diagonal.
  Mesh left = quad({-4, -4, 0}, {0, -4, 0}, {0, 4, 0}, {-4, 4, 0});
  Mesh right = quad({0, -4, 0}, {4, -4, 0}, {4, 4, 0}, {0, 4, 0});
  Scene scene = scene_of({object_of(left), object_of(right)}, cam, 31, 31);
  GBuffer a = reference::trace_gbuffer(scene, scene.width, scene.height);
  GBuffer b = reference::trace_gbuffer(scene, scene.width, scene.height);
  EXPECT_EQ(covered_pixels(a), a.ids.pixels()) << "a ray through a shared edge went through the surface";
  EXPECT_EQ(a.ids.data, b.ids.data);
  EXPECT_EQ(a.bary.data, b.bary.data);
  for (int y = 0; y < 31; ++y) EXPECT_NEAR(a.depth.at(15, y), 5.0f, 1e-5f);
  expect_barycentrics_reproduce_hits(scene, a);
}

TEST(ReferenceGBuffer, SphereNormalsAreUnitAndFaceTheCamera) {
  Camera cam = camera_at({0.3f, 0.4f, 4}, {0, 0, 0});
  Scene scene = scene_of({object_of(make_procedural("sphere"))}, cam, 96, 80);
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  ASSERT_GT(covered_pixels(g), g.ids.pixels() / 10);
  glm::mat4 view = cam.view();
  glm::vec3 center_view(view * glm::vec4(0, 0, 0, 1));
  PrimaryRays rays(cam, scene.width, scene.height);
  for (int y = 0; y < g.depth.height; ++y)
    for (int x = 0; x < g.depth.width; ++x) {
      if (g.background(x, y)) continue;
      glm::vec3 n = get3(g.normal, x, y), fn = get3(g.face_normal, x, y);
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      EXPECT_NEAR(glm::length(fn), 1.0f, 1e-5f);
      glm::vec3 dir = rays.direction(x + 0.5f, y + 0.5f);
      glm::vec3 hit_view(view * glm::vec4(cam.eye + dir * (g.depth.at(x, y) / glm::dot(dir, cam.forward())), 1));
      EXPECT_NEAR(-hit_view.z, g.depth.at(x, y), 1e-5f);  // depth = -z_view
      EXPECT_LT(glm::dot(fn, hit_view), 0.0f) << x << "," << y << ": a visible outside face faces the camera";
      // On a fine sphere the shading normal is close to the analytic one.
      EXPECT_GT(glm::dot(n, glm::normalize(hit_view - center_view)), 0.99f) << x << "," << y;
    }
  expect_barycentrics_reproduce_hits(scene, g);
  expect_all_finite(g);
}

TEST(ReferenceGBuffer, DegenerateTrianglesGiveNoNaN) {
  Camera cam = camera_at({0, 0, 5}, {0, 0, 0});
  Mesh m = quad({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
  m.positions.push_back({0.2f, 0.2f, 0.5f});
  m.normals.push_back({0, 0, 1});
  m.triangles.push_back({4, 4, 4});  // zero area, in front of the quad
  m.triangles.push_back({0, 2, 4});  // a real triangle rising towards the camera
  m.triangles.push_back({1, 1, 3});  // zero area along the quad's diagonal
  Scene scene = scene_of({object_of(m)}, cam, 50, 50);
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height);
  ASSERT_GT(covered_pixels(g), 0u);
  expect_all_finite(g);
  expect_barycentrics_reproduce_hits(scene, g);
}

// Threads and the BVH build may differ between runs; the image may not.
void expect_two_runs_bit_identical(const Scene& scene) {
  GBuffer a = reference::trace_gbuffer(scene, scene.width, scene.height);
  GBuffer b = reference::trace_gbuffer(scene, scene.width, scene.height);
  ASSERT_GT(covered_pixels(a), 0u);
  EXPECT_EQ(a.normal.data, b.normal.data);
  EXPECT_EQ(a.face_normal.data, b.face_normal.data);
  EXPECT_EQ(a.depth.data, b.depth.data);
  EXPECT_EQ(a.ids.data, b.ids.data);
  EXPECT_EQ(a.bary.data, b.bary.data);
  EXPECT_EQ(a.gouraud.data, b.gouraud.data);
  expect_all_finite(a);
}

TEST(ReferenceGBuffer, TwoRunsAreBitIdentical) {
  Camera cam = camera_at({1, 2, 3}, {0, 0, 0});
  Scene scene =
      scene_of({object_of(make_procedural("torus")), object_of(make_procedural("sphere"), true)}, cam, 123, 77);
  scene.objects[1].transform = glm::mat4(0.4f);
  scene.objects[1].transform[3] = glm::vec4(0.2f, 0.5f, 0.3f, 1);
  expect_two_runs_bit_identical(scene);
}

TEST(ReferenceGBuffer, TwoRunsOnAModelAreBitIdentical) {
  PLUMBAGO_REQUIRE_MODEL("stanford-bunny.obj");
  expect_two_runs_bit_identical(testing::model_scene("stanford-bunny.obj", 400, 400));
}

}  // namespace
}  // namespace plumbago

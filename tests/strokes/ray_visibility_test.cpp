// The ray truth of stroke visibility (reference/strokes/ray_visibility.hpp): a line on the mesh
// passes over the triangles it lies on and nothing else; a silhouette over hits within its
// own facets' reach.
#include "reference/strokes/ray_visibility.hpp"

#include <gtest/gtest.h>

#include "common/mesh/procedural.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// The unit cube [-0.5, 0.5]^3 seen from (3, 2.5, 4): the faces +x, +y and +z face the eye.
Scene cube_scene() { return testing::one_stroke_object(make_procedural("cube"), {3.0f, 2.5f, 4.0f}); }

// A square of side 0.4 at z = 0.5 + gap, centered on the cube's +z face, facing +z.
Mesh square_above_face(float gap) {
  Mesh m;
  m.name = "test:square";
  float z = 0.5f + gap;
  m.positions = {{-0.2f, -0.2f, z}, {0.2f, -0.2f, z}, {0.2f, 0.2f, z}, {-0.2f, 0.2f, z}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  compute_normals(m);
  return m;
}

std::vector<uint8_t> on_surface(const Scene& scene, const std::vector<glm::dvec3>& points) {
  std::vector<reference::RayTarget> targets;
  for (const glm::dvec3& p : points) targets.push_back({p, 0.0});
  return reference::visible_by_rays(scene, targets);
}

TEST(RayVisibility, ALineOnTheMeshPassesTheTrianglesItLiesOn) {
  // The crease between +x and +y, a corner of three front faces (six triangles meet there),
  // the middle of the +z face (on the diagonal of its two triangles): all seen.
  std::vector<uint8_t> seen = on_surface(cube_scene(), {{0.5, 0.5, 0.1}, {0.5, 0.5, 0.5}, {0.0, 0.0, 0.5}});
  EXPECT_EQ(seen, std::vector<uint8_t>({1, 1, 1}));
}

TEST(RayVisibility, ACreaseBehindItsOwnObjectIsHiddenHoweverNearItsFaces) {
  // The crease between -x and -y, behind the cube. The ray enters the cube through the +z
  // face 0.62 units before it, within two edges (2) of it: a silhouette's rule passes that
  // hit as the point's own facets; a crease's does not.
  Scene scene = cube_scene();
  glm::dvec3 back(-0.5, -0.5, 0.1);
  EXPECT_EQ(on_surface(scene, {back}), std::vector<uint8_t>({0}));
  EXPECT_EQ(reference::visible_by_rays(scene, {{back, 2.0}}), std::vector<uint8_t>({1}));
}

TEST(RayVisibility, AnOccluderAThousandthAboveTheSurfaceHidesAPointOnIt) {
  Scene scene = cube_scene();
  scene.objects.push_back({std::make_shared<const Mesh>(square_above_face(1e-3f))});
  // The middle of the +z face under the square, and a point of the face beside it.
  EXPECT_EQ(on_surface(scene, {{0.0, 0.0, 0.5}, {-0.4, 0.4, 0.5}}), std::vector<uint8_t>({0, 1}));
}

}  // namespace
}  // namespace plumbago

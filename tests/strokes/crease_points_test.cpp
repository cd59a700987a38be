// Crease and border points (Kalnins et al. 2002, §4.5): the GPU's float projection and facing
// against the reference's double ones, on the built-in parts, a mirrored object, an object
// far from the origin and faces of zero area; and the reference's points against the paths
// that window_lines projects.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "common/mesh/procedural.hpp"
#include "common/strokes/crease_points.hpp"
#include "common/strokes/strokes.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

std::vector<StageParity> point_parity(const Scene& scene, const std::string& label) {
  return testing::table_parity(scene, "crease_points", {kCreaseWindow.name, kCreaseFaces.name}, label);
}

size_t keys_in(const Image& faces) {
  return size_t(std::count_if(faces.data.begin(), faces.data.end(), [](float v) { return v != 0; }));
}

class CreasePoints : public testing::GlTest {};

// The CAD part, a cube and the brick facade of Kalnins et al. 2002's building.
Scene part(const std::string& name) {
  if (name == "cad") return testing::drawn_with_strokes(testing::builtin_at(name, 320, 240));
  return testing::one_stroke_object(make_procedural(name),
                                    name == "cube" ? glm::vec3(2.0f, 1.5f, 2.5f) : glm::vec3(4.0f, 5.0f, 9.0f));
}

TEST_F(CreasePoints, BuiltinPartsAgree) {
  for (const char* name : {"cad", "cube", "storefront"}) {
    auto results = point_parity(part(name), name);
    ASSERT_EQ(results.size(), 2u);
    EXPECT_GT(results[0].reference.pixels(), 20u) << name << ": creases to project";
    EXPECT_GT(keys_in(results[1].gpu), 10u) << name << ": faces that face the eye";
  }
}

// The GPU tests facing in object space: a mirroring transform must not turn it around.
TEST_F(CreasePoints, MirroredObjectFacesTheSameFaces) {
  Scene s = part("cube");
  s.objects[0].transform = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
  auto results = point_parity(s, "mirrored cube");
  ASSERT_EQ(results.size(), 2u);
  EXPECT_GT(keys_in(results[1].reference), 10u);
}

// Far from the origin the object-to-clip matrix, made in double, cancels the offset before
// it is rounded to float. Through a field of view of 0.002 degrees the off-window points lie
// millions of pixels out, where the float projection is off by more than the tolerance: the
// derived bound must explain every difference there.
TEST_F(CreasePoints, FarAndMagnifiedWithinTheDerivedBound) {
  Scene far = part("cad");
  glm::vec3 offset(1e6f, -2e6f, 5e5f);
  far.objects[0].transform = glm::translate(glm::mat4(1.0f), offset);
  far.camera.eye += offset, far.camera.target += offset;
  auto results = point_parity(far, "cad at 1e6");
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].bounded, 0u) << "no point needs more than the tolerance";
  Scene narrow = part("cad");
  narrow.camera.fov_deg = 0.002f;
  results = point_parity(narrow, "cad at 0.002 degrees");
  ASSERT_EQ(results.size(), 2u);
  const Image &ref = results[0].reference, &gpu = results[0].gpu;
  double raw = 0;
  for (size_t i = 0; i < ref.data.size(); ++i) raw = std::max(raw, double(std::abs(ref.data[i] - gpu.data[i])));
  std::printf("cad at 0.002 degrees: the largest difference %.3g px, %zu points bounded\n", raw, results[0].bounded);
  EXPECT_GT(raw, kCreasePointPx) << "points millions of px out: the bound is what passes them";
}

// Zero-area faces around the creases: their facing is n·(eye - p) = 0 in any precision.
TEST_F(CreasePoints, ZeroAreaFacesAreFiniteAndAgree) {
  Mesh cube = make_procedural("cube");
  const uint32_t a = cube.triangles[0][0], b = cube.triangles[0][1];
  cube.triangles.push_back({a, b, a});  // a sliver repeating a corner
  Scene s = testing::one_stroke_object(cube, glm::vec3(2.0f, 1.5f, 2.5f));
  auto results = point_parity(s, "cube with a sliver");
  ASSERT_EQ(results.size(), 2u);
  for (float v : results[1].gpu.data) EXPECT_TRUE(std::isfinite(v));
}

// The records are window_lines' crease and border points, in its order (a scene wholly in
// front of the near plane: no path is split).
TEST_F(CreasePoints, RecordsAreTheProjectedPathsInOrder) {
  Scene s = testing::drawn_with_strokes(testing::builtin_at("cad", 320, 240));
  auto results = point_parity(s, "cad order");
  ASSERT_EQ(results.size(), 2u);
  WindowLines lines = window_lines(s, s.params.get<StrokesParams>());
  size_t i = 0;
  const Image& window = results[0].reference;
  for (const WindowPath& p : lines.paths) {
    if (p.kind != LineKind::Crease && p.kind != LineKind::Border) continue;
    for (size_t k = 0; k < p.window.size(); ++k, ++i) {
      ASSERT_LT(i, window.pixels());
      EXPECT_NEAR(window.data[3 * i], p.window[k].x, 1e-3) << "record " << i;
      EXPECT_NEAR(window.data[3 * i + 1], p.window[k].y, 1e-3) << "record " << i;
      EXPECT_NEAR(window.data[3 * i + 2], p.depth[k], 1e-5 * p.depth[k]) << "record " << i;
    }
  }
  EXPECT_GT(i, 20u);
}

}  // namespace
}  // namespace plumbago

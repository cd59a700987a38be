// Silhouette segments face by face (Kalnins et al. 2002, §4.5): the GPU's float segments against the
// reference's double ones, on the analytic sphere (its silhouette stays on the true circle),
// where g is 0 in exact arithmetic at whole columns of vertices (the sign mismatches stay
// within the derived bound), on degenerate meshes and on the built-in scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/mesh/procedural.hpp"
#include "common/strokes/silhouette_segments.hpp"
#include "common/strokes/strokes.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/strokes/stroke_meshes.hpp"
#include "parity/parity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const std::vector<std::string> kSegmentResults = {kSegmentEnds.name, kSegmentFacing.name, kSegmentSlots.name};

// The outputs' parity, printed: the ends, the facing and the slots, in that order.
std::vector<StageParity> segment_parity(const Scene& scene, const std::string& label) {
  return testing::table_parity(scene, "silhouette_segments", kSegmentResults, label);
}

size_t segments_in(const Image& facing) {
  return size_t(std::count_if(facing.data.begin(), facing.data.end(), [](float v) { return v != 0; }));
}

class SilhouetteSegments : public testing::GlTest {};

// The meshes both silhouette steps read (gpu/strokes/stroke_meshes.hpp): a stroke object, one
// in pencil between (no rows of its own but zeros), another stroke object; each face record
// its object's own vertex numbers and slot orientations, each object's positions after the
// last one's.
TEST_F(SilhouetteSegments, StrokeMeshesHoldEveryStrokeObjectByRecord) {
  Scene s = testing::drawn_with_strokes(testing::builtin_at("cad", 160, 120));
  s.objects.push_back(s.objects[0]);
  s.objects.push_back(s.objects[0]);
  s.objects[1].style = Style::Pencil;
  std::shared_ptr<const LineMeshes> meshes = line_meshes(s, s.params.get<StrokesParams>(), LineObjects::Strokes);
  gpu::StrokeMeshes shared(s, *meshes);
  const Mesh& mesh = *s.objects[0].mesh;
  const size_t faces = mesh.triangles.size(), vertices = mesh.positions.size();
  ASSERT_EQ(shared.first_vertex, (std::vector<uint32_t>{0, uint32_t(vertices), uint32_t(vertices)}));
  std::vector<glm::uvec4> corners(3 * faces);
  std::vector<glm::vec4> positions(2 * vertices);
  gpu::read_buffer(shared.faces, corners.data(), corners.size() * sizeof(glm::uvec4));
  gpu::read_buffer(shared.positions, positions.data(), positions.size() * sizeof(glm::vec4));
  const FeatureLineMesh& lines = *line_mesh(*meshes, 0);
  for (size_t f = 0; f < faces; ++f) {
    const glm::uvec4 own(mesh.triangles[f], lines.reversed_slots(uint32_t(f)));
    EXPECT_EQ(corners[f], own) << f;
    EXPECT_EQ(corners[faces + f], glm::uvec4(0)) << f;
    EXPECT_EQ(corners[2 * faces + f], own) << f;
  }
  for (size_t v = 0; v < vertices; ++v) {
    EXPECT_EQ(positions[v], glm::vec4(mesh.positions[v], 1.0f)) << v;
    EXPECT_EQ(positions[vertices + v], glm::vec4(mesh.positions[v], 1.0f)) << v;
  }
}

TEST_F(SilhouetteSegments, BuiltinsAgreeInBothReadingsOfG) {
  for (const char* name : {"torus", "sphere", "cad"})
    for (bool normalized : {true, false}) {
      Scene s = testing::drawn_with_strokes(testing::builtin_at(name, 320, 240));
      s.params.set("strokes.silhouette_normalized", normalized ? 1.0 : 0.0);
      auto results = segment_parity(s, std::string(name) + (normalized ? "" : " literal"));
      ASSERT_EQ(results.size(), 3u);
      EXPECT_GT(segments_in(results[1].reference), 20u) << name;
    }
}

// The distance from the sphere's center (the origin) to the eye ray through window point p:
// the radius exactly where p is the image of a point of the true silhouette.
double ray_distance_to_center(const Scene& s, glm::dvec2 p) {
  glm::dvec3 d = glm::normalize(glm::dvec3(PrimaryRays(s.camera, s.width, s.height).direction(float(p.x), float(p.y))));
  glm::dvec3 to_center = -glm::dvec3(s.camera.eye);
  return glm::length(to_center - glm::dot(to_center, d) * d);
}

// docs/stages.md: the GPU's silhouette of a sphere lies on the circle where the view cone
// touches it. The points lie within the mesh's error of the true silhouette (feature_lines_test:
// the chord error plus the error of interpolating g along an edge, for the largest edge
// angle), and a point p off by e moves its ray by at most e from the tangent ray.
TEST_F(SilhouetteSegments, GpuSphereSilhouetteStaysOnTheTrueCircle) {
  Mesh sphere = make_procedural("sphere", 1.0f);
  double theta = 0;
  for (const auto& t : sphere.triangles)
    for (int k = 0; k < 3; ++k)
      theta =
          std::max(theta, std::acos(std::clamp(glm::dot(glm::normalize(glm::dvec3(sphere.positions[t[k]])),
                                                        glm::normalize(glm::dvec3(sphere.positions[t[(k + 1) % 3]]))),
                                               -1.0, 1.0)));
  for (double D : {2.0, 4.0, 20.0}) {
    Scene s = testing::one_stroke_object(sphere, glm::vec3(D * glm::normalize(glm::dvec3(0.3, -0.5, 0.8))));
    s.camera.fov_deg = float(2 * std::asin(1.0 / D) * 180 / std::numbers::pi) * 1.2f;
    const double bound = (1 - std::cos(theta / 2)) + theta * theta / 8 / std::sqrt(D * D - 1) + 1e-5;
    auto results = segment_parity(s, "sphere D " + std::to_string(int(D)));
    ASSERT_EQ(results.size(), 3u);
    const Image &ends = results[0].gpu, &facing = results[1].gpu;
    glm::dvec2 center(WindowProjection(s.camera, s.width, s.height)(glm::dvec3(0.0)));
    double worst = 0;
    size_t front = 0, counter_clockwise = 0;
    for (size_t i = 0; i < facing.pixels(); ++i) {
      if (facing.data[i] == 0) continue;
      front += facing.data[i] > 0;
      glm::dvec2 entry(ends.data[4 * i], ends.data[4 * i + 1]), exit(ends.data[4 * i + 2], ends.data[4 * i + 3]);
      glm::dvec2 d = exit - entry, to_center = center - entry;
      counter_clockwise += d.x * to_center.y - d.y * to_center.x > 0;
      for (int end = 0; end < 2; ++end) {
        glm::dvec2 p(ends.data[4 * i + 2 * end], ends.data[4 * i + 2 * end + 1]);
        worst = std::max(worst, std::abs(ray_distance_to_center(s, p) - 1.0));
      }
    }
    std::printf(
        "GPU sphere D %.0f: %zu segments, %zu front-facing, max distance to the true silhouette %.3g (bound %.3g)\n", D,
        segments_in(facing), front, worst, bound);
    EXPECT_EQ(front, segments_in(facing)) << "a convex object seen from outside has front-facing silhouettes only";
    EXPECT_EQ(counter_clockwise, front) << "g > 0, the visible side, on the left: the disc inside the loop";
    EXPECT_GT(front, 50u);
    EXPECT_LE(worst, bound);
  }
}

// An open cylinder of radius 1 (axis z, `around` columns, `rings` + 1 rings), column k at angle 2 pi k / around.
Mesh cylinder(int around, int rings) {
  Mesh m;
  for (int j = 0; j <= rings; ++j)
    for (int k = 0; k < around; ++k) {
      double a = 2 * std::numbers::pi * k / around;
      m.positions.emplace_back(float(std::cos(a)), float(std::sin(a)), float(2.0 * j / rings - 1));
    }
  auto v = [&](int j, int k) { return uint32_t(j * around + (k % around)); };
  for (int j = 0; j < rings; ++j)
    for (int k = 0; k < around; ++k) {
      m.triangles.push_back({v(j, k), v(j, k + 1), v(j + 1, k + 1)});
      m.triangles.push_back({v(j, k), v(j + 1, k + 1), v(j + 1, k)});
    }
  return m;
}

// The eye on the tangent planes of columns 1 and -1 (at distance 1 / cos(2 pi / around) along x):
// there g = 0 in exact arithmetic, so double and float round it either way. Every face
// mismatch must be one the derived bound names, and the bound must name the faces around
// those columns.
TEST_F(SilhouetteSegments, SignMismatchesAtGZeroStayWithinTheDerivedBound) {
  size_t bounded = 0, mismatched = 0;
  for (int around : {20, 24, 30, 36, 40, 48, 64, 100}) {
    Scene s = testing::one_stroke_object(cylinder(around, 16),
                                         glm::vec3(float(1 / std::cos(2 * std::numbers::pi / around)), 0, 0.3f));
    s.camera.target = glm::vec3(0, 0, 0.3f);
    s.camera.up = glm::vec3(0, 0, 1);
    s.camera.fov_deg = 150;
    auto results = segment_parity(s, "cylinder of " + std::to_string(around) + ", g = 0 on two columns");
    ASSERT_EQ(results.size(), 3u);
    const StageParity& facing = results[1];
    EXPECT_GE(facing.bounded, size_t(2 * 16 * 4)) << "the four faces per ring around each of the two columns";
    bounded += facing.bounded;
    for (size_t i = 0; i < facing.reference.pixels(); ++i) mismatched += facing.reference.data[i] != facing.gpu.data[i];
  }
  std::printf("cylinders: %zu faces where the sign may flip, %zu where the backends differ\n", bounded, mismatched);
}

// Zero-area faces, repeated corners, an isolated vertex and a flat sheet seen edge-on
// (g = 0 at every vertex): finite output, agreeing within the bound.
TEST_F(SilhouetteSegments, DegenerateMeshesStayFiniteAndAgree) {
  Mesh m = cylinder(24, 4);
  m.positions.emplace_back(5.0f, 5.0f, 5.0f);  // used by no face
  m.triangles.push_back({0, 0, 1});            // repeated corner
  m.positions.emplace_back(2.0f, 0.0f, 0.0f);
  m.positions.emplace_back(3.0f, 0.0f, 0.0f);
  m.triangles.push_back({uint32_t(m.positions.size() - 2), uint32_t(m.positions.size() - 1), 0});  // collinear
  for (glm::vec3 eye : {glm::vec3(3, 1, 0.5f), glm::vec3(0, 0, 4)}) {
    auto results = segment_parity(testing::one_stroke_object(m, eye), "degenerate");
    for (const StageParity& r : results) EXPECT_FALSE(has_non_finite(r.gpu)) << r.name;
  }
  Mesh sheet = make_procedural("plane", 1.0f);
  auto results = segment_parity(testing::one_stroke_object(sheet, glm::vec3(3, 0.0f, 0.0f)), "sheet edge-on");
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(segments_in(results[1].reference), 0u) << "g = 0 everywhere is taken as -1e-8: no sign change";
}

// A face table longer than GL's largest texture (1024 records a row) is refused with the
// table, the rows and the limit named, not left to a GL error: stroke objects of more than
// 1024 x GL_MAX_TEXTURE_SIZE faces (16.7M on llvmpipe) cannot be drawn by the GPU backend.
TEST_F(SilhouetteSegments, TablesBeyondTheLargestTextureAreRefusedByName) {
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  Scene scene = testing::builtin_at("torus", 64, 48);
  gpu::GpuFrame f(scene, Preprocessed{}, {"silhouette_segments"});
  const size_t fits = size_t(largest) * kTableRow;
  try {
    gpu::table_target(f, fits + 1, kSegmentEnds);
    ADD_FAILURE() << "a table of " << fits + 1 << " records was made";
  } catch (const std::runtime_error& e) {
    std::string expected = std::string(kSegmentEnds.name) + ": " + std::to_string(fits + 1) + " records take " +
                           std::to_string(largest + 1) + " rows of 1024, over this GL's largest texture";
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
  EXPECT_EQ(gpu::table_target(f, 5000, kSegmentEnds).height, 5);  // 5000 records: 5 rows
}

}  // namespace
}  // namespace plumbago

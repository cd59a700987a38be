// Feature lines (common/strokes/feature_lines.cpp, Kalnins et al. 2002, §4.5) checked as geometry
// (docs/conventions.md): on analytic shapes the silhouette lies on the true silhouette within the mesh's chord
// error, a cube has 12 crease paths, an open sheet one border loop, and tracing ends on
// degenerate input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <random>

#include "common/mesh/procedural.hpp"
#include "common/strokes/feature_lines.hpp"

namespace plumbago {
namespace {

const glm::dmat4 kIdentity(1.0);

size_t segment_count(const std::vector<FeaturePath>& paths) {
  size_t n = 0;
  for (const auto& p : paths) n += p.points.size() - 1 + (p.closed ? 1 : 0);
  return n;
}

size_t point_count(const std::vector<FeaturePath>& paths) {
  size_t n = 0;
  for (const auto& p : paths) n += p.points.size();
  return n;
}

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Every point is a surface point: finite, barycentrics in [0, 1] summing to 1, and the
// position their combination of the face's corners.
void expect_surface_points(const Mesh& mesh, const std::vector<FeaturePath>& paths, const char* what) {
  for (const auto& path : paths) {
    ASSERT_GE(path.points.size(), 2u) << what;
    for (const auto& p : path.points) {
      ASSERT_TRUE(finite(p.position) && finite(p.bary)) << what;
      ASSERT_LT(p.face, mesh.triangles.size()) << what;
      ASSERT_NEAR(p.bary.x + p.bary.y + p.bary.z, 1.0, 1e-12) << what;
      glm::dvec3 x(0.0);
      for (int k = 0; k < 3; ++k) {
        ASSERT_GE(p.bary[k], -1e-12) << what;
        x += p.bary[k] * glm::dvec3(mesh.positions[mesh.triangles[p.face][k]]);
      }
      ASSERT_LT(glm::length(x - p.position), 1e-9) << what;
    }
  }
}

void expect_surface_points(const Mesh& mesh, const FeatureLines& lines) {
  expect_surface_points(mesh, lines.creases, "crease");
  expect_surface_points(mesh, lines.borders, "border");
  expect_surface_points(mesh, lines.silhouettes, "silhouette");
}

// The largest angle an edge subtends at the origin (for a mesh on a sphere around it).
double max_edge_angle(const Mesh& m) {
  double largest = 0;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      glm::dvec3 a = glm::normalize(glm::dvec3(m.positions[t[k]])),
                 b = glm::normalize(glm::dvec3(m.positions[t[(k + 1) % 3]]));
      largest = std::max(largest, std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)));
    }
  return largest;
}

// Distance from p to the silhouette circle of the sphere (center 0, radius r) seen from
// `eye`: the points x with |x| = r and x·(x - eye) = 0, a circle of radius
// r sqrt(1 - r^2/D^2) around (r^2/D^2) eye in the plane perpendicular to eye.
double distance_to_sphere_silhouette(glm::dvec3 p, double r, glm::dvec3 eye) {
  double D = glm::length(eye);
  glm::dvec3 u = eye / D, center = u * (r * r / D);
  double rho = r * std::sqrt(1 - r * r / (D * D));
  glm::dvec3 q = p - center;
  double h = glm::dot(q, u), radial = glm::length(q - h * u);
  return std::sqrt(h * h + (radial - rho) * (radial - rho));
}

// docs/conventions.md: a sphere's silhouette is the circle where the view cone touches it. Bound, for
// the largest edge angle theta: the chord error r (1 - cos(theta/2)) (points on edges lie
// inside the sphere by up to that) plus the error of interpolating g linearly along an
// edge, r (theta^2 / 8) |g''/g'| with |g''/g'| = cot(alpha) = r / sqrt(D^2 - r^2) at the
// silhouette (g ~ cos(alpha) - r/D, alpha the angle from the eye direction), plus 1e-6.
// The default front-facing test must keep the whole loop (convex, seen from outside).
TEST(FeatureLines, SphereSilhouetteIsOneLoopOnTheTrueSilhouetteCircle) {
  Mesh sphere = make_procedural("sphere", 1.0f);
  const double r = 1.0, theta = max_edge_angle(sphere);
  for (bool normalized : {true, false})
    for (double D : {2.0, 4.0, 20.0}) {
      const double bound = r * (1 - std::cos(theta / 2)) + r * theta * theta / 8 * r / std::sqrt(D * D - r * r) + 1e-6;
      glm::dvec3 eye = D * glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
      FeatureLineOptions options;
      options.silhouette_normalized = normalized;
      FeatureLines lines = feature_lines(sphere, kIdentity, eye, options);
      expect_surface_points(sphere, lines);
      EXPECT_TRUE(lines.creases.empty());
      EXPECT_TRUE(lines.borders.empty());
      ASSERT_EQ(lines.silhouettes.size(), 1u) << "D " << D;
      EXPECT_TRUE(lines.silhouettes[0].closed);
      EXPECT_TRUE(lines.silhouettes[0].front_facing);
      double worst = 0;
      const auto& loop = lines.silhouettes[0].points;
      for (size_t i = 0; i < loop.size(); ++i) {
        glm::dvec3 p = loop[i].position, d = loop[(i + 1) % loop.size()].position - p;
        worst = std::max(worst, distance_to_sphere_silhouette(p, r, eye));
        // Oriented with the visible side (towards the eye) on the left, seen from outside.
        ASSERT_GT(glm::dot(glm::cross(glm::normalize(p), d), eye - p), 0) << "segment " << i;
      }
      std::printf(
          "sphere (%zu faces, max edge angle %.4f rad) D %.0f %s: %zu points, max distance to the true "
          "silhouette %.3g (bound %.3g)\n",
          sphere.triangles.size(), theta, D, normalized ? "normalized" : "literal c - x",
          lines.silhouettes[0].points.size(), worst, bound);
      EXPECT_LE(worst, bound);
      EXPECT_GT(lines.silhouettes[0].points.size(), 50u);
    }
}

// The true silhouette of an infinite cylinder (axis z, radius r) seen from `eye`: two
// rulings at the angles phi ± acos(r / rho) of the eye's horizontal direction phi and
// distance rho.
std::array<glm::dvec2, 2> cylinder_rulings(double r, glm::dvec3 eye) {
  double rho = std::hypot(eye.x, eye.y), phi = std::atan2(eye.y, eye.x), a = std::acos(r / rho);
  return {glm::dvec2(r * std::cos(phi + a), r * std::sin(phi + a)),
          glm::dvec2(r * std::cos(phi - a), r * std::sin(phi - a))};
}

// docs/conventions.md: a capped cylinder seen from the side has two silhouette rulings (open paths
// from rim to rim, parallel to the axis) and two closed cap-rim crease loops. Bound: the
// chord error r (1 - cos(pi / n)) of its n = 64 sides, plus 1e-6.
TEST(FeatureLines, CylinderHasTwoRulingsAndTwoRimLoops) {
  Mesh cylinder = make_procedural("cylinder", 1.0f);  // radius 0.5, z in [-1, 1], 64 sides
  const double r = 0.5, bound = r * (1 - std::cos(std::numbers::pi / 64)) + 1e-6;
  glm::dvec3 eye(4 * std::cos(0.3), 4 * std::sin(0.3), 0.2);
  FeatureLines lines = feature_lines(cylinder, kIdentity, eye, {});
  expect_surface_points(cylinder, lines);
  EXPECT_TRUE(lines.borders.empty());
  ASSERT_EQ(lines.creases.size(), 2u);
  for (const auto& rim : lines.creases) {
    EXPECT_TRUE(rim.closed);
    EXPECT_EQ(rim.points.size(), 64u);
    for (const auto& p : rim.points) {
      EXPECT_NEAR(std::abs(p.position.z), 1.0, 1e-6);
      EXPECT_NEAR(std::hypot(p.position.x, p.position.y), r, 1e-6);
    }
  }
  ASSERT_EQ(lines.silhouettes.size(), 2u);
  auto rulings = cylinder_rulings(r, eye);
  bool used[2] = {false, false};
  double worst = 0;
  for (const auto& path : lines.silhouettes) {
    EXPECT_FALSE(path.closed);
    glm::dvec2 start(path.points[0].position);
    int ruling = glm::length(start - rulings[0]) < glm::length(start - rulings[1]) ? 0 : 1;
    EXPECT_FALSE(used[ruling]) << "both paths on one ruling";
    used[ruling] = true;
    double zmin = 1e9, zmax = -1e9;
    for (const auto& p : path.points) {
      worst = std::max(worst, glm::length(glm::dvec2(p.position) - rulings[ruling]));
      zmin = std::min(zmin, p.position.z);
      zmax = std::max(zmax, p.position.z);
    }
    EXPECT_NEAR(zmin, -1.0, 1e-6);
    EXPECT_NEAR(zmax, 1.0, 1e-6);
    EXPECT_NEAR(std::abs(path.points.front().position.z), 1.0, 1e-6) << "a ruling ends at a rim";
    EXPECT_NEAR(std::abs(path.points.back().position.z), 1.0, 1e-6) << "a ruling ends at a rim";
  }
  std::printf("cylinder: rulings of %zu and %zu points, max distance from the true ruling %.3g (bound %.3g)\n",
              lines.silhouettes[0].points.size(), lines.silhouettes[1].points.size(), worst, bound);
  EXPECT_LE(worst, bound);
}

Mesh cube() {
  Mesh m;
  m.name = "test:cube";
  for (int i = 0; i < 8; ++i) m.positions.push_back(glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  const unsigned quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    glm::vec3 a = m.positions[q[0]], b = m.positions[q[1]], c = m.positions[q[2]];
    bool outward = glm::dot(glm::cross(b - a, c - a), a + c) > 0;
    for (glm::uvec3 t : {glm::uvec3(q[0], q[1], q[2]), glm::uvec3(q[0], q[2], q[3])})
      m.triangles.push_back(outward ? t : glm::uvec3(t.x, t.z, t.y));
  }
  compute_normals(m);
  return m;
}

// docs/conventions.md: a cube has 12 crease paths: every corner has crease degree 3, so each edge is
// a path of its own; the face diagonals are flat. No borders. With crease_deg = 100
// (n1·n2 = 0 is not below cos 100°) there are none.
TEST(FeatureLines, CubeHasTwelveCreasePaths) {
  Mesh m = cube();
  FeatureLines lines = feature_lines(m, kIdentity, glm::dvec3(3, 4, 5), {});
  expect_surface_points(m, lines);
  EXPECT_TRUE(lines.borders.empty());
  ASSERT_EQ(lines.creases.size(), 12u);
  for (const auto& path : lines.creases) {
    EXPECT_FALSE(path.closed);
    ASSERT_EQ(path.points.size(), 2u);
    EXPECT_NEAR(glm::length(path.points[0].position - path.points[1].position), 2.0, 1e-12) << "a cube edge";
  }
  FeatureLineOptions blunt;
  blunt.crease_deg = 100;
  EXPECT_TRUE(feature_lines(m, kIdentity, glm::dvec3(3, 4, 5), blunt).creases.empty());
}

// An open sheet: its border is one closed loop (the grid's corners have border degree
// 2), no creases; seen from above, no silhouette.
TEST(FeatureLines, OpenSheetHasOneBorderLoop) {
  Mesh plane = make_procedural("plane", 1.0f);  // 16 x 16 quads on [-1, 1]^2
  FeatureLines lines = feature_lines(plane, kIdentity, glm::dvec3(0.2, 0.1, 3), {});
  expect_surface_points(plane, lines);
  EXPECT_TRUE(lines.creases.empty());
  EXPECT_TRUE(lines.silhouettes.empty());
  ASSERT_EQ(lines.borders.size(), 1u);
  EXPECT_TRUE(lines.borders[0].closed);
  EXPECT_EQ(lines.borders[0].points.size(), 64u);
  for (const auto& p : lines.borders[0].points)
    EXPECT_NEAR(std::max(std::abs(p.position.x), std::abs(p.position.y)), 1.0, 1e-6);
}

// The torus (R = 1, r = 0.4) from a generic direction: the whole zero set of g
// (keep_back_facing) is closed loops. Without back-facing segments there are fewer
// segments (the inner silhouette folds behind the surface between cusps). Reported: the
// largest |n·normalize(eye - x)| with the analytic normal at the silhouette points.
TEST(FeatureLines, TorusSilhouettesAreClosedLoopsAndBackFacingOnesAreDropped) {
  Mesh torus = make_procedural("torus", 1.0f);
  glm::dvec3 eye(3.1, -1.7, 2.3);
  FeatureLineOptions all;
  all.keep_back_facing = true;
  FeatureLines everything = feature_lines(torus, kIdentity, eye, all);
  expect_surface_points(torus, everything);
  EXPECT_TRUE(everything.creases.empty());
  EXPECT_TRUE(everything.borders.empty());
  ASSERT_FALSE(everything.silhouettes.empty());
  // Joined back together, the pieces of each facing are closed loops: count ends.
  size_t ends = 0;
  for (const auto& path : everything.silhouettes) ends += path.closed ? 0 : 1;
  FeatureLines front = feature_lines(torus, kIdentity, eye, {});
  expect_surface_points(torus, front);
  size_t back_pieces = 0;
  for (const auto& path : everything.silhouettes) back_pieces += path.front_facing ? 0 : 1;
  for (const auto& path : front.silhouettes) EXPECT_TRUE(path.front_facing);
  double worst = 0;
  for (const auto& path : everything.silhouettes)
    for (const auto& p : path.points) {
      glm::dvec3 x = p.position, ring = 1.0 * glm::normalize(glm::dvec3(x.x, x.y, 0));
      glm::dvec3 n = glm::normalize(x - ring);
      worst = std::max(worst, std::abs(glm::dot(n, glm::normalize(eye - x))));
    }
  std::printf(
      "torus (%zu faces): %zu paths with back-facing kept (%zu back-facing, %zu open at facing changes), "
      "%zu segments; front only %zu paths, %zu segments; max |n.v| at the points %.3g\n",
      torus.triangles.size(), everything.silhouettes.size(), back_pieces, ends, segment_count(everything.silhouettes),
      front.silhouettes.size(), segment_count(front.silhouettes), worst);
  EXPECT_GT(segment_count(everything.silhouettes), segment_count(front.silhouettes));
  EXPECT_GT(back_pieces, 0u);
  EXPECT_LT(worst, 0.02);
}

// The torus's full zero set before any cut by facing: with every segment counted as
// front-facing there would be no open path; here, cut pieces end where the facing flips,
// so checking closure directly needs the uncut loops: the sum of open ends of front and
// back pieces is even, and each open front piece ends where a back piece begins.
TEST(FeatureLines, TorusPiecesJoinIntoClosedLoops) {
  Mesh torus = make_procedural("torus", 1.0f);
  FeatureLineOptions all;
  all.keep_back_facing = true;
  for (glm::dvec3 eye : {glm::dvec3(3.1, -1.7, 2.3), glm::dvec3(0.3, 0.2, 5.0), glm::dvec3(-4, 1, 0.7)}) {
    FeatureLines lines = feature_lines(torus, kIdentity, eye, all);
    ASSERT_FALSE(lines.silhouettes.empty());
    // Every open piece's end points coincide with an end point of another piece.
    std::vector<glm::dvec3> ends;
    for (const auto& path : lines.silhouettes)
      if (!path.closed) ends.insert(ends.end(), {path.points.front().position, path.points.back().position});
    for (size_t i = 0; i < ends.size(); ++i) {
      size_t matches = 0;
      for (size_t j = 0; j < ends.size(); ++j) matches += j != i && ends[i] == ends[j];
      EXPECT_EQ(matches, 1u) << "an open end at no other piece's end";
    }
  }
}

// Seen down its axis, a torus shows two front-facing closed loops: the outer equator and
// the rim of the hole (the tube bends away from the viewer on both), and nothing
// back-facing.
TEST(FeatureLines, TorusFromAboveHasTwoFrontFacingLoops) {
  Mesh torus = make_procedural("torus", 1.0f);
  FeatureLineOptions all;
  all.keep_back_facing = true;
  FeatureLines lines = feature_lines(torus, kIdentity, glm::dvec3(0.03, 0.02, 6.0), all);
  ASSERT_EQ(lines.silhouettes.size(), 2u);
  double radii[2];
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(lines.silhouettes[i].closed);
    EXPECT_TRUE(lines.silhouettes[i].front_facing);
    glm::dvec3 p = lines.silhouettes[i].points[0].position;
    radii[i] = std::hypot(p.x, p.y);
  }
  std::printf("torus from above: loops at radius %.3f and %.3f (equators 1.4 and 0.6)\n", radii[0], radii[1]);
  EXPECT_NEAR(std::max(radii[0], radii[1]), 1.4, 0.02);
  EXPECT_NEAR(std::min(radii[0], radii[1]), 0.6, 0.02);
}

// Moving the object and the eye together changes nothing (the eye goes to object space).
TEST(FeatureLines, EyeIsTakenToObjectSpace) {
  Mesh torus = make_procedural("torus", 0.5f);
  glm::dvec3 eye(3.1, -1.7, 2.3);
  glm::dmat4 m = glm::scale(glm::translate(kIdentity, glm::dvec3(1, -2, 3)), glm::dvec3(2.5));
  FeatureLines a = feature_lines(torus, kIdentity, eye, {});
  FeatureLines b = feature_lines(torus, m, glm::dvec3(m * glm::dvec4(eye, 1)), {});
  ASSERT_EQ(a.silhouettes.size(), b.silhouettes.size());
  for (size_t i = 0; i < a.silhouettes.size(); ++i) {
    ASSERT_EQ(a.silhouettes[i].points.size(), b.silhouettes[i].points.size());
    for (size_t k = 0; k < a.silhouettes[i].points.size(); ++k)
      EXPECT_LT(glm::length(a.silhouettes[i].points[k].position - b.silhouettes[i].points[k].position), 1e-9);
  }
}

// A sheet with a smooth bump in its middle; outside the bump it is flat (z = 0 exactly),
// so an eye in the plane z = 0 has g = 0 exactly at those vertices.
Mesh bump_sheet(int n) {
  Mesh m;
  m.name = "test:bump";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      float x = 2.0f * float(i) / float(n) - 1, y = 2.0f * float(j) / float(n) - 1;
      float s = std::max(0.0f, 1 - (x * x + y * y) / 0.36f);
      m.positions.push_back({x, y, 0.4f * s * s});
    }
  auto at = [&](int i, int j) { return unsigned(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  compute_normals(m);
  return m;
}

// No NaN, every path point a surface point, and at most 2 points per face (silhouettes)
// and per edge (creases and borders).
void expect_bounded_and_finite(const Mesh& m, const FeatureLines& lines, size_t edges_bound) {
  expect_surface_points(m, lines);
  EXPECT_LE(point_count(lines.silhouettes), 2 * m.triangles.size());
  EXPECT_LE(point_count(lines.creases) + point_count(lines.borders), 2 * edges_bound);
}

// Termination (Kalnins et al. 2002, §4.5): vertices where g = 0 exactly, a non-manifold edge (three
// faces), a repeated face, zero-area faces (collinear corners, a repeated corner), and
// the eye on a vertex.
TEST(FeatureLines, TracingEndsOnDegenerateInput) {
  Mesh bump = bump_sheet(24);
  glm::dvec3 eye(3, 0.37, 0);
  auto g = silhouette_function(bump, eye);
  size_t zeros = std::count(g.begin(), g.end(), -1e-8);
  EXPECT_GT(zeros, 100u) << "the test should hit g = 0 exactly";
  FeatureLineOptions all;
  all.keep_back_facing = true;
  FeatureLines lines = feature_lines(bump, kIdentity, eye, all);
  EXPECT_FALSE(lines.silhouettes.empty());
  expect_bounded_and_finite(bump, lines, 3 * bump.triangles.size());
  std::printf("bump sheet: %zu corners with g = 0 -> -1e-8, %zu silhouette paths, %zu points (%zu faces)\n", zeros,
              lines.silhouettes.size(), point_count(lines.silhouettes), bump.triangles.size());

  // Degenerate additions on top of the bump sheet and a small non-manifold soup.
  Mesh soup = bump;
  unsigned base = unsigned(soup.positions.size());
  soup.positions.insert(soup.positions.end(),
                        {{0, 0, 2}, {1, 0, 2}, {0.5f, 1, 2}, {0.5f, -1, 2}, {0.5f, 0, 3}, {2, 0, 2}, {0.5f, 0, 1}});
  for (glm::uvec3 t : {glm::uvec3(0, 1, 2), glm::uvec3(1, 0, 3), glm::uvec3(0, 1, 4), glm::uvec3(0, 1, 6),
                       glm::uvec3(0, 1, 2), glm::uvec3(0, 1, 5), glm::uvec3(2, 2, 4), glm::uvec3(4, 4, 4)})
    soup.triangles.push_back(t + glm::uvec3(base));
  soup.triangles.push_back(bump.triangles[10]);  // a repeated face of the sheet
  soup.triangles.push_back(glm::uvec3(bump.triangles[20].x, bump.triangles[20].z, bump.triangles[20].y));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<glm::dvec3> eyes = {eye, glm::dvec3(soup.positions[base]), glm::dvec3(soup.positions[5]),
                                  glm::dvec3(0.5, 0, 2.5)};
  for (int i = 0; i < 40; ++i) eyes.push_back({u(rng), u(rng), u(rng)});
  size_t most = 0;
  for (const auto& e : eyes)
    for (bool normalized : {true, false}) {
      all.silhouette_normalized = normalized;
      FeatureLines soup_lines = feature_lines(soup, kIdentity, e, all);
      expect_bounded_and_finite(soup, soup_lines, 3 * soup.triangles.size());
      most = std::max(most, point_count(soup_lines.silhouettes));
    }
  std::printf("degenerate soup (%zu faces): %zu eyes finished, at most %zu silhouette points\n", soup.triangles.size(),
              2 * eyes.size(), most);
}

// The CAD part (creases next to smooth patches): finite, bounded, and silhouettes stop
// at creases (no path point off the mesh).
TEST(FeatureLines, CadPartIsFiniteAndBounded) {
  Mesh cad = make_procedural("cad", 1.0f);
  FeatureLines lines = feature_lines(cad, kIdentity, glm::dvec3(2.2, -3.1, 1.7), {});
  expect_bounded_and_finite(cad, lines, 3 * cad.triangles.size());
  EXPECT_FALSE(lines.creases.empty());
  EXPECT_TRUE(lines.borders.empty());
  EXPECT_FALSE(lines.silhouettes.empty());
  std::printf("cad part (%zu faces): %zu crease paths, %zu silhouette paths\n", cad.triangles.size(),
              lines.creases.size(), lines.silhouettes.size());
}

}  // namespace
}  // namespace plumbago

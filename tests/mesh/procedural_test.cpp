// Procedural meshes (common/mesh/procedural.cpp): closed and outward where they should be, on
// their analytic surfaces, sharp creases on the CAD part, refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <numeric>

#include "common/mesh/procedural.hpp"

namespace plumbago {
namespace {

using Edge = std::pair<unsigned, unsigned>;

std::map<Edge, int> directed_edges(const Mesh& m) {
  std::map<Edge, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) directed[{t[k], t[(k + 1) % 3]}]++;
  return directed;
}

// Enclosed volume by the divergence theorem: sum of the tetrahedra (0, a, b, c) / 6.
double signed_volume(const Mesh& m) {
  double volume = 0;
  for (const auto& t : m.triangles)
    volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  return volume;
}

// Pieces of the mesh joined through shared vertices.
size_t connected_pieces(const Mesh& m) {
  std::vector<unsigned> parent(m.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](unsigned v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : m.triangles) parent[root(t[1])] = parent[root(t[2])] = root(t[0]);
  size_t pieces = 0;
  for (unsigned v = 0; v < parent.size(); ++v) pieces += root(v) == v;
  return pieces;
}

void expect_unit_normals(const Mesh& m, const std::string& kind) {
  ASSERT_EQ(m.normals.size(), m.positions.size()) << kind;
  for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << kind;
}

// Closed kinds: every edge in exactly two faces, in opposite directions; one piece;
// positive enclosed volume (outward orientation), at several tessellations.
TEST(Procedural, ClosedKindsAreWatertightOutwardAndInOnePiece) {
  for (const char* kind : {"torus", "sphere", "cylinder", "cad"})
    for (float res : {0.5f, 1.0f, 2.0f}) {
      Mesh m = make_procedural(kind, res);
      auto directed = directed_edges(m);
      for (const auto& [e, n] : directed) {
        ASSERT_EQ(n, 1) << kind << " edge used twice in one direction";
        ASSERT_EQ(directed.count({e.second, e.first}), 1u) << kind << " open edge";
      }
      EXPECT_EQ(connected_pieces(m), 1u) << kind;
      EXPECT_GT(signed_volume(m), 0) << kind;
      expect_unit_normals(m, kind);
    }
}

TEST(Procedural, VolumesApproachTheAnalyticSolids) {
  const double pi = std::numbers::pi;
  EXPECT_NEAR(signed_volume(make_procedural("torus", 2)), 2 * pi * pi * 1.0 * 0.4 * 0.4, 0.01);
  EXPECT_NEAR(signed_volume(make_procedural("sphere", 2)), 4.0 / 3.0 * pi, 0.01);
  EXPECT_NEAR(signed_volume(make_procedural("cylinder", 2)), pi * 0.25 * 2, 0.01);
  // Slab 1.2 x 1.2 plus a half disc of radius 0.6, 0.5 thick; boss of radius 0.3, 0.4 tall.
  EXPECT_NEAR(signed_volume(make_procedural("cad", 2)), (1.44 + pi * 0.18) * 0.5 + pi * 0.09 * 0.4, 0.01);
}

TEST(Procedural, VerticesLieOnTheirSurfaces) {
  for (const auto& p : make_procedural("sphere").positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
  for (const auto& p : make_procedural("torus").positions)
    EXPECT_NEAR(std::hypot(std::hypot(p.x, p.y) - 1.0f, p.z), 0.4f, 1e-5f);
}

// The icosphere has no poles: its smallest triangle is not much smaller than its largest.
TEST(Procedural, SphereTrianglesAreNearlyUniform) {
  Mesh m = make_procedural("sphere");
  float smallest = INFINITY, largest = 0;
  for (const auto& t : m.triangles) {
    float a = glm::length(glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
    smallest = std::min(smallest, a);
    largest = std::max(largest, a);
  }
  EXPECT_GT(smallest, 0.5f * largest);
}

TEST(Procedural, PlaneIsOneFlatSheetFacingUp) {
  Mesh m = make_procedural("plane");
  auto directed = directed_edges(m);
  size_t boundary = 0;
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1);
    boundary += directed.count({e.second, e.first}) == 0;
  }
  EXPECT_EQ(boundary, 4u * 16u);  // the square's rim at the default 16 x 16 grid
  for (const auto& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(Procedural, CadPartHasSharpCreasesAndSmoothPatches) {
  Mesh m = make_procedural("cad");
  std::map<Edge, std::vector<size_t>> faces_of_edge;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      auto e = std::minmax(m.triangles[f][k], m.triangles[f][(k + 1) % 3]);
      faces_of_edge[{e.first, e.second}].push_back(f);
    }
  auto normal = [&](size_t f) {
    const auto& t = m.triangles[f];
    return glm::normalize(glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
  };
  int sharp = 0, gentle = 0;
  for (const auto& [e, fs] : faces_of_edge) {
    ASSERT_EQ(fs.size(), 2u);
    float c = glm::dot(normal(fs[0]), normal(fs[1]));
    sharp += c < 0.2f;                   // about 80 degrees or more
    gentle += c > 0.95f && c < 0.9999f;  // curved patch
  }
  EXPECT_GT(sharp, 4 * 96);  // rims of the slab and the boss, the boss's foot, the slab's corners
  EXPECT_GT(gentle, 100);
}

// Every curved kind; the cube's flat faces take no resolution (its two triangles a face
// and the caps' fans are exact).
TEST(Procedural, ACubeIsTwelveCreaseEdgesAroundAUnitCube) {
  Mesh m = make_procedural("cube", 1);
  EXPECT_EQ(m.bbox_min(), glm::vec3(-0.5f));
  EXPECT_EQ(m.bbox_max(), glm::vec3(0.5f));
  EXPECT_EQ(make_procedural("cube", 3).triangles.size(), m.triangles.size());
}

// Kalnins et al. 2002's building, Table 1: 16K faces; the stand-in within a factor 1.5.
TEST(Procedural, AStorefrontIsBricksOnAWall) {
  Mesh m = make_procedural("storefront", 1);
  EXPECT_EQ(m.triangles.size() % 16, 0u);  // boxes only (16 triangles each): the wall and the bricks
  EXPECT_GT(m.triangles.size(), 16000 / 1.5);
  EXPECT_LT(m.triangles.size(), 16000 * 1.5);
  EXPECT_EQ(m.bbox_min(), glm::vec3(-3.0f, 0.0f, -0.3f));
  EXPECT_NEAR(m.bbox_max().y, 4.0f, 0.1f);
}

TEST(Procedural, ResolutionScalesTheTessellation) {
  for (const auto& kind : procedural_kinds())
    if (kind != "cube") {
      EXPECT_GT(make_procedural(kind, 2).triangles.size(), 2 * make_procedural(kind, 1).triangles.size()) << kind;
    }
}

TEST(Procedural, UnknownKindAndBadResolutionAreRefused) {
  EXPECT_THROW(make_procedural("donut"), std::invalid_argument);
  EXPECT_THROW(make_procedural("torus", 0.0f), std::invalid_argument);
  EXPECT_THROW(make_procedural("torus", NAN), std::invalid_argument);
}

// The parameterized kinds carry (u, v) per corner (Mesh::uvs): a chart without folds, each
// face's (u, v) triangle turning the way the face does seen from outside (u about the axis,
// v along it or across the tube), and the corners' u the angle of their position about z
// (the sphere, cylinder and cone; 1 past the seam), through the weld.
TEST(Procedural, ParameterizedKindsHaveAnUnfoldedChart) {
  for (const std::string kind : {"torus", "sphere", "plane", "cylinder", "cone"}) {
    Mesh m = make_procedural(kind);
    ASSERT_EQ(m.uvs.size(), 3 * m.triangles.size()) << kind;
    for (size_t f = 0; f < m.triangles.size(); ++f) {
      const glm::vec2 *uv = &m.uvs[3 * f], a = uv[1] - uv[0], b = uv[2] - uv[0];
      ASSERT_GT(a.x * b.y - a.y * b.x, 0.0f) << kind << " face " << f;
      if (kind == "torus" || kind == "plane") continue;
      for (int k = 0; k < 3; ++k) {
        glm::vec3 p = m.positions[m.triangles[f][k]];
        if (p.x == 0 && p.y == 0) continue;  // on the axis: no angle of its own
        float angle = std::atan2(p.y, p.x) / (2 * std::numbers::pi_v<float>);
        ASSERT_NEAR(std::fmod(uv[k].x - angle + 2, 1.0f), 0.0f, 1e-5f) << kind << " face " << f;
      }
    }
  }
  for (const std::string kind : {"cad", "cube", "storefront"}) EXPECT_TRUE(make_procedural(kind).uvs.empty()) << kind;
}

}  // namespace
}  // namespace plumbago

// Decimation by edge collapse with quadric error metrics (common/mesh/decimate.hpp): the face
// count asked for, a surface that stays where it was, a manifold and clean result, and
// refusals that name the mesh; scenes that ask for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/mesh/decimate.hpp"
#include "common/mesh/mesh_topology.hpp"
#include "common/mesh/procedural.hpp"
#include "common/scene/scene.hpp"
#include "tests/support/far_mesh_files.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

// How far the vertices of `m` lie from the sphere of radius r about the origin, at most.
double off_sphere(const Mesh& m, double r) {
  double worst = 0;
  for (const glm::vec3& p : m.positions) worst = std::max(worst, std::abs(glm::length(glm::dvec3(p)) - r));
  return worst;
}

TEST(Decimate, ASphereKeepsItsShapeAtAFifthOfItsFaces) {
  Mesh sphere = make_procedural("sphere", 2.0f);
  const double r = glm::length(glm::dvec3(sphere.positions[0]));
  const size_t asked = sphere.triangles.size() / 5;
  Mesh coarse = decimate(sphere, asked);
  std::printf("sphere: %zu faces -> %zu (asked %zu), %zu vertices, off the sphere by %.2e of r = %.3f\n",
              sphere.triangles.size(), coarse.triangles.size(), asked, coarse.positions.size(),
              off_sphere(coarse, r) / r, r);
  EXPECT_LE(coarse.triangles.size(), asked + 2);  // a closed mesh: 3 faces / 2 edges
  EXPECT_GE(coarse.triangles.size(), asked - 2);
  EXPECT_LT(off_sphere(coarse, r), 0.02 * r);  // quadrics keep vertices on the surface's planes
  MeshTopology topology = build_topology(coarse);
  EXPECT_EQ(topology.split_faces, 0u);
  for (const MeshTopology::Edge& e : topology.edges) EXPECT_GE(e.face[1], 0);  // still closed
  EXPECT_EQ(coarse.normals.size(), coarse.positions.size());
  for (const glm::vec3& n : coarse.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  EXPECT_TRUE(coarse.uvs.empty());
  EXPECT_NE(coarse.name.find("decimated to"), std::string::npos);
  EXPECT_NO_THROW(validate_drawable_mesh(coarse));
}

TEST(Decimate, AMeshWithNoMoreFacesIsKept) {
  Mesh torus = make_procedural("torus", 1.0f);
  Mesh same = decimate(torus, torus.triangles.size());
  EXPECT_EQ(same.triangles, torus.triangles);
  EXPECT_EQ(same.positions, torus.positions);
}

TEST(Decimate, RefusalsNameTheMesh) {
  Mesh torus = make_procedural("torus", 1.0f);
  EXPECT_THROW(decimate(torus, 3), MeshError);
  Mesh fin;  // three faces on the edge (0, 1): no manifold
  fin.name = "fin.obj";
  fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 1, 5}, {4, 5, 1}};
  compute_normals(fin);
  try {
    decimate(fin, 4);
    ADD_FAILURE() << "a face on an edge of two others decimated";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("fin.obj: cannot be decimated: face 2"), std::string::npos) << e.what();
  }
}

// A file's mesh and a procedural one decimated from a scene; the file read once for both
// objects that name it, decimated or not.
TEST(Decimate, ScenesAskForIt) {
  testing::TempDir dir;
  dir.write("ball.obj", testing::mesh_text_at(make_procedural("sphere", 1.0f), "obj", 0.0));
  Scene s = parse_scene(R"({"objects": [{"mesh": {"file": "ball.obj", "decimate_to": 200}},
      {"mesh": "ball.obj"}, {"mesh": {"procedural": "torus", "decimate_to": 300}}]})",
                        "decimate.json", dir.dir());
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_NEAR(double(s.objects[0].mesh->triangles.size()), 200.0, 2.0);
  EXPECT_EQ(s.objects[1].mesh->triangles.size(), make_procedural("sphere", 1.0f).triangles.size());
  EXPECT_NEAR(double(s.objects[2].mesh->triangles.size()), 300.0, 2.0);
}

}  // namespace
}  // namespace plumbago

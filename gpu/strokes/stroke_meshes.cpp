// The stroke objects' meshes on the GPU: see gpu/strokes/stroke_meshes.hpp.
#include "gpu/strokes/stroke_meshes.hpp"

#include <algorithm>

#include "common/strokes/strokes.hpp"

namespace plumbago::gpu {

StrokeMeshes::StrokeMeshes(const Scene& scene, const LineMeshes& meshes) {
  const std::vector<uint32_t> first = first_faces(scene);
  std::vector<glm::vec4> points;
  std::vector<glm::uvec4> corners(std::max<size_t>(first.back(), 1), glm::uvec4(0));  // never an empty buffer
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    first_vertex.push_back(uint32_t(points.size()));
    const FeatureLineMesh* lines = line_mesh(meshes, o);
    if (!lines) continue;
    const Mesh& mesh = *scene.objects[o].mesh;
    for (glm::vec3 p : mesh.positions) points.emplace_back(p, 1.0f);
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
      corners[first[o] + f] = glm::uvec4(mesh.triangles[f], lines->reversed_slots(f));
  }
  if (points.empty()) points.emplace_back(0.0f);
  positions = make_buffer(points.data(), points.size() * sizeof(glm::vec4));
  faces = make_buffer(corners.data(), corners.size() * sizeof(glm::uvec4));
}

}  // namespace plumbago::gpu

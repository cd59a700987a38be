// Crease and border points: see common/strokes/crease_points.hpp.
#include "common/strokes/crease_points.hpp"

#include <stdexcept>

#include "common/strokes/strokes.hpp"

namespace plumbago {

namespace {

void add_path(const Scene& scene, const LineMeshes& meshes, uint32_t object, const FeaturePath& path,
              std::vector<CreaseRecord>& out) {
  const Mesh& mesh = *scene.objects[object].mesh;
  const size_t n = path.points.size();
  for (size_t i = 0; i < n; ++i) {
    CreaseRecord r{object, vertex_of(mesh, path.points[i]), {}};
    if (i + 1 < n || path.closed)
      r.faces = edge_faces(meshes, object, r.vertex, vertex_of(mesh, path.points[(i + 1) % n]));
    out.push_back(std::move(r));
  }
}

}  // namespace

std::vector<CreaseRecord> crease_records(const Scene& scene, const LineMeshes& meshes) {
  if (first_faces(scene).back() >= (1u << 24))
    throw std::length_error("crease points: " + std::to_string(first_faces(scene).back()) +
                            " faces; face keys are exact in a float below 2^24");
  std::vector<CreaseRecord> out;
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    const FeatureLineMesh* lines = line_mesh(meshes, o);
    if (!lines) continue;
    for (const FeaturePath& path : lines->creases_and_borders().creases) add_path(scene, meshes, o, path, out);
    for (const FeaturePath& path : lines->creases_and_borders().borders) add_path(scene, meshes, o, path, out);
  }
  return out;
}

}  // namespace plumbago

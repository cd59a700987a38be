#include "common/strokes/silhouette_paths.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace plumbago {

std::vector<ChainPath> chain_paths(const Scene& scene, const LineMeshes& meshes, const std::vector<float>& paths,
                                   const std::vector<float>& crossings, bool normalized) {
  const std::vector<uint32_t> first = first_faces(scene);
  const auto path_count = size_t(paths.at(0)), point_count = size_t(paths.at(1));
  if (paths.size() < 4 * (path_count + 1) || crossings.size() < 2 * point_count)
    throw std::logic_error("silhouette paths: the tables hold fewer rows than their counts");
  std::vector<ChainPath> out;
  for (size_t p = 1; p <= path_count; ++p) {
    const float* row = &paths[4 * p];
    const auto start = uint32_t(row[0]) - 1, first_point = uint32_t(row[1]), flags = uint32_t(row[3]);
    const auto object = uint32_t(std::upper_bound(first.begin(), first.end(), start) - first.begin()) - 1;
    const FeatureLineMesh* mesh = start < first.back() ? line_mesh(meshes, object) : nullptr;
    if (!mesh || first_point + size_t(row[2]) > point_count)
      throw std::logic_error("silhouette paths: row " + std::to_string(p) + " names no path of a stroke object");
    const glm::dvec3 eye =
        eye_in_object_space(glm::dmat4(scene.objects[object].transform), glm::dvec3(scene.camera.eye));
    ChainPath c{object, start, {{}, (flags & 1u) != 0, (flags & 2u) != 0}};
    for (size_t q = first_point; q < first_point + size_t(row[2]); ++q)
      c.path.points.push_back(
          mesh->crossing(eye, normalized, uint32_t(crossings[2 * q]) - 1 - first[object], int(crossings[2 * q + 1])));
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace plumbago

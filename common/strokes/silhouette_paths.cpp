#include "common/strokes/silhouette_paths.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace plumbago {

std::vector<ChainPath> chain_paths(const Scene& scene, const LineMeshes& meshes, const std::vector<float>& paths,
                                   const std::vector<SilhouettePoint>& points) {
  const std::vector<uint32_t> first = first_faces(scene);
  const auto path_count = size_t(paths.at(0));
  if (paths.size() < 4 * (path_count + 1) || points.size() < size_t(paths[1]))
    throw std::logic_error("silhouette paths: the tables hold fewer rows than their counts");
  std::vector<ChainPath> out;
  for (size_t p = 1; p <= path_count; ++p) {
    const float* row = &paths[4 * p];
    const auto start = uint32_t(row[0]) - 1, first_point = uint32_t(row[1]), flags = uint32_t(row[3]);
    const auto object = uint32_t(std::upper_bound(first.begin(), first.end(), start) - first.begin()) - 1;
    const FeatureLineMesh* mesh = start < first.back() ? line_mesh(meshes, object) : nullptr;
    if (!mesh || first_point + size_t(row[2]) > points.size())
      throw std::logic_error("silhouette paths: row " + std::to_string(p) + " names no path of a stroke object");
    ChainPath c{object, start, {{}, (flags & 1u) != 0, (flags & 2u) != 0}};
    for (size_t q = first_point; q < first_point + size_t(row[2]); ++q) {
      const SilhouettePoint& s = points[q];
      if (s.record < first[object] || s.record >= first[object + 1] || s.slot > 2)
        throw std::logic_error("silhouette paths: point " + std::to_string(q) +
                               " lies on no face of its path's object");
      c.path.points.push_back(mesh->slot_point(s.record - first[object], int(s.slot), s.t));
      c.window.emplace_back(s.x, s.y, s.depth);
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace plumbago

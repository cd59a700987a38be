#include "common/strokes/silhouette_chains.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/strokes/strokes.hpp"

namespace plumbago {

std::vector<glm::uvec4> slot_links(const Scene& scene, const LineMeshes& meshes) {
  std::vector<uint32_t> first = first_faces(scene);
  if (first.back() >= (1u << 24))
    throw std::length_error("silhouette chains: " + std::to_string(first.back()) +
                            " faces; record numbers are exact in a float below 2^24");
  std::vector<glm::uvec4> links(first.back(), glm::uvec4(kNoLink));
  for (size_t o = 0; o < scene.objects.size(); ++o)
    if (const FeatureLineMesh* lines = line_mesh(meshes, o))
      for (uint32_t f = 0; f < scene.objects[o].mesh->triangles.size(); ++f)
        for (int k = 0; k < 3; ++k)
          if (auto [face, slot] = lines->across(f, k); face >= 0)
            links[first[o] + f][k] = (first[o] + uint32_t(face)) * 4 + uint32_t(slot);
  return links;
}

std::map<std::string, double> silhouette_counts(const Image* facing, const Image* chains) {
  std::map<std::string, double> out;
  if (facing)
    out["segments"] = double(std::count_if(facing->data.begin(), facing->data.end(), [](float v) { return v != 0; }));
  if (chains) {
    double starts = 0;
    for (size_t i = 0; i < chains->pixels(); ++i) starts += chains->data[i * 4] != 0 && chains->data[i * 4 + 1] == 0;
    out["chains"] = starts;
  }
  return out;
}

}  // namespace plumbago

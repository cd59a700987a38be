#include "common/sketchy/sketchy.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "common/util/noise.hpp"

namespace plumbago {

namespace {

Scene with_objects(const Scene& scene, bool sketchy) {
  Scene out = scene;
  out.objects.clear();
  for (const SceneObject& o : scene.objects)
    if ((o.style == Style::Sketchy) == sketchy) out.objects.push_back(o);
  return out;
}

}  // namespace

Scene sketchy_objects(const Scene& scene) { return with_objects(scene, true); }
Scene ordinary_objects(const Scene& scene) { return with_objects(scene, false); }

std::vector<glm::vec3> object_colors(const Scene& scene) {
  std::vector<glm::vec3> out;
  for (const SceneObject& o : scene.objects) out.push_back(o.color);
  return out;
}

Mesh enlarged_mesh(const Mesh& mesh, float distance) {
  Mesh out = mesh;
  out.name = mesh.name + " (enlarged)";
  for (size_t v = 0; v < out.positions.size(); ++v) out.positions[v] += distance * mesh.normals[v];
  compute_normals(out);
  return out;
}

Scene enlarged_scene(const Scene& sketchy) {
  float enlarge = sketchy.params.get<SketchyParams>().enlarge;
  Scene out = sketchy;
  for (SceneObject& o : out.objects)
    o.mesh = std::make_shared<Mesh>(enlarged_mesh(*o.mesh, enlarge * o.mesh->bbox_diagonal()));
  return out;
}

std::vector<glm::vec3> noise_coordinates(const Mesh& enlarged) {
  float diagonal = enlarged.bbox_diagonal();
  float scale = diagonal > 0 ? 1.0f / diagonal : 1.0f;
  std::vector<glm::vec3> out;
  out.reserve(enlarged.positions.size());
  for (const glm::vec3& p : enlarged.positions) out.push_back(p * scale);
  return out;
}

float sketch_reach(const SketchyParams& p) {
  auto frobenius = [](const glm::mat2& m) { return std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1])); };
  float uv = (p.style == SketchyStyle::Rough ? 0.5f : 1.5f) * std::sqrt(2.0f);
  return uv * std::max(frobenius(edge_matrix(p)), frobenius(shade_matrix(p)));
}

PixelRect composite_rect(const Scene& sketchy, int width, int height) {
  return covered_rect(sketchy, width, height, sketch_reach(sketchy.params.get<SketchyParams>()) + 3);
}

glm::mat2 edge_matrix(const SketchyParams& p) { return glm::mat2(p.edge_a, p.edge_c, p.edge_b, p.edge_d); }
glm::mat2 shade_matrix(const SketchyParams& p) { return glm::mat2(p.shade_a, p.shade_c, p.shade_b, p.shade_d); }

glm::mat2 copy_matrix(const SketchyParams& p, int k) {
  float a = glm::radians(p.copy_rotation_deg) * float(k), c = std::cos(a), s = std::sin(a);
  return glm::mat2(c, s, -s, c) * edge_matrix(p);
}

glm::vec3 copy_ink(const SketchyParams& p, int k) {
  float t = p.edge_copies > 1 ? float(k) / float(p.edge_copies - 1) : 0.0f;
  return t * glm::vec3(p.copy_red, p.copy_green, p.copy_blue);
}

glm::vec2 copy_noise_shift(int k) { return float(k) * glm::vec2(0.37f, 0.61f); }

SketchyNoise make_sketchy_noise(const ParamSet& params, uint32_t seed) {
  auto p = params.get<SketchyParams>();
  auto n = params.get<NoiseTextureParams>();
  SketchyNoise out;
  if (p.style == SketchyStyle::Rough)
    out.white = white_noise_texture(n.size, seed);
  else if (p.style == SketchyStyle::Object)
    out.perlin_3d = perlin_noise_texture_3d(p.noise3d_size, p.noise3d_period, seed);
  else
    out.perlin = perlin_noise_texture(n, seed);
  return out;
}

}  // namespace plumbago

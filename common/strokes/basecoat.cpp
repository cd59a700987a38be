#include "common/strokes/basecoat.hpp"

#include <cmath>

#include "common/scene/gbuffer.hpp"
#include "common/scene/lights.hpp"

namespace plumbago {

Image basecoat_texture(const BaseCoatParams& p) {
  const glm::vec4 dark(p.dark_r, p.dark_g, p.dark_b, p.dark_a), light(p.light_r, p.light_g, p.light_b, p.light_a);
  Image t(kBaseCoatTexels, 1, 4);
  for (int k = 0; k < kBaseCoatTexels; ++k) {
    float s = (float(k) + 0.5f) / float(kBaseCoatTexels);  // the texel's center
    glm::vec4 c = p.preset == BaseCoatPreset::Solid    ? light
                  : p.preset == BaseCoatPreset::Smooth ? glm::mix(dark, light, s)
                  : s < p.threshold                    ? dark
                                                       : light;
    for (int ch = 0; ch < 4; ++ch) t.at(k, 0, ch) = c[ch];
  }
  return t;
}

namespace {

// s = sum_k I_k (n . L_k), or of |n . L_k| (Kalnins et al. 2002, §4.2).
float vertex_shade(glm::vec3 n, const std::vector<Light>& unit_lights, const BaseCoatParams& p) {
  float s = 0;
  for (const Light& l : unit_lights) {
    float d = glm::dot(n, l.direction);
    s += l.intensity * (p.abs_n_dot_l ? std::abs(d) : d);
  }
  return s;
}

}  // namespace

TriangleShades triangle_shades(const Scene& scene, const BaseCoatParams& p) {
  std::vector<Light> lights = unit_world_lights(scene);
  TriangleShades out;
  std::vector<WorldObject> objects = world_geometry(scene);
  for (size_t o = 0; o < objects.size(); ++o) {
    const WorldObject& obj = objects[o];
    out.first_triangle.push_back(uint32_t(out.corners.size()));
    for (const glm::uvec3& t : obj.triangles) {
      glm::vec4 record(0.0f, 0.0f, 0.0f, scene.objects[o].style == Style::Strokes ? 1.0f : 0.0f);
      for (int k = 0; k < 3; ++k) record[k] = vertex_shade(obj.normals[t[k]], lights, p);
      out.corners.push_back(record);
    }
  }
  return out;
}

}  // namespace plumbago

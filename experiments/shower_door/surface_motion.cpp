#include "experiments/shower_door/surface_motion.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "reference/util/rows.hpp"

namespace plumbago::shower_door {

Camera orbit(const Camera& c, float degrees) {
  glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(c.up));
  Camera out = c;
  out.eye = c.target + glm::vec3(turn * glm::vec4(c.eye - c.target, 0.0f));
  return out;
}

Image surface_points(const std::vector<WorldObject>& objects, const GBuffer& g) {
  int w = g.ids.width, h = g.ids.height;
  Image out(w, h, 4);
  reference::for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (g.background(x, y)) continue;
      const WorldObject& obj = objects[g.ids.at(x, y, 0) - 1];
      const glm::uvec3& tri = obj.triangles[g.ids.at(x, y, 1)];
      glm::vec3 p(0.0f);
      for (int k = 0; k < 3; ++k) p += g.bary.at(x, y, k) * obj.positions[tri[k]];
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = p[c];
      out.at(x, y, 3) = 1.0f;
    }
  });
  return out;
}

glm::vec3 project(const Camera& c, int width, int height, glm::vec3 x) {
  glm::vec4 view = c.view() * glm::vec4(x, 1.0f);
  glm::vec4 clip = c.projection(float(width) / float(height)) * view;
  glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x + 1.0f) * 0.5f * float(width), (ndc.y + 1.0f) * 0.5f * float(height), -view.z};
}

namespace {

// True when the four pixel centers around window point q (those a bilinear read of the
// previous frame mixes) all lie inside the image and see surface points within
// `tolerance` of x: x was visible there, away from any silhouette or occlusion edge.
bool seen_around(const Image& points, glm::vec2 q, glm::vec3 x, float tolerance) {
  int x0 = int(std::floor(q.x - 0.5f)), y0 = int(std::floor(q.y - 0.5f));
  for (int j = y0; j <= y0 + 1; ++j)
    for (int i = x0; i <= x0 + 1; ++i) {
      if (i < 0 || j < 0 || i >= points.width || j >= points.height || points.at(i, j, 3) == 0.0f) return false;
      if (glm::length(glm::vec3(points.at(i, j, 0), points.at(i, j, 1), points.at(i, j, 2)) - x) > tolerance)
        return false;
    }
  return true;
}

}  // namespace

Image surface_motion(const Camera& prev, const Image& prev_points, const Image& next_points,
                     const MotionParams& params) {
  int w = next_points.width, h = next_points.height;
  // World size of one pixel at depth d: 2 d tan(fov / 2) / height (docs/conventions.md's pinhole).
  float pixel_per_depth = 2.0f * std::tan(glm::radians(prev.fov_deg) * 0.5f) / float(h);
  Image out(w, h, 3);
  reference::for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (next_points.at(x, y, 3) == 0.0f) continue;
      glm::vec3 point(next_points.at(x, y, 0), next_points.at(x, y, 1), next_points.at(x, y, 2));
      glm::vec3 q = project(prev, w, h, point);
      if (q.z <= 0 || !seen_around(prev_points, glm::vec2(q), point, params.footprints * pixel_per_depth * q.z))
        continue;
      glm::vec2 center(float(x) + 0.5f, float(y) + 0.5f);
      if (glm::length(glm::vec2(q) - center) < params.min_motion_px) continue;
      out.at(x, y, 0) = q.x, out.at(x, y, 1) = q.y, out.at(x, y, 2) = 1.0f;
    }
  });
  return out;
}

}  // namespace plumbago::shower_door

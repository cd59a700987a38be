#include "reference/pencil/edge_detect.hpp"

#include <algorithm>
#include <glm/glm.hpp>

#include "reference/core/stage.hpp"
#include "reference/util/rows.hpp"

namespace plumbago::reference {

namespace {

// Window-space neighborhood of Nienhaus & Döllner 2003, as given in Pacheco §2, y up:  A B C / D X E / F G H.
struct Diagonals {
  int ax, ay, hx, hy, cx, cy, fx, fy;
};

Diagonals diagonals(int x, int y, int w, int h) {
  int left = std::max(x - 1, 0), right = std::min(x + 1, w - 1);  // clamp to edge
  int down = std::max(y - 1, 0), up = std::min(y + 1, h - 1);
  return {left, up, right, down, right, up, left, down};
}

glm::vec3 normal_at(const Image& n, int x, int y) { return {n.at(x, y, 0), n.at(x, y, 1), n.at(x, y, 2)}; }

// z = (d - near) / (far - near) (docs/conventions.md).
float normalized_depth_at(const GBuffer& g, int x, int y) { return (g.depth.at(x, y) - g.near) / (g.far - g.near); }

// N_1.N_2, with the background reading of common/pencil/edge_detect.hpp.
float normal_agreement(glm::vec3 n1, glm::vec3 n2, BackgroundPairs mode) {
  bool both_background = glm::dot(n1, n1) == 0.0f && glm::dot(n2, n2) == 0.0f;
  return both_background && mode == BackgroundPairs::Continuous ? 1.0f : glm::dot(n1, n2);
}

// I_n = clamp(1/2 (N_A.N_H + N_C.N_F), 0, 1)
float normal_intensity(const Image& n, const Diagonals& d, BackgroundPairs mode) {
  float s = normal_agreement(normal_at(n, d.ax, d.ay), normal_at(n, d.hx, d.hy), mode) +
            normal_agreement(normal_at(n, d.cx, d.cy), normal_at(n, d.fx, d.fy), mode);
  return std::clamp(0.5f * s, 0.0f, 1.0f);
}

// One factor of I_z: (1 - min(1, s/2 |z_1 - z_2|))^2
float depth_factor(float z1, float z2, float s) {
  float f = 1.0f - std::min(1.0f, 0.5f * s * std::abs(z1 - z2));
  return f * f;
}

// I_z = (1 - min(1, s/2 |z_A - z_H|))^2 (1 - min(1, s/2 |z_C - z_F|))^2
float depth_intensity(const GBuffer& g, const Diagonals& d, float s) {
  return depth_factor(normalized_depth_at(g, d.ax, d.ay), normalized_depth_at(g, d.hx, d.hy), s) *
         depth_factor(normalized_depth_at(g, d.cx, d.cy), normalized_depth_at(g, d.fx, d.fy), s);
}

}  // namespace

Image contour_darkness(const GBuffer& g, const EdgeDetectParams& p) {
  const Image& normals = p.normals == EdgeNormals::Face ? g.face_normal : g.normal;
  int w = g.depth.width, h = g.depth.height;
  Image out(w, h, 1);
  for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      Diagonals d = diagonals(x, y, w, h);
      out.at(x, y) = 1.0f - normal_intensity(normals, d, p.background_pairs) * depth_intensity(g, d, p.depth_scale);
    }
  });
  return out;
}

PLUMBAGO_REFERENCE_STAGE(edge_detect, [](ReferenceFrame& f) {
  f.put(kContourDarkness, contour_darkness(f.get(kGBuffer), f.params<EdgeDetectParams>()));
});

}  // namespace plumbago::reference

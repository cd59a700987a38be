// The scalar triangle rasterizer of the reference (docs/conventions.md; Kalnins et al. 2002, §4.6; §4.1): what a GPU
// does with a window-space triangle, written out so that the reference draws exactly the triangles
// the GPU draws (the ID image, the stroke ribbons).
//   - vertices snapped to 1/2^kSubpixelBits px (common/strokes/id_image.hpp);
//   - a pixel is covered when its center lies inside, or on a top or left edge (window
//     y up; either winding);
//   - attributes interpolated with the window barycentrics (affine in window space).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

#include <glm/glm.hpp>

#include "common/strokes/id_image.hpp"
#include "common/util/image.hpp"

namespace plumbago::reference {

inline glm::dvec2 snapped(glm::vec2 p) {
  const double s = double(1 << kSubpixelBits);
  return {std::round(double(p.x) * s) / s, std::round(double(p.y) * s) / s};
}

namespace detail {
// Twice the signed area of (a, b, p): positive when p lies left of a -> b.
inline double edge(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}
// An edge of a counter-clockwise triangle (y up) whose points count as inside: a left edge
// runs downwards, a top edge is horizontal and runs leftwards.
inline bool top_left(glm::dvec2 a, glm::dvec2 b) { return b.y < a.y || (b.y == a.y && b.x < a.x); }
}  // namespace detail

// Calls covered(x, y, w, edge) for each pixel of `clip` that triangle (p0, p1, p2) covers, w
// its barycentric weights of the corners; `edge` says the pixel center lies within
// `edge_px` of an edge, where a rasterizer with other rounding may decide otherwise. With
// edge_px > 0 it is also called (edge = true, w outside [0, 1]) for the pixels just outside.
template <class Covered>
void rasterize_triangle(glm::vec2 p0, glm::vec2 p1, glm::vec2 p2, const PixelRect& clip, double edge_px,
                        const Covered& covered) {
  glm::dvec2 v[3] = {snapped(p0), snapped(p1), snapped(p2)};
  double area = detail::edge(v[0], v[1], v[2]);
  if (area == 0 || !std::isfinite(area)) return;
  bool flipped = area < 0;
  if (flipped) std::swap(v[1], v[2]), area = -area;  // counter-clockwise from here on
  double length[3];
  for (int k = 0; k < 3; ++k) length[k] = glm::distance(v[(k + 1) % 3], v[(k + 2) % 3]);
  int x0 = std::max(clip.x0, int(std::floor(std::min({v[0].x, v[1].x, v[2].x}) - 0.5 - edge_px)));
  int x1 = std::min(clip.x1 - 1, int(std::ceil(std::max({v[0].x, v[1].x, v[2].x}) - 0.5 + edge_px)));
  int y0 = std::max(clip.y0, int(std::floor(std::min({v[0].y, v[1].y, v[2].y}) - 0.5 - edge_px)));
  int y1 = std::min(clip.y1 - 1, int(std::ceil(std::max({v[0].y, v[1].y, v[2].y}) - 0.5 + edge_px)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      glm::dvec2 c(x + 0.5, y + 0.5);
      double e[3];
      bool inside = true, near_edge = false, near_inside = true;
      for (int k = 0; k < 3; ++k) {
        glm::dvec2 a = v[(k + 1) % 3], b = v[(k + 2) % 3];  // the edge opposite corner k
        e[k] = detail::edge(a, b, c);
        inside = inside && (e[k] > 0 || (e[k] == 0 && detail::top_left(a, b)));
        near_edge = near_edge || std::abs(e[k]) <= edge_px * length[k];
        near_inside = near_inside && e[k] >= -edge_px * length[k];
      }
      if (!inside && !(edge_px > 0 && near_edge && near_inside)) continue;
      glm::dvec3 w(e[0] / area, e[1] / area, e[2] / area);
      if (flipped) std::swap(w[1], w[2]);  // back to the caller's corner order
      covered(x, y, w, !inside || near_edge);
    }
}

// Draws triangles (three vertices each, window position `position(v)`) in order into a
// window of `height` rows: bands of rows in parallel, each drawing the triangles that touch
// it in their order, with draw(first vertex, y0, y1) limited to rows [y0, y1).
template <class Vertex, class Position, class Draw>
void draw_in_bands(const std::vector<Vertex>& v, int height, const Position& position, const Draw& draw) {
  constexpr int kBand = 16;
  int bands = (height + kBand - 1) / kBand;
  std::vector<std::vector<size_t>> binned(static_cast<size_t>(bands));
  for (size_t t = 0; t + 2 < v.size(); t += 3) {
    float lo = std::min({position(v[t]).y, position(v[t + 1]).y, position(v[t + 2]).y});
    float hi = std::max({position(v[t]).y, position(v[t + 1]).y, position(v[t + 2]).y});
    if (!(hi >= 0) || !(lo < float(height))) continue;
    int first = int(std::max(lo, 0.0f)) / kBand, last = int(std::min(hi, float(height))) / kBand;
    for (int b = std::max(0, first - 1); b <= std::min(bands - 1, last + 1); ++b) binned[size_t(b)].push_back(t);
  }
  tbb::parallel_for(0, bands, [&](int b) {
    for (size_t t : binned[size_t(b)]) draw(&v[t], b * kBand, std::min(height, (b + 1) * kBand));
  });
}

}  // namespace plumbago::reference

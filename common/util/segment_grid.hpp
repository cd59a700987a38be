// Line segments in a window, on a grid of square cells, for nearest-point queries: what the
// coherent silhouettes' votes (common/strokes/coherent_silhouettes.cpp) and the
// temporal-coherence study's landings (experiments/temporal_coherence/stroke_track.cpp) search.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace plumbago {

// The nearest point to `q` of the segment from a to b: its share t along it and its distance.
inline std::pair<double, double> nearest_on(glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) {
  glm::dvec2 d = b - a;
  double len2 = glm::dot(d, d);
  double t = len2 > 0 ? std::clamp(glm::dot(q - a, d) / len2, 0.0, 1.0) : 0.0;
  return {t, glm::distance(a + t * d, q)};
}

// Segments by index over a width x height window in cells of `cell` px; a segment is in
// every cell its bounding box touches, and what lies outside the window is in the border
// cells.
class SegmentGrid {
 public:
  SegmentGrid(int width, int height, double cell)
      : cell_(cell),
        columns_(int(std::ceil(width / cell)) + 1),
        rows_(int(std::ceil(height / cell)) + 1),
        cells_(size_t(columns_) * size_t(rows_)) {}

  void add(glm::dvec2 a, glm::dvec2 b, uint32_t index) {
    for (size_t c : cells(glm::min(a, b), glm::max(a, b))) cells_[c].push_back(index);
  }

  // Calls visit(index) for the segments in the cells that the box [lo, hi] touches (a
  // segment may come more than once).
  template <class Visit>
  void near(glm::dvec2 lo, glm::dvec2 hi, const Visit& visit) const {
    for (size_t c : cells(lo, hi))
      for (uint32_t i : cells_[c]) visit(i);
  }

 private:
  int index(double v, int n) const { return std::clamp(int(std::floor(std::clamp(v / cell_, -1e9, 1e9))), 0, n - 1); }

  std::vector<size_t> cells(glm::dvec2 lo, glm::dvec2 hi) const {
    std::vector<size_t> out;
    for (int y = index(lo.y, rows_); y <= index(hi.y, rows_); ++y)
      for (int x = index(lo.x, columns_); x <= index(hi.x, columns_); ++x)
        out.push_back(size_t(y) * size_t(columns_) + size_t(x));
    return out;
  }

  double cell_;
  int columns_, rows_;
  std::vector<std::vector<uint32_t>> cells_;
};

}  // namespace plumbago

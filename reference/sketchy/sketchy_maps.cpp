#include "reference/sketchy/sketchy_maps.hpp"
#include "common/sketchy/sketchy_maps.hpp"

#include <algorithm>

#include "common/sketchy/sketchy.hpp"
#include "reference/core/stage.hpp"
#include "reference/pencil/edge_detect.hpp"
#include "reference/util/rows.hpp"

namespace plumbago::reference {

namespace {

// The nearest linear depth among X and its diagonals (clamped to the window).
float edge_depth(const GBuffer& g, int x, int y) {
  int w = g.depth.width, h = g.depth.height;
  float nearest = g.depth.at(x, y);
  for (int dy : {-1, 1})
    for (int dx : {-1, 1})
      nearest = std::min(nearest, g.depth.at(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1)));
  return nearest;
}

}  // namespace

SketchyMaps sketchy_maps(const GBuffer& g, const std::vector<glm::vec3>& colors, const EdgeDetectParams& p) {
  Image darkness = contour_darkness(g, p);
  int w = g.depth.width, h = g.depth.height;
  SketchyMaps maps{Image(w, h, 2), Image(w, h, 4)};
  for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      maps.edge.at(x, y, 0) = darkness.at(x, y);
      maps.edge.at(x, y, 1) = edge_depth(g, x, y);
      uint32_t id = g.ids.at(x, y, 0);
      if (id == 0) continue;
      for (int c = 0; c < 3; ++c) maps.shade.at(x, y, c) = colors[id - 1][c];
      maps.shade.at(x, y, 3) = 1.0f;
    }
  });
  return maps;
}

PLUMBAGO_REFERENCE_STAGE(sketchy_maps, [](ReferenceFrame& f) {
  SketchyMaps maps = sketchy_maps(f.get(kSketchyGBuffer), object_colors(f.sketchy), f.params<EdgeDetectParams>());
  f.put(kSketchyEdge, std::move(maps.edge));
  f.put(kSketchyShade, std::move(maps.shade));
});

}  // namespace plumbago::reference

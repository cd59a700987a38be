#include "common/pencil/multi_contour.hpp"

#include "common/pencil/distortion.hpp"
#include "common/pencil/edge_detect.hpp"

namespace plumbago {

PixelRect contour_rect(const Scene& scene, const std::vector<Image>& grids) {
  if (background_darkness(scene.params.get<EdgeDetectParams>()) != 0.0f) return {0, 0, scene.width, scene.height};
  return covered_rect(scene, scene.width, scene.height, largest_offset(grids) + 3);
}

}  // namespace plumbago

#include "common/contour_texture.hpp"

#include <algorithm>

#include "common/multi_contour.hpp"
#include "common/pencil_textures.hpp"
#include "common/preprocess.hpp"

namespace plumbago {

void ContourTextureStage::make(const Scene& scene, Preprocessed& out) {
  auto pencil = scene.params.get<PencilTexturesParams>();
  int layer = std::min(scene.params.get<ContourParams>().texture_layer, pencil.layers - 1);
  out.contour_texture = out.pencil_stack.empty() ? pencil_layers(pencil, scene.seed, layer).back()
                                                 : out.pencil_stack[size_t(layer)];
}

}  // namespace plumbago

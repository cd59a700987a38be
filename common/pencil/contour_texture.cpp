#include "common/pencil/contour_texture.hpp"

#include <algorithm>

#include "common/pencil/multi_contour.hpp"
#include "common/pencil/pencil_textures.hpp"
#include "common/core/preprocess.hpp"

namespace plumbago {

int ContourTextureStage::layer(const ParamSet& params) {
  return std::min(params.get<ContourParams>().texture_layer, params.get<PencilTexturesParams>().layers - 1);
}

void ContourTextureStage::make(const Scene& scene, Preprocessed& out) {
  int l = layer(scene.params);
  out.contour_texture = out.pencil_stack.empty()
                            ? pencil_layers(scene.params.get<PencilTexturesParams>(), scene.seed, l).back()
                            : out.pencil_stack[size_t(l)];
}

}  // namespace plumbago

#include "common/pencil/contour_texture.hpp"

#include <algorithm>

#include "common/core/preprocess.hpp"
#include "common/pencil/multi_contour.hpp"
#include "common/pencil/pencil_textures.hpp"

namespace plumbago {

int ContourTextureStage::layer(const ParamSet& params) {
  return std::min(params.get<ContourParams>().texture_layer, params.get<PencilTexturesParams>().layers - 1);
}

void ContourTextureStage::make(const Scene& scene, Preprocessed& out) {
  int l = layer(scene.params);
  const std::vector<Image>* stack = out.get(maybe(kPencilStack));
  out.put(kContourTexture,
          stack ? (*stack)[size_t(l)] : pencil_layers(scene.params.get<PencilTexturesParams>(), scene.seed, l).back());
}

}  // namespace plumbago

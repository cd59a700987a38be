// The contour texture (Lee et al. 2006, §5.1, Eq. 3-4; §4.2-4.3): the layer `contour.texture_layer` of the pencil
// stack (the last layer when the stack has fewer), which breaks up the contour copies.
#pragma once

#include "common/core/stage.hpp"
#include "common/util/image.hpp"

namespace plumbago {

struct Scene;
struct Preprocessed;
inline constexpr Slot<Image> kContourTexture{"contour_texture.texture"};  // T_c

struct ContourTextureStage {
  using Params = TypeList<>;
  // The stack's own layer when the stack was made; else only the layers up to it.
  static void make(const Scene& scene, Preprocessed& out);
  // The layer: contour.texture_layer, or the stack's last when it has fewer.
  static int layer(const ParamSet& params);
  static StageDesc describe() {
    return {.name = "contour_texture",
            .kind = StageKind::Preprocessing,
            .doc = "the pencil layer used as contour texture (Lee et al. 2006, §5.1)",
            .params = {"contour", "pencil_textures"},
            .outputs = {{.handle = kContourTexture, .texel = Texel::Host, .doc = "T_c"}},
            .preprocess = make};
  }
};

}  // namespace plumbago

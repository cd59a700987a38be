// The noise textures of sketchy drawing's uncertainty (Nienhaus & Döllner 2004, §3.2; §3.4, §4; common/util/noise.hpp),
// only what sketchy.style reads.
#pragma once

#include "common/core/stage.hpp"
#include "common/util/noise.hpp"

namespace plumbago {

struct Scene;
struct Preprocessed;
struct SketchyNoise;
inline constexpr Slot<SketchyNoise> kSketchyNoise{"sketchy_noise.textures"};

struct SketchyNoiseStage {
  using Params = TypeList<NoiseTextureParams>;
  static void make(const Scene& scene, Preprocessed& out);
  static StageDesc describe() {
    return {.name = "sketchy_noise",
            .kind = StageKind::Preprocessing,
            .doc = "noise textures of the sketchy uncertainty (Nienhaus & Döllner 2004, §3.2, §3.4)",
            .params = {"noise", "sketchy"},
            .outputs = {{.handle = kSketchyNoise,
                         .channels = 2,
                         .texel = Texel::Host,
                         .doc = "2D Perlin, white noise or 3D Perlin, as the style reads"}},
            .preprocess = make};
  }
};

}  // namespace plumbago

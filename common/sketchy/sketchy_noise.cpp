#include "common/sketchy/sketchy_noise.hpp"

#include "common/core/preprocess.hpp"
#include "common/sketchy/sketchy.hpp"

namespace plumbago {

void SketchyNoiseStage::make(const Scene& scene, Preprocessed& out) {
  out.put(kSketchyNoise, make_sketchy_noise(scene.params, scene.seed));
}

}  // namespace plumbago

#include "common/sketchy/sketchy_noise.hpp"

#include "common/core/preprocess.hpp"

namespace plumbago {

void SketchyNoiseStage::make(const Scene& scene, Preprocessed& out) {
  out.sketchy_noise = make_sketchy_noise(scene.params, scene.seed);
}

}  // namespace plumbago

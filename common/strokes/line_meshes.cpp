#include "common/strokes/line_meshes.hpp"

#include "common/core/preprocess.hpp"

namespace plumbago {

void LineMeshesStage::make(const Scene& scene, Preprocessed& out) {
  out.put(kLineMeshes, line_meshes(scene, scene.params.get<StrokesParams>(), LineObjects::Strokes));
}

}  // namespace plumbago

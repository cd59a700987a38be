#include "common/core/preprocess.hpp"

#include <algorithm>

#include "common/core/stage.hpp"
#include "common/mesh/mesh.hpp"

namespace plumbago {

Preprocessed preprocess(const Scene& scene, const std::vector<std::string>& passes) {
  for (const SceneObject& object : scene.objects) validate_drawable_mesh(*object.mesh);
  Preprocessed out;
  for (const StageDesc& stage : stage_table()) {
    if (stage.kind != StageKind::Preprocessing) continue;
    if (std::find(passes.begin(), passes.end(), stage.name) == passes.end()) continue;
    Stopwatch w;
    stage.preprocess(scene, out);
    out.ran.push_back({stage.name, w.ms()});
  }
  return out;
}

}  // namespace plumbago

// The brush parameters of coherent silhouettes, CPU reference (Kalnins et al. 2003; the method
// in common/strokes/coherent_silhouettes.hpp, the stage in common/strokes/brush_parameters.hpp):
// the previous frame's brush samples vote, each run's votes are fitted, and this frame's
// strokes are sampled for the next.
#include "common/strokes/brush_parameters.hpp"

#include "reference/core/stage.hpp"

namespace plumbago::reference {

PLUMBAGO_REFERENCE_STAGE(brush_parameters, [](ReferenceFrame& f) {
  const WindowLines& lines = f.get(kWindowLines);
  const Visibility& visibility = f.get(kVisibleRuns);
  const auto p = f.params<CoherenceParams>();
  std::vector<RunBrush> brushes(visibility.runs.size());  // none voted for: t = s, new brush paths
  if (const std::vector<BrushSample>* previous = f.before(kBrushSamples))
    brushes = coherent_parameters(*previous, f.scene.camera, lines, visibility, p);
  f.put(kBrushSamples, brush_samples(lines, visibility, brushes, p, f.scene.seed));
  f.put(kBrushParameters, std::move(brushes));
});

}  // namespace plumbago::reference

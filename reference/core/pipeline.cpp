#include "reference/core/pipeline.hpp"

#include "common/core/passes.hpp"
#include "common/core/preprocess.hpp"
#include "common/sketchy/sketchy.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/silhouette_chains.hpp"
#include "common/strokes/stroke.hpp"
#include "common/strokes/visibility.hpp"

namespace plumbago::reference {

ReferenceFrame run_stages(const Scene& scene, std::vector<PassTime>& ran, const DataTable* previous) {
  check_implementations();
  std::vector<std::string> all = passes_for(scene.effects, scene.params);
  ReferenceFrame f(scene, preprocess(scene, all), frame_stages(all));
  f.previous = previous;
  ran = f.pre.ran;
  for (const std::string& name : f.stages) {
    Stopwatch watch;
    run_stage(f, name);
    ran.push_back({name, watch.ms()});
  }
  return f;
}

Frame render(const Scene& scene, const FrameOptions& options) {
  Frame frame;
  ReferenceFrame f = run_stages(scene, frame.ran, options.carry ? options.carry->before(scene.frame) : nullptr);
  f.previous = nullptr;
  if (options.carry) *options.carry = {scene.frame, f.data};
  std::string color = frame_color_buffer(f.stages);  // none without effects: the blank page
  frame.color = color.empty() ? Image(scene.width, scene.height, 3, 1.0f) : f.images.at(color);
  if (options.keep_buffers) {
    frame.buffers = dump(f);
    frame.lines = kept(f.get(maybe(kWindowLines))), frame.visibility = kept(f.get(maybe(kVisibleRuns)));
  }
  frame.counts = stroke_counts(f.get(maybe(kWindowLines)), f.get(maybe(kVisibleRuns)));
  frame.counts.merge(silhouette_counts(f.get(maybe(kSegmentFacing)), f.get(maybe(kChains))));
  return frame;
}

}  // namespace plumbago::reference

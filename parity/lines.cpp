#include "parity/lines.hpp"

#include <stdexcept>
#include <string>

#include "common/strokes/id_image.hpp"
#include "common/strokes/stroke.hpp"
#include "gpu/core/pipeline.hpp"
#include "reference/core/pipeline.hpp"

namespace plumbago {
namespace {

// The scene with every object but the sketchy ones drawn with strokes: its frame's ID image
// holds all their lines.
Scene lines_scene(const Scene& scene) {
  Scene s = scene;
  for (SceneObject& o : s.objects)
    if (o.style != Style::Sketchy) o.style = Style::Strokes;
  s.effects = {"strokes"};
  if (!sketchy_objects(scene).objects.empty()) s.effects.push_back("sketchy");
  return s;
}

Frame strokes_frame(const Scene& scene, const std::string& backend) {
  FrameOptions keep{true};
  return backend == "reference" ? reference::render(scene, keep) : gpu::Renderer(scene).render(keep);
}

}  // namespace

SceneLines scene_lines(const Scene& scene, const std::string& backend) {
  SceneLines out{lines_scene(scene)};
  out.frame = strokes_frame(out.scene, backend);
  if (!out.frame.lines || !out.frame.visibility)
    throw std::logic_error("the " + backend + " strokes frame kept no lines or runs");
  out.lines = *out.frame.lines;  // the lines the frame made and tested, and the runs it found
  out.visibility = *out.frame.visibility;
  out.keys = keys_from_channels(out.frame.buffers.at(kIds.name));
  if (out.scene.params.get<StrokesParams>().crease_under_silhouettes)
    out.crease_keys = keys_from_channels(out.frame.buffers.at(kCreaseIds.name));
  for (VisibleRun& r : out.visibility.runs)  // the GPU frame's: their polylines were made on the GPU
    if (r.window.empty())
      r = run_along(out.lines.paths.at(r.path), r.path, r.s0, r.s1, r.closed, r.occluded_start, r.occluded_end);
  return out;
}

std::vector<bool> points_visible(const WindowPath& path, const SceneLines& found) {
  const ImageU32* under = found.crease_keys ? &*found.crease_keys : nullptr;
  std::vector<bool> out;
  for (size_t k = 0; k < path.window.size(); ++k)
    out.push_back(path.front_facing && sample_visible(found.keys, under, sample_at(path, path.arc_px[k])));
  return out;
}

}  // namespace plumbago

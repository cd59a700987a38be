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

// The runs a GPU frame listed (its visibility.run_paths and run_ends tables, whose rows end
// at the first path 0), along `lines`, the paths that frame tested.
Visibility frame_visibility(const Frame& frame, const WindowLines& lines) {
  const Image &paths = frame.buffers.at(kRunPaths.name), &ends = frame.buffers.at(kRunEnds.name);
  Visibility v;
  for (size_t k = 0; k < paths.pixels() && paths.data[2 * k] > 0; ++k) {
    auto path = uint32_t(paths.data[2 * k]) - 1, flags = uint32_t(paths.data[2 * k + 1]);
    if (path >= lines.paths.size())
      throw std::logic_error("the GPU frame's run " + std::to_string(k) + " is on path " + std::to_string(path) +
                             " of " + std::to_string(lines.paths.size()));
    v.runs.push_back(run_from_row(lines.paths[path], path, ends.data[2 * k], ends.data[2 * k + 1], flags));
  }
  return v;
}

}  // namespace

SceneLines scene_lines(const Scene& scene, const std::string& backend) {
  SceneLines out{lines_scene(scene)};
  auto p = out.scene.params.get<StrokesParams>();
  out.frame = strokes_frame(out.scene, backend);
  if (!out.frame.lines) throw std::logic_error("the " + backend + " strokes frame kept no lines");
  out.lines = *out.frame.lines;  // the lines the frame made and tested
  out.keys = keys_from_channels(out.frame.buffers.at(kIds.name));
  if (backend != "reference") {
    out.visibility = frame_visibility(out.frame, out.lines);
    return out;
  }
  const ImageU32& keys = out.keys;  // the reference's runs in double, as its frame made them
  auto test = [&keys](const std::vector<VisibilitySample>& batch) {
    std::vector<uint8_t> flags;
    for (const VisibilitySample& s : batch) flags.push_back(sample_visible(keys, s));
    return flags;
  };
  out.visibility = visible_runs(out.lines, p, test);
  return out;
}

std::vector<bool> points_visible(const WindowPath& path, const ImageU32& keys) {
  std::vector<bool> out;
  for (size_t k = 0; k < path.window.size(); ++k)
    out.push_back(path.front_facing && sample_visible(keys, sample_at(path, path.arc_px[k])));
  return out;
}

}  // namespace plumbago

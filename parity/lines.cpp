#include "parity/lines.hpp"

#include <stdexcept>
#include <string>

#include "common/strokes/decal.hpp"
#include "common/strokes/id_image.hpp"
#include "common/strokes/silhouette_paths.hpp"
#include "common/strokes/stroke.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/gl/context.hpp"
#include "gpu/strokes/decal.hpp"
#include "reference/core/pipeline.hpp"
#include "reference/strokes/decal.hpp"

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

// The decals' surface points, projected as the backend's frames project them.
DecalSurface decal_surface(const Scene& scene, const std::string& backend) {
  if (!has_decals(scene)) return {};
  if (backend == "reference") return reference::project_decals_by_rays(scene);
  gpu::Context::get();  // before any GL call
  return gpu::project_decals_through_gbuffer(scene);
}

// The silhouettes a GPU frame chained itself, from its tables (common/strokes/silhouette_paths.hpp).
std::vector<ChainPath> frame_silhouettes(const Scene& scene, const LineMeshes& meshes, const Frame& frame,
                                         bool normalized) {
  auto table = [&](const Buffer& b) { return frame.buffers.at(b.name).data; };
  return chain_paths(scene, meshes, table(kSilhouettePaths), table(kSilhouetteCrossings), normalized);
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
  DecalSurface decals = decal_surface(out.scene, backend);
  out.frame = strokes_frame(out.scene, backend);
  std::shared_ptr<const LineMeshes> meshes = line_meshes(out.scene, p, LineObjects::Strokes);
  std::vector<ChainPath> gpu_silhouettes;
  if (backend != "reference")
    gpu_silhouettes = frame_silhouettes(out.scene, *meshes, out.frame, p.silhouette_normalized);
  out.lines = window_lines(out.scene, p, LineObjects::Strokes, meshes.get(), &decals,
                           backend != "reference" ? &gpu_silhouettes : nullptr);
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

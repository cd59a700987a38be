#include "common/preprocess.hpp"

#include <algorithm>

#include "common/distortion.hpp"
#include "common/pencil_texture.hpp"

namespace plumbago {

namespace {

bool has(const std::vector<std::string>& passes, const char* name) {
  return std::find(passes.begin(), passes.end(), name) != passes.end();
}

}  // namespace

Preprocessed preprocess(const Scene& scene, const std::vector<std::string>& passes) {
  Preprocessed out;
  auto contour = scene.params.get<ContourParams>();
  if (has(passes, "distortion")) {
    Stopwatch w;
    out.offset_grids = distortion_grids(contour, scene.width, scene.height, scene.seed);
    out.texture_shifts = contour_texture_shifts(contour, scene.seed);
    out.ran.push_back({"distortion", w.ms()});
  }
  auto pencil = scene.params.get<PencilParams>();
  int contour_layer = std::min(contour.texture_layer, pencil.layers - 1);
  if (has(passes, "pencil_textures")) {
    Stopwatch w;
    out.pencil_stack = pencil_layers(pencil, scene.seed);
    out.ran.push_back({"pencil_textures", w.ms()});
  }
  if (has(passes, "contour_texture")) {  // the stack's own layer; only the layers up to it when alone
    Stopwatch w;
    out.contour_texture = out.pencil_stack.empty() ? pencil_layers(pencil, scene.seed, contour_layer).back()
                                                   : out.pencil_stack[size_t(contour_layer)];
    out.ran.push_back({"contour_texture", w.ms()});
  }
  if (has(passes, "paper")) {
    Stopwatch w;
    out.paper = make_paper(scene.params.get<PaperParams>(), scene.seed);
    out.ran.push_back({"paper", w.ms()});
  }
  if (has(passes, "sketchy_noise")) {
    Stopwatch w;
    out.sketchy_noise = make_sketchy_noise(scene.params, scene.seed);
    out.ran.push_back({"sketchy_noise", w.ms()});
  }
  if (has(passes, "curvature")) {
    Stopwatch w;
    auto params = scene.params.get<CurvatureParams>();
    CurvatureOptions options;
    options.progress = false;
    for (const auto& obj : scene.objects) out.curvature.push_back(compute_curvature(*obj.mesh, params, options));
    out.ran.push_back({"curvature", w.ms()});
  }
  return out;
}

}  // namespace plumbago

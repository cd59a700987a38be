#include "experiments/shower_door/sketch_frames.hpp"

#include <algorithm>
#include <stdexcept>

#include "reference/sketchy/sketchy_composite.hpp"
#include "reference/sketchy/sketchy_enlarged.hpp"
#include "reference/util/rows.hpp"

namespace plumbago::shower_door {

std::vector<std::string> all_mode_names() {
  return {"default", "repeat", "rough", "object", "object_enlarge0", "unperturbed"};
}

Mode make_mode(const Scene& sketchy, const std::string& name) {
  Mode m{name, sketchy, {}, {}, true};
  ParamSet& p = m.scene.params;
  if (name == "default" || name == "repeat" || name == "rough" || name == "object") {
    p.set("sketchy.style", name);
  } else if (name.rfind("object_enlarge", 0) == 0 && name.size() > 14) {
    p.set("sketchy.style", std::string("object"));
    p.set("sketchy.enlarge", name.substr(14));
  } else if (name == "unperturbed") {
    p.set("sketchy.style", std::string("default"));
    for (const char* k : {"edge_a", "edge_b", "edge_c", "edge_d", "shade_a", "shade_b", "shade_c", "shade_d"})
      p.set(std::string("sketchy.") + k, 0.0);
    m.perturbed = false;
  } else {
    throw std::invalid_argument("unknown shower-door mode '" + name + "'");
  }
  m.noise = make_sketchy_noise(p, m.scene.seed);
  if (p.get<SketchyParams>().style == SketchyStyle::Object) m.enlarged = enlarged_scene(m.scene);
  return m;
}

View trace_view(const Scene& sketchy, const Camera& camera) {
  View v{sketchy, {}, {}};
  v.scene.camera = camera;
  v.gbuffer = reference::trace_gbuffer(v.scene, v.scene.width, v.scene.height);
  v.maps = reference::sketchy_maps(v.gbuffer, object_colors(v.scene), v.scene.params.get<EdgeDetectParams>());
  return v;
}

ModeFrame render_mode(const Mode& mode, const View& view) {
  SketchyParams p = mode.scene.params.get<SketchyParams>();
  int w = view.scene.width, h = view.scene.height;
  Image coordinates;
  if (!mode.enlarged.objects.empty()) {
    Scene enlarged = mode.enlarged;
    enlarged.camera = view.scene.camera;
    coordinates = reference::enlarged_noise_coordinates(enlarged, w, h);
  }
  reference::SketchyInputs in{view.maps, view.gbuffer, mode.noise, coordinates};
  ModeFrame out;
  out.coordinates = coordinates;
  out.sketch = reference::sketchy_composite(in, p, {}, {}).color;
  if (!mode.perturbed) return out;
  int copies = p.style == SketchyStyle::Repeat ? p.edge_copies : 1;
  out.field = Image(w, h, 2 * copies);
  reference::for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < copies; ++k) {
        glm::vec2 uv = reference::uncertainty(in, p, {float(x) + 0.5f, float(y) + 0.5f}, k);
        out.field.at(x, y, 2 * k) = uv.x, out.field.at(x, y, 2 * k + 1) = uv.y;
      }
  });
  return out;
}

Image own_shell(const Mode& mode, const View& view, const Image& points, const Image& coordinates, float reach) {
  float enlarge = mode.scene.params.get<SketchyParams>().enlarge;
  // Per object: world -> object space, the enlarged bbox diagonal (noise coordinate =
  // enlarged object-space position / that, common/sketchy/sketchy.hpp) and the enlarge distance.
  std::vector<glm::mat4> to_object;
  std::vector<float> diagonal, distance;
  for (size_t i = 0; i < mode.scene.objects.size(); ++i) {
    to_object.push_back(glm::inverse(mode.scene.objects[i].transform));
    diagonal.push_back(mode.enlarged.objects[i].mesh->bbox_diagonal());
    distance.push_back(std::max(enlarge * mode.scene.objects[i].mesh->bbox_diagonal(), 1e-6f * diagonal.back()));
  }
  Image out(points.width, points.height, 1);
  for (int y = 0; y < points.height; ++y)
    for (int x = 0; x < points.width; ++x) {
      if (points.at(x, y, 3) == 0.0f || coordinates.at(x, y, 3) == 0.0f) continue;
      unsigned i = view.gbuffer.ids.at(x, y, 0) - 1;
      glm::vec3 shell =
          glm::vec3(coordinates.at(x, y, 0), coordinates.at(x, y, 1), coordinates.at(x, y, 2)) * diagonal[i];
      glm::vec3 surface(to_object[i] * glm::vec4(points.at(x, y, 0), points.at(x, y, 1), points.at(x, y, 2), 1.0f));
      out.at(x, y) = glm::length(shell - surface) <= reach * distance[i] ? 1.0f : 0.0f;
    }
  return out;
}

}  // namespace plumbago::shower_door

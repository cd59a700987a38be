#include "common/scene/gbuffer.hpp"

#include "common/core/frame.hpp"
#include "common/pencil/interior_intensity.hpp"
#include "common/scene/lights.hpp"

namespace plumbago {

namespace {

glm::vec3 unit_or_z(glm::vec3 v) {
  float len = glm::length(v);
  return len > 0 && std::isfinite(len) ? v / len : glm::vec3(0, 0, 1);
}

WorldObject world_object(const SceneObject& obj, const std::vector<Light>& lights, const InteriorParams& ip) {
  const Mesh& m = *obj.mesh;
  WorldObject w;
  w.flat = obj.flat;
  glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(obj.transform)));
  w.positions.reserve(m.positions.size());
  for (const auto& p : m.positions) w.positions.push_back(glm::vec3(obj.transform * glm::vec4(p, 1.0f)));
  w.normals.reserve(m.normals.size());
  for (const auto& n : m.normals) w.normals.push_back(unit_or_z(normal_matrix * n));
  w.triangles = m.triangles;
  w.gouraud.reserve(w.normals.size());
  for (const auto& n : w.normals) w.gouraud.push_back(lambert_intensity(n, lights, ip));
  return w;
}

// Curvature directions are tangent vectors: they move with the object's linear part.
void add_directions(const SceneObject& obj, const Curvature& c, WorldObject& w) {
  glm::mat3 linear(obj.transform);
  for (size_t v = 0; v < c.size(); ++v) {
    w.d_min.push_back(unit_or_z(linear * c.d_min[v]));
    w.d_max.push_back(unit_or_z(linear * c.d_max[v]));
  }
}

}  // namespace

glm::vec3 face_normal(const WorldObject& obj, size_t t) {
  const glm::uvec3& tri = obj.triangles[t];
  glm::vec3 p0 = obj.positions[tri[0]], p1 = obj.positions[tri[1]], p2 = obj.positions[tri[2]];
  return unit_or_z(glm::cross(p1 - p0, p2 - p0));
}

std::vector<WorldObject> world_geometry(const Scene& scene, const std::vector<Curvature>& curvature) {
  InteriorParams ip = scene.params.get<InteriorParams>();
  std::vector<WorldObject> out;
  std::vector<Light> lights = unit_world_lights(scene);
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    out.push_back(world_object(scene.objects[i], lights, ip));
    if (i < curvature.size()) add_directions(scene.objects[i], curvature[i], out.back());
  }
  return out;
}

Image normalized_depth(const GBuffer& g) {
  Image z(g.depth.width, g.depth.height, 1);
  for (size_t i = 0; i < z.pixels(); ++i) z.data[i] = (g.depth.data[i] - g.near) / (g.far - g.near);
  return z;
}

}  // namespace plumbago

namespace plumbago {

void add_gbuffer_buffers(const GBuffer& g, std::map<std::string, Image>& out, const std::string& prefix) {
  out[prefix + ".normal"] = g.normal;
  out[prefix + ".face_normal"] = g.face_normal;
  out[prefix + ".depth"] = normalized_depth(g);
  out[prefix + ".bary"] = g.bary;
  out[prefix + ".gouraud"] = g.gouraud;
  if (!g.theta_min.empty()) out[prefix + ".theta_min"] = g.theta_min;
  if (!g.theta_max.empty()) out[prefix + ".theta_max"] = g.theta_max;
  Image ids(g.ids.width, g.ids.height, 2);
  for (size_t i = 0; i < g.ids.data.size(); ++i) ids.data[i] = float(g.ids.data[i]);
  out[prefix + ".ids"] = ids;
}

std::vector<Output> gbuffer_outputs(const GBufferSlot& g, bool with_angles) {
  const char* interior =
      "raster vs ray on interior pixels; the band along depth discontinuities excluded; where triangles are slivers "
      "in the window, plus a derived bound (a raster's corners snap by up to 1/32 px), none within that of an "
      "occluding edge in front";
  const char* same =
      "raster vs ray on interior pixels that both backends give the same triangle; where triangles are slivers in the "
      "window, plus a derived bound (a raster's corners snap by up to 1/32 px), none within that of an occluding edge "
      "in front";
  const char* angles = "(cos, sin) of each corner's angle; interior pixels on the same triangle";
  std::vector<Output> out = {
      {.handle = g.normal,
       .channels = 3,
       .doc = "unit view-space shading normal",
       .tolerance = tolerance::kNormal,
       .tolerance_why = interior,
       .mask = ParityMask::Interior},
      {.handle = g.face_normal,
       .channels = 3,
       .doc = "unit view-space geometric normal",
       .tolerance = tolerance::kNormal,
       .tolerance_why = same,
       .mask = ParityMask::SameTriangle},
      {.handle = g.depth,
       .doc = "linear view depth (dumps: normalized)",
       .tolerance = tolerance::kDepth,
       .tolerance_why = interior,
       .mask = ParityMask::Interior},
      {.handle = g.ids,
       .channels = 2,
       .texel = Texel::Uint,
       .doc = "object index + 1, triangle index",
       .tolerance_why = "coverage: the band's share is reported",
       .compared = false},
      {.handle = g.bary,
       .channels = 3,
       .doc = "barycentrics",
       .tolerance = tolerance::kBary,
       .tolerance_why = same,
       .mask = ParityMask::SameTriangle},
      {.handle = g.gouraud,
       .doc = "Gouraud intensity (Lee et al. 2006, §3, §5.2)",
       .tolerance = tolerance::kNormal,
       .tolerance_why = interior,
       .mask = ParityMask::Interior},
      {.handle = g.theta_min,
       .channels = 3,
       .doc = "corner angles of the min-curvature direction (Lee et al. 2006, §5.3)",
       .tolerance = tolerance::kAngle,
       .tolerance_why = angles,
       .mask = ParityMask::SameTriangle,
       .value = ParityValue::Angles,
       .written = when::effect_interior},
      {.handle = g.theta_max,
       .channels = 3,
       .doc = "corner angles of the max-curvature direction (Lee et al. 2006, §5.3)",
       .tolerance = tolerance::kAngle,
       .tolerance_why = angles,
       .mask = ParityMask::SameTriangle,
       .value = ParityValue::Angles,
       .written = when::effect_interior},
  };
  if (!with_angles) out.erase(out.begin() + 6, out.end());
  return out;
}

}  // namespace plumbago

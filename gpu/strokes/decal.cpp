// Decals' projection on the GPU (Kalnins et al. 2002, §3, §4.5, common/strokes/decal.hpp 1.): the G-buffer rendered
// with the stroke file's camera says which faces are seen around each sample (its ids at
// the 3x3 pixel centers around it); the ray through the sample picks the nearest of them
// (else of the faces around them: a sliver may cover no pixel center) and gives the
// barycentrics where it meets it.
#include "gpu/strokes/decal.hpp"

#include <algorithm>
#include <climits>
#include <map>

#include "common/scene/gbuffer.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago::gpu {

namespace {

// The G-buffer's ids (object + 1, triangle) of `scene` seen through `file`'s camera.
ImageU32 ids_seen_from(const Scene& scene, const StrokeFile& file) {
  Scene view = scene;
  view.camera = file.camera, view.width = file.width, view.height = file.height;
  GBufferPass pass(view);
  GBufferTargets targets = make_gbuffer_targets(file.width, file.height, GBufferFormat::RGBA32F);
  GBufferChannels ids_only = GBufferChannels::none();
  ids_only.read_region = {0, 0, INT_MAX, INT_MAX};  // 0 where no object is
  pass.render(view, targets, ids_only);
  return download_texture_u32(targets.ids, 2);
}

// The faces around each vertex of each object, made on first use: where no face seen at
// the pixel centers around a sample meets its ray (a sliver between pixel centers), the
// faces around theirs are tried.
class FacesAround {
 public:
  explicit FacesAround(const std::vector<WorldObject>& world) : world_(world), around_(world.size()) {}
  const std::vector<uint32_t>& of(uint32_t object, uint32_t vertex) {
    std::vector<std::vector<uint32_t>>& a = around_[object];
    if (a.empty()) {
      a.resize(world_[object].positions.size());
      for (uint32_t f = 0; f < world_[object].triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) a[world_[object].triangles[f][k]].push_back(f);
    }
    return a[vertex];
  }

 private:
  const std::vector<WorldObject>& world_;
  std::vector<std::vector<std::vector<uint32_t>>> around_;
};

// The face the ray through p meets first among `faces` (object, face), if any.
void nearest_hit(const std::vector<WorldObject>& world, const DecalRay& ray,
                 const std::vector<std::pair<uint32_t, uint32_t>>& faces, DecalPoint& best, double& nearest) {
  for (auto [object, face] : faces) {
    const glm::uvec3& t = world[object].triangles[face];
    const std::vector<glm::vec3>& v = world[object].positions;
    auto hit = decal_ray_hit(ray, glm::dvec3(v[t[0]]), glm::dvec3(v[t[1]]), glm::dvec3(v[t[2]]));
    if (hit && hit->t < nearest) nearest = hit->t, best.object = object, best.face = face, best.bary = hit->bary;
  }
}

// The face of the 3x3 pixels around p that the ray through p meets first, else of the faces
// around those.
DecalPoint surface_point(const ImageU32& ids, const std::vector<WorldObject>& world, FacesAround& around,
                         const StrokeFile& file, const DrawnPoint& p) {
  DecalRay ray = decal_ray(file, p.window);
  DecalPoint best;
  best.pressure = p.pressure;
  double nearest = INFINITY;
  std::vector<std::pair<uint32_t, uint32_t>> seen;
  int x = int(std::floor(p.window.x)), y = int(std::floor(p.window.y));
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int px = x + dx, py = y + dy;
      if (px < 0 || py < 0 || px >= ids.width || py >= ids.height || ids.at(px, py, 0) == 0) continue;
      seen.push_back({ids.at(px, py, 0) - 1, ids.at(px, py, 1)});
    }
  nearest_hit(world, ray, seen, best, nearest);
  if (best.object != kMissed || seen.empty()) return best;
  std::vector<std::pair<uint32_t, uint32_t>> next;
  for (auto [object, face] : seen)
    for (int k = 0; k < 3; ++k)
      for (uint32_t f : around.of(object, world[object].triangles[face][k])) next.push_back({object, f});
  nearest_hit(world, ray, next, best, nearest);
  return best;
}

}  // namespace

DecalSurface project_decals_through_gbuffer(const Scene& scene) {
  std::vector<WorldObject> world = world_geometry(scene);
  FacesAround around(world);
  std::map<const StrokeFile*, ImageU32> ids;
  DecalSurface out;
  for (const DecalSamples& d : decal_samples(scene)) {
    auto it = ids.find(d.file);
    if (it == ids.end()) it = ids.emplace(d.file, ids_seen_from(scene, *d.file)).first;
    ProjectedDecal decal{*d.style, {}, d.hatch};
    for (const DrawnPoint& p : d.samples) decal.points.push_back(surface_point(it->second, world, around, *d.file, p));
    out.push_back(std::move(decal));
  }
  return out;
}

}  // namespace plumbago::gpu

// Decals' projection, CPU reference (Kalnins et al. 2002, §3, §4.5, common/strokes/decal.hpp 1.): the ray from the
// stroke file's eye through each sample, traced by Embree over the scene's world geometry;
// the face it meets first and where, as barycentrics (1 - u - v, u, v).
#include "reference/strokes/decal.hpp"

#include <limits>

#include "reference/scene/ray_scene.hpp"

namespace plumbago::reference {

DecalPoint first_surface_hit(RTCScene scene, const StrokeFile& file, const DrawnPoint& p) {
  DecalRay ray = decal_ray(file, p.window);
  RTCRayHit r{};
  r.ray.org_x = float(ray.origin.x), r.ray.org_y = float(ray.origin.y), r.ray.org_z = float(ray.origin.z);
  r.ray.dir_x = float(ray.direction.x), r.ray.dir_y = float(ray.direction.y), r.ray.dir_z = float(ray.direction.z);
  r.ray.tnear = 0.0f;
  r.ray.tfar = std::numeric_limits<float>::infinity();
  r.ray.mask = 0xFFFFFFFFu;
  r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &r);
  DecalPoint out;
  out.pressure = p.pressure;
  if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return out;
  out.object = r.hit.geomID, out.face = r.hit.primID;
  out.bary = {1.0 - double(r.hit.u) - double(r.hit.v), double(r.hit.u), double(r.hit.v)};
  return out;
}

DecalSurface project_decals_by_rays(const Scene& scene) {
  RayScene rays(world_geometry(scene));
  DecalSurface out;
  for (const DecalSamples& d : decal_samples(scene)) {
    ProjectedDecal decal{*d.style, {}, d.hatch};
    for (const DrawnPoint& p : d.samples) decal.points.push_back(first_surface_hit(rays.get(), *d.file, p));
    out.push_back(std::move(decal));
  }
  rays.check("projecting the decals");
  return out;
}

}  // namespace plumbago::reference

// Stroke visibility by rays: see reference/strokes/ray_visibility.hpp.
#include "reference/strokes/ray_visibility.hpp"

#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "reference/scene/ray_scene.hpp"

namespace plumbago::reference {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;

constexpr double kOnSurface = 1e-5;  // of the eye distance: a triangle this close passes through the point
constexpr int kMaxOwnHits = 64;      // own triangles a ray may pass (a vertex's ring) before it gives up

Kernel::Point_3 cgal(glm::dvec3 p) { return {p.x, p.y, p.z}; }

// Whether triangle `prim` of `object` passes within `tolerance` of `point`.
bool passes_through(const WorldObject& object, unsigned prim, glm::dvec3 point, double tolerance) {
  const glm::uvec3& t = object.triangles[prim];
  Kernel::Triangle_3 triangle(cgal(object.positions[t[0]]), cgal(object.positions[t[1]]), cgal(object.positions[t[2]]));
  if (triangle.is_degenerate()) return false;
  return CGAL::squared_distance(cgal(point), triangle) <= tolerance * tolerance;
}

RTCRayHit ray_to(glm::dvec3 eye, glm::dvec3 dir, float tnear, float tfar) {
  RTCRayHit r{};
  r.ray.org_x = float(eye.x), r.ray.org_y = float(eye.y), r.ray.org_z = float(eye.z);
  r.ray.dir_x = float(dir.x), r.ray.dir_y = float(dir.y), r.ray.dir_z = float(dir.z);
  r.ray.tnear = tnear, r.ray.tfar = tfar;
  r.ray.mask = 0xFFFFFFFFu;
  r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  return r;
}

// A point on the mesh: traced hit by hit, passing the triangles the point lies on.
bool visible_on_surface(const RayScene& rays, const std::vector<WorldObject>& objects, glm::dvec3 eye,
                        glm::dvec3 point) {
  double distance = glm::length(point - eye);
  if (!(distance > 0)) return true;
  glm::dvec3 dir = (point - eye) / distance;
  float tnear = 0.0f;
  for (int own = 0; own < kMaxOwnHits; ++own) {
    RTCRayHit r = ray_to(eye, dir, tnear, float(distance * (1 + kOnSurface)));  // the point's own hits included
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(rays.get(), &context, &r);
    if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return true;
    if (!passes_through(objects[r.hit.geomID], r.hit.primID, point, kOnSurface * distance)) return false;
    tnear = std::nextafter(r.ray.tfar, INFINITY);
  }
  return false;
}

// A silhouette point: hits within own_facets of it along the ray are its own facets.
bool visible_off_facets(const RayScene& rays, glm::dvec3 eye, glm::dvec3 point, double own_facets) {
  double distance = glm::length(point - eye);
  if (!(distance > own_facets)) return true;  // nothing can lie between
  RTCRayHit r = ray_to(eye, (point - eye) / distance, 0.0f, float(distance - own_facets));
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(rays.get(), &context, &r.ray);
  return r.ray.tfar >= 0.0f;  // Embree sets tfar to -inf when something is hit
}

}  // namespace

std::vector<uint8_t> visible_by_rays(const Scene& scene, const std::vector<RayTarget>& targets) {
  std::vector<WorldObject> objects = world_geometry(scene);
  RayScene rays(objects);
  std::vector<uint8_t> out(targets.size());
  glm::dvec3 eye(scene.camera.eye);
  tbb::parallel_for(size_t(0), targets.size(), [&](size_t k) {
    const RayTarget& t = targets[k];
    out[k] = t.own_facets > 0 ? visible_off_facets(rays, eye, t.point, t.own_facets)
                              : visible_on_surface(rays, objects, eye, t.point);
  });
  rays.check("tracing visibility rays");
  return out;
}

}  // namespace plumbago::reference

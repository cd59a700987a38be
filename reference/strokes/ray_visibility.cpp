// Stroke visibility by rays: see reference/strokes/ray_visibility.hpp.
#include "reference/strokes/ray_visibility.hpp"

#include <tbb/parallel_for.h>

#include "reference/scene/ray_scene.hpp"

namespace plumbago::reference {

std::vector<uint8_t> visible_by_rays(const Scene& scene, const std::vector<glm::dvec3>& points,
                                     const std::vector<double>& ignore) {
  RayScene rays(world_geometry(scene));
  std::vector<uint8_t> out(points.size());
  glm::dvec3 eye(scene.camera.eye);
  tbb::parallel_for(size_t(0), points.size(), [&](size_t k) {
    double distance = glm::length(points[k] - eye);
    if (!(distance > ignore[k])) {
      out[k] = 1;  // nothing can lie between
      return;
    }
    glm::dvec3 dir = (points[k] - eye) / distance;
    RTCRay ray{};
    ray.org_x = float(eye.x), ray.org_y = float(eye.y), ray.org_z = float(eye.z);
    ray.dir_x = float(dir.x), ray.dir_y = float(dir.y), ray.dir_z = float(dir.z);
    ray.tnear = 0.0f;
    ray.tfar = float(distance - ignore[k]);  // a hit on the ray within `ignore` of the point is its own surface
    ray.mask = 0xFFFFFFFFu;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(rays.get(), &context, &ray);
    out[k] = ray.tfar >= 0.0f;  // Embree sets tfar to -inf when something is hit
  });
  rays.check("tracing visibility rays");
  return out;
}

}  // namespace plumbago::reference

#include "reference/scene/gbuffer.hpp"
#include "common/sketchy/sketchy_gbuffer.hpp"

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/curvature/texture_rotation.hpp"
#include "common/pencil/interior_intensity.hpp"
#include "reference/core/stage.hpp"
#include "reference/scene/ray_scene.hpp"

namespace plumbago::reference {

namespace {

struct Hit {
  glm::vec3 dir{0};  // unit ray direction
  unsigned object = RTC_INVALID_GEOMETRY_ID, triangle = 0;
  float t = 0, u = 0, v = 0;
};

// Traces the primary rays of one 4x4 tile (a packet of 16 coherent rays).
void trace_tile(RTCScene scene, const Camera& cam, const PrimaryRays& primary, int x0, int y0, int w, int h,
                Hit out[16]) {
  alignas(64) RTCRayHit16 rays;
  alignas(64) int valid[16];
  glm::vec3 dirs[16];
  for (int i = 0; i < 16; ++i) {
    int x = x0 + i % 4, y = y0 + i / 4;
    valid[i] = x < w && y < h ? -1 : 0;
    dirs[i] = primary.direction(float(x) + 0.5f, float(y) + 0.5f);  // pixel center (docs/conventions.md)
    rays.ray.org_x[i] = cam.eye.x, rays.ray.org_y[i] = cam.eye.y, rays.ray.org_z[i] = cam.eye.z;
    rays.ray.dir_x[i] = dirs[i].x, rays.ray.dir_y[i] = dirs[i].y, rays.ray.dir_z[i] = dirs[i].z;
    rays.ray.tnear[i] = 0.0f;
    rays.ray.tfar[i] = std::numeric_limits<float>::infinity();
    rays.ray.mask[i] = 0xFFFFFFFFu, rays.ray.flags[i] = 0, rays.ray.time[i] = 0;
    rays.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect16(valid, scene, &context, &rays);
  for (int i = 0; i < 16; ++i)
    out[i] = {dirs[i], rays.hit.geomID[i], rays.hit.primID[i], rays.ray.tfar[i], rays.hit.u[i], rays.hit.v[i]};
}

void set3(Image& img, int x, int y, glm::vec3 v) {
  for (int c = 0; c < 3; ++c) img.at(x, y, c) = v[c];
}

// Lee et al. 2006, §5.3: each corner's stroke angles, min and max curvature, at the corner itself.
void corner_angles(const WorldObject& obj, const glm::uvec3& tri, const ProjectionInfo& proj, float min_projected,
                   int x, int y, GBuffer& g) {
  for (int k = 0; k < 3; ++k) {
    glm::vec3 p = obj.positions[tri[k]], d_min = obj.d_min[tri[k]], d_max = obj.d_max[tri[k]];
    g.theta_min.at(x, y, k) = stroke_angle(proj, p, d_min, d_max, min_projected);
    g.theta_max.at(x, y, k) = stroke_angle(proj, p, d_max, d_min, min_projected);
  }
}

// Fills pixel (x, y) from its hit: barycentrics w = (1-u-v, u, v) weight corners 0, 1, 2.
void shade_hit(const Hit& hit, const std::vector<WorldObject>& objects, const glm::mat3& to_view, glm::vec3 forward,
               int x, int y, GBuffer& g) {
  const WorldObject& obj = objects[hit.object];
  const glm::uvec3& tri = obj.triangles[hit.triangle];
  glm::vec3 w(1.0f - hit.u - hit.v, hit.u, hit.v);
  glm::vec3 fn = face_normal(obj, hit.triangle);
  glm::vec3 n = obj.flat ? fn : w[0] * obj.normals[tri[0]] + w[1] * obj.normals[tri[1]] + w[2] * obj.normals[tri[2]];
  auto unit = [](glm::vec3 v) {
    float len = glm::length(v);
    return len > 0 ? v / len : glm::vec3(0);
  };
  set3(g.normal, x, y, unit(to_view * n));
  set3(g.face_normal, x, y, unit(to_view * fn));
  set3(g.bary, x, y, w);
  g.depth.at(x, y) = hit.t * glm::dot(hit.dir, forward);  // d = dot(hit - eye, forward) = -z_view
  g.ids.at(x, y, 0) = hit.object + 1;
  g.ids.at(x, y, 1) = hit.triangle;
  g.gouraud.at(x, y) = w[0] * obj.gouraud[tri[0]] + w[1] * obj.gouraud[tri[1]] + w[2] * obj.gouraud[tri[2]];
}

// The background values of every channel (common/scene/gbuffer.hpp). The channels (49 MB at
// 800x800) are allocated in parallel: faulting in fresh pages on one thread took a third
// of the frame (bunny at 800x800: 54 -> 44 ms per call).
GBuffer background_gbuffer(int w, int h, const Camera& cam) {
  GBuffer g;
  tbb::parallel_invoke([&] { g.normal = Image(w, h, 3); }, [&] { g.face_normal = Image(w, h, 3); },
                       [&] { g.depth = Image(w, h, 1, cam.far); }, [&] { g.theta_min = Image(w, h, 3); },
                       [&] { g.theta_max = Image(w, h, 3); }, [&] { g.ids = ImageU32(w, h, 2); },
                       [&] { g.bary = Image(w, h, 3); }, [&] { g.gouraud = Image(w, h, 1, 1.0f); });
  g.near = cam.near;
  g.far = cam.far;
  return g;
}

}  // namespace

GBuffer trace_gbuffer(const Scene& scene, int width, int height, const std::vector<Curvature>& curvature) {
  std::vector<WorldObject> objects = world_geometry(scene, curvature);
  ProjectionInfo proj{scene.camera.projection(float(width) / float(height)) * scene.camera.view(), float(width),
                      float(height), std::tan(glm::radians(scene.camera.fov_deg) * 0.5f)};
  float min_projected = scene.params.get<InteriorParams>().min_projected;
  RayScene rays(objects);
  const Camera& cam = scene.camera;
  GBuffer g = background_gbuffer(width, height, cam);
  PrimaryRays primary(cam, width, height);
  glm::mat3 to_view(cam.view());
  glm::vec3 forward = cam.forward();
  int tiles_x = (width + 3) / 4, tiles_y = (height + 3) / 4;
  tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
    int x0 = tile % tiles_x * 4, y0 = tile / tiles_x * 4;
    Hit hits[16];
    trace_tile(rays.get(), cam, primary, x0, y0, width, height, hits);
    for (int i = 0; i < 16; ++i) {
      int x = x0 + i % 4, y = y0 + i / 4;
      if (x >= width || y >= height || hits[i].object == RTC_INVALID_GEOMETRY_ID) continue;
      shade_hit(hits[i], objects, to_view, forward, x, y, g);
      const WorldObject& obj = objects[hits[i].object];
      if (!obj.d_min.empty()) corner_angles(obj, obj.triangles[hits[i].triangle], proj, min_projected, x, y, g);
    }
  });
  rays.check("tracing primary rays");
  return g;
}

PLUMBAGO_REFERENCE_STAGE(gbuffer, [](ReferenceFrame& f) {
  const std::vector<Curvature>* curvature = f.get(maybe(kCurvature));
  f.put(kGBuffer,
        trace_gbuffer(f.ordinary, f.scene.width, f.scene.height, curvature ? *curvature : std::vector<Curvature>{}));
});
PLUMBAGO_REFERENCE_STAGE(sketchy_gbuffer, [](ReferenceFrame& f) {
  f.put(kSketchyGBuffer, trace_gbuffer(f.sketchy, f.scene.width, f.scene.height));
});

}  // namespace plumbago::reference

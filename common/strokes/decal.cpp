// Decals (Kalnins et al. 2002, §3, §4.5): see common/strokes/decal.hpp.
#include "common/strokes/decal.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace plumbago {

double drawn_length(const std::vector<DrawnPoint>& points) {
  double length = 0;
  for (size_t k = 1; k < points.size(); ++k) length += glm::distance(points[k - 1].window, points[k].window);
  return length;
}

std::vector<DrawnPoint> resampled_evenly(const std::vector<DrawnPoint>& points, size_t segments) {
  std::vector<double> arc{0};
  for (size_t k = 1; k < points.size(); ++k)
    arc.push_back(arc.back() + glm::distance(points[k - 1].window, points[k].window));
  std::vector<DrawnPoint> out;
  size_t k = 0;
  for (size_t i = 0; i <= segments; ++i) {
    double s = arc.back() * double(i) / double(segments);
    while (k + 2 < points.size() && arc[k + 1] < s) ++k;
    double length = arc[k + 1] - arc[k], t = length > 0 ? std::clamp((s - arc[k]) / length, 0.0, 1.0) : 0.0;
    out.push_back({points[k].window + t * (points[k + 1].window - points[k].window),
                   points[k].pressure + t * (points[k + 1].pressure - points[k].pressure)});
  }
  return out;
}

namespace {

// The polyline resampled every kDecalStepPx px of its length or a little less, ends kept.
std::vector<DrawnPoint> resampled(const std::vector<DrawnPoint>& points) {
  return resampled_evenly(points, std::max<size_t>(1, size_t(std::ceil(drawn_length(points) / kDecalStepPx))));
}

}  // namespace

std::vector<DecalSamples> decal_samples(const Scene& scene) {
  std::vector<DecalSamples> out;
  for (const StrokeFile& file : scene.stroke_files)
    for (const DrawnStroke& stroke : file.strokes)
      if (stroke.role == StrokeRole::Decal) out.push_back({&file, &*stroke.style, {}, resampled(stroke.points)});
  for (const HatchPolyline& h : hatch_polylines(scene))
    out.push_back({&scene.stroke_files[h.file], &*h.stroke->style, h.tag, resampled(h.points)});
  return out;
}

bool has_decals(const Scene& scene) {
  for (const StrokeFile& file : scene.stroke_files)
    for (const DrawnStroke& stroke : file.strokes)
      if (stroke.role == StrokeRole::Decal || stroke.role == StrokeRole::Hatching) return true;
  return false;
}

uint32_t most_common_object(const std::vector<uint32_t>& objects) {
  std::map<uint32_t, size_t> count;
  for (uint32_t o : objects)
    if (o != kMissed) ++count[o];
  auto most = std::max_element(count.begin(), count.end(), [](auto& a, auto& b) { return a.second < b.second; });
  return most == count.end() ? kMissed : most->first;
}

glm::dvec3 decal_point_local(const Scene& scene, const DecalPoint& d) {
  const Mesh& mesh = *scene.objects[d.object].mesh;
  const glm::uvec3& t = mesh.triangles[d.face];
  return d.bary.x * glm::dvec3(mesh.positions[t[0]]) + d.bary.y * glm::dvec3(mesh.positions[t[1]]) +
         d.bary.z * glm::dvec3(mesh.positions[t[2]]);
}

glm::dvec3 decal_point_world(const Scene& scene, const DecalPoint& d) {
  return glm::dvec3(glm::dmat4(scene.objects[d.object].transform) * glm::dvec4(decal_point_local(scene, d), 1.0));
}

DecalRay decal_ray(const StrokeFile& file, glm::dvec2 p) {
  PrimaryRays rays(file.camera, file.width, file.height);
  return {glm::dvec3(file.camera.eye), glm::dvec3(rays.direction(float(p.x), float(p.y)))};
}

// Möller-Trumbore: t along the ray, u and v the weights of b and c.
std::optional<RayTriangleHit> decal_ray_hit(const DecalRay& ray, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  glm::dvec3 e1 = b - a, e2 = c - a, q = glm::cross(ray.direction, e2);
  double det = glm::dot(e1, q);
  if (det == 0 || !std::isfinite(det)) return std::nullopt;
  glm::dvec3 s = ray.origin - a, r = glm::cross(s, e1);
  double u = glm::dot(s, q) / det, v = glm::dot(ray.direction, r) / det, t = glm::dot(e2, r) / det;
  if (u < 0 || v < 0 || u + v > 1 || t <= 0) return std::nullopt;
  return RayTriangleHit{t, {1 - u - v, u, v}};
}

ProjectionAgreement compare_projections(const DecalSurface& a, const DecalSurface& b,
                                        const std::vector<uint8_t>& near_silhouette) {
  ProjectionAgreement out;
  for (size_t d = 0; d < a.size() && d < b.size(); ++d)
    for (size_t k = 0; k < a[d].points.size() && k < b[d].points.size(); ++k, ++out.points) {
      const DecalPoint &p = a[d].points[k], &q = b[d].points[k];
      if (p.object == q.object && (p.object == kMissed || p.face == q.face)) {
        ++out.same_face;
        glm::dvec3 diff = glm::abs(p.bary - q.bary);
        out.max_bary_difference = std::max({out.max_bary_difference, diff.x, diff.y, diff.z});
      } else if (p.object == q.object && std::min({p.bary.x, p.bary.y, p.bary.z}) < 1e-3 &&
                 std::min({q.bary.x, q.bary.y, q.bary.z}) < 1e-3) {
        ++out.differ_on_edge;
      } else if (out.points < near_silhouette.size() && near_silhouette[out.points]) {
        ++out.differ_near_silhouette;
      } else {
        ++out.differ_elsewhere;
      }
    }
  return out;
}

}  // namespace plumbago

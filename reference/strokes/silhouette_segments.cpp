// Silhouette segments face by face, CPU reference (Kalnins et al. 2002, §4.5): the segments
// of common/strokes/feature_lines.hpp in double, one face at a time, and the bound that
// parity allows the GPU's float evaluation of the same formula.
#include "common/strokes/silhouette_segments.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cfloat>

#include "common/strokes/strokes.hpp"
#include "reference/core/stage.hpp"
#include "reference/strokes/float_error.hpp"

namespace plumbago::reference {

namespace {

// One stroke object seen from this frame's eye: g per face corner, in double.
struct ObjectView {
  const FeatureLineMesh& lines;
  const Mesh& mesh;
  WindowProjection camera;
  glm::dmat4 model, clip;  // object to world, object to clip space
  glm::dvec3 eye;          // object space
  std::vector<double> g;
  uint32_t first_record;
};

struct WindowEnd {
  glm::dvec2 window;
  double depth;
};

WindowEnd project(const ObjectView& v, glm::dvec3 p) {
  glm::dvec3 w = v.camera(glm::dvec3(v.model * glm::dvec4(p, 1.0)));
  return {{w.x, w.y}, w.z};
}

std::vector<ObjectView> object_views(const Scene& scene, const LineMeshes& meshes, bool normalized) {
  std::vector<ObjectView> views;
  std::vector<uint32_t> first = first_faces(scene);
  WindowProjection camera(scene.camera, scene.width, scene.height);
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const FeatureLineMesh* lines = line_mesh(meshes, o);
    if (!lines) continue;
    glm::dmat4 m(scene.objects[o].transform);
    glm::dvec3 eye = eye_in_object_space(m, glm::dvec3(scene.camera.eye));
    views.push_back({*lines, *scene.objects[o].mesh, camera, m, camera.clip * m, eye,
                     lines->silhouette_values(eye, normalized), first[o]});
  }
  return views;
}

// Calls fn(record, view, face) for every face of every stroke object, in parallel.
template <class Fn>
void for_each_face(const std::vector<ObjectView>& views, Fn fn) {
  for (const ObjectView& v : views)
    tbb::parallel_for(uint32_t(0), uint32_t(v.mesh.triangles.size()),
                      [&](uint32_t f) { fn(v.first_record + f, v, f); });
}

// A segment of the table: both ends in front of the near plane (common/strokes/silhouette_segments.hpp).
bool in_front(const WindowEnd (&ends)[2], const Scene& scene) {
  return ends[0].depth >= double(scene.camera.near) && ends[1].depth >= double(scene.camera.near);
}

// --- the float error the GPU may make (reference/strokes/float_error.hpp) ------------------

// g at a corner: the eye rounded to float (u |e|), e - x (u |e - x|), the normal rounded
// (u), normalize (5u), the three-term dot (3u): u (10 + (|e| + |x|) / |e - x|) relative to
// |g|'s scale, 1 when normalized and |e - x| for the paper's literal c - x.
double g_error(glm::dvec3 eye, glm::dvec3 x, bool normalized) {
  double d = glm::length(eye - x), s = glm::length(eye) + glm::length(x);
  return 2 * kU * (normalized ? 10 + s / d : 10 * d + s);
}

struct FaceErrors {
  bool sign_ambiguous = false;  // some corner's g, the facing test or the near-plane test may flip
  double end_px = 0;            // the ends' window error
};

// The window error of an end at object point p, itself off by `dp`.
double projection_error_px(const ObjectView& v, const Scene& scene, glm::dvec3 p, double dp) {
  return reference::projection_error_px(v.clip, scene.width, scene.height, p, dp);
}

// The errors of one crossing (slot k of face f, run the edge's own way as the rule does):
// t = g_a / (g_a - g_b) moves by (|g_b| dg_a + |g_a| dg_b) / (g_a - g_b)^2, and p = a + (b - a) t.
struct CrossingError {
  double object, px;
};
CrossingError crossing_error(const ObjectView& v, const Scene& scene, uint32_t f, int k, const double (&dg)[3]) {
  int ka = k, kb = (k + 1) % 3;
  if (v.lines.reversed_slots(f) & (1u << k)) std::swap(ka, kb);
  double ga = v.g[3 * f + uint32_t(ka)], gb = v.g[3 * f + uint32_t(kb)];
  double dt = 2 * (std::abs(gb) * dg[ka] + std::abs(ga) * dg[kb]) / ((ga - gb) * (ga - gb)) + 4 * kU;
  glm::dvec3 a(v.mesh.positions[v.mesh.triangles[f][ka]]), b(v.mesh.positions[v.mesh.triangles[f][kb]]);
  glm::dvec3 p = a + (b - a) * (ga / (ga - gb));
  double object = dt * glm::length(b - a) + 3 * kU * (glm::length(a) + glm::length(b));
  double along = dt * glm::distance(project(v, a).window, project(v, b).window);
  return {object, along + projection_error_px(v, scene, p, object)};
}

// The facing test s = ∇g · (e - m) (common/strokes/feature_lines.hpp), ∇g = Σ g_i (N × e_i):
// whether its float value may have the other sign.
bool facing_ambiguous(const ObjectView& v, uint32_t f, const FaceSilhouette& s, const double (&dg)[3],
                      double mid_error) {
  glm::dvec3 c[3];
  for (int k = 0; k < 3; ++k) c[k] = glm::dvec3(v.mesh.positions[v.mesh.triangles[f][k]]);
  glm::dvec3 n = glm::cross(c[1] - c[0], c[2] - c[0]), gradient(0.0);
  double dn = 6 * kU * glm::length(c[1] - c[0]) * glm::length(c[2] - c[0]), d_gradient = 0;
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 opposite = c[(i + 2) % 3] - c[(i + 1) % 3];
    double g = v.g[3 * f + uint32_t(i)];
    gradient += g * glm::cross(n, opposite);
    d_gradient += (dg[i] * glm::length(n) + std::abs(g) * (dn + 4 * kU * glm::length(n))) * glm::length(opposite);
  }
  glm::dvec3 mid = 0.5 * (s.ends[0].position + s.ends[1].position), to_eye = v.eye - mid;
  double d_to_eye = 2 * kU * (glm::length(v.eye) + glm::length(mid)) + mid_error;
  double ds = d_gradient * glm::length(to_eye) + glm::length(gradient) * d_to_eye +
              3 * kU * glm::length(gradient) * glm::length(to_eye);
  return std::abs(glm::dot(gradient, to_eye)) <= 2 * ds;
}

FaceErrors face_errors(const ObjectView& v, const Scene& scene, uint32_t f, bool normalized) {
  FaceErrors e;
  double dg[3];
  for (int k = 0; k < 3; ++k) {
    dg[k] = g_error(v.eye, glm::dvec3(v.mesh.positions[v.mesh.triangles[f][k]]), normalized);
    e.sign_ambiguous |= std::abs(v.g[3 * f + uint32_t(k)]) <= dg[k];
  }
  FaceSilhouette s = v.lines.face_silhouette(v.g, v.eye, f);
  if (e.sign_ambiguous || !s.exists) return e;
  double mid_error = 0;
  for (int end = 0; end < 2; ++end) {
    CrossingError c = crossing_error(v, scene, f, s.slots[end], dg);
    e.end_px = std::max(e.end_px, c.px);
    mid_error = std::max(mid_error, c.object);
    WindowEnd w = project(v, s.ends[end].position);
    e.sign_ambiguous |= std::abs(w.depth - scene.camera.near) <= 16 * kU * (std::abs(w.depth) + 1);
  }
  e.sign_ambiguous |= facing_ambiguous(v, f, s, dg, mid_error);
  return e;
}

// Per record: FLT_MAX where the sign may flip, `ends`: the ends' error where it passes the
// declared tolerance; 0 elsewhere.
Image segment_bound(const ReferenceFrame& f, bool ends) {
  bool normalized = f.params<StrokesParams>().silhouette_normalized;
  Image bound = table_image(first_faces(f.scene).back(), 1);
  for_each_face(object_views(f.scene, f.get(kLineMeshes), normalized),
                [&](uint32_t i, const ObjectView& v, uint32_t face) {
                  FaceErrors e = face_errors(v, f.scene, face, normalized);
                  if (e.sign_ambiguous)
                    bound.data[i] = FLT_MAX;
                  else if (ends && e.end_px > kSegmentEndPx)
                    bound.data[i] = float(e.end_px);
                });
  return bound;
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(silhouette_segments, [](ReferenceFrame& f) {
  size_t records = first_faces(f.scene).back();
  Image ends = table_image(records, 4), facing = table_image(records, 1), slots = table_image(records, 2);
  for_each_face(object_views(f.scene, f.get(kLineMeshes), f.params<StrokesParams>().silhouette_normalized),
                [&](uint32_t i, const ObjectView& v, uint32_t face) {
                  FaceSilhouette s = v.lines.face_silhouette(v.g, v.eye, face);
                  if (!s.exists) return;
                  WindowEnd w[2] = {project(v, s.ends[0].position), project(v, s.ends[1].position)};
                  if (!in_front(w, f.scene)) return;
                  float* e = &ends.data[size_t(i) * 4];
                  e[0] = float(w[0].window.x), e[1] = float(w[0].window.y);
                  e[2] = float(w[1].window.x), e[3] = float(w[1].window.y);
                  facing.data[i] = s.front ? 1.0f : -1.0f;
                  slots.data[size_t(i) * 2] = float(s.slots[0]), slots.data[size_t(i) * 2 + 1] = float(s.slots[1]);
                });
  f.put(kSegmentEnds, std::move(ends));
  f.put(kSegmentFacing, std::move(facing));
  f.put(kSegmentSlots, std::move(slots));
});

PLUMBAGO_REFERENCE_BOUND(silhouette_segment_ends, kSegmentEnds.name,
                         [](const ReferenceFrame& f) { return segment_bound(f, true); });
PLUMBAGO_REFERENCE_BOUND(silhouette_segment_facing, kSegmentFacing.name,
                         [](const ReferenceFrame& f) { return segment_bound(f, false); });
PLUMBAGO_REFERENCE_BOUND(silhouette_segment_slots, kSegmentSlots.name,
                         [](const ReferenceFrame& f) { return segment_bound(f, false); });

}  // namespace plumbago::reference

// Crease and border points, CPU reference (Kalnins et al. 2002, §4.5): the records of
// common/strokes/crease_points.hpp projected in double, and the bound that parity allows the
// GPU's float evaluation of the same formula.
#include "common/strokes/crease_points.hpp"

#include <cfloat>

#include "common/strokes/strokes.hpp"
#include "reference/core/stage.hpp"
#include "reference/strokes/float_error.hpp"

namespace plumbago::reference {

namespace {

// One stroke object's frame: its matrices in double, the eye in world and object space.
struct ObjectFrame {
  const Mesh& mesh;
  glm::dmat4 model, view, clip;  // object to world, to view, to clip space
  glm::dvec3 eye, eye_object;
  uint32_t first_key;
};

std::vector<ObjectFrame> object_frames(const Scene& scene) {
  WindowProjection camera(scene.camera, scene.width, scene.height);
  std::vector<uint32_t> first = first_faces(scene);
  std::vector<ObjectFrame> out;
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    glm::dmat4 m(scene.objects[o].transform);
    glm::dvec3 eye(scene.camera.eye);
    out.push_back(
        {*scene.objects[o].mesh, m, camera.view * m, camera.clip * m, eye, eye_in_object_space(m, eye), first[o] + 1});
  }
  return out;
}

// Whether the float test n·(eye - p0) of face f, evaluated in object space, may have the
// other sign: u = p1 - p0, v = p2 - p0, w = eye - p0, each rounded from its terms, then a
// cross and a dot (10u of |u||v||w|).
bool facing_ambiguous(const ObjectFrame& o, uint32_t f) {
  glm::dvec3 p[3];
  for (int k = 0; k < 3; ++k) p[k] = glm::dvec3(o.mesh.positions[o.mesh.triangles[f][k]]);
  glm::dvec3 u = p[1] - p[0], v = p[2] - p[0], w = o.eye_object - p[0];
  double lu = glm::length(u), lv = glm::length(v), lw = glm::length(w), l0 = glm::length(p[0]);
  double ds = 2 * kU *
              (10 * lu * lv * lw + (l0 + glm::length(p[1])) * lv * lw + (l0 + glm::length(p[2])) * lu * lw +
               (glm::length(o.eye_object) + l0) * lu * lv);
  return std::abs(glm::dot(glm::cross(u, v), w)) <= ds;
}

// The keys of the first two faces of r that face the eye (common/strokes/strokes.hpp faces_eye).
glm::vec2 front_keys(const ObjectFrame& o, const CreaseRecord& r) {
  glm::vec2 keys(0.0f);
  int k = 0;
  for (uint32_t f : r.faces)
    if (k < 2 && faces_eye(o.mesh, o.model, f, o.eye)) keys[k++] = float(o.first_key + f);
  return keys;
}

// The frame's records, each with its object's frame.
struct Records {
  explicit Records(const ReferenceFrame& f)
      : objects(object_frames(f.scene)), records(crease_records(f.scene, f.get(kLineMeshes))) {}
  template <class Fn>
  void each(Fn fn) const {
    for (size_t i = 0; i < records.size(); ++i) fn(i, objects[records[i].object], records[i]);
  }
  std::vector<ObjectFrame> objects;
  std::vector<CreaseRecord> records;
};

}  // namespace

PLUMBAGO_REFERENCE_STAGE(crease_points, [](ReferenceFrame& f) {
  Records records(f);
  Image window = table_image(records.records.size(), 3), faces = table_image(records.records.size(), 2);
  WindowProjection camera(f.scene.camera, f.scene.width, f.scene.height);
  records.each([&](size_t i, const ObjectFrame& o, const CreaseRecord& r) {
    glm::dvec3 w = camera(glm::dvec3(o.model * glm::dvec4(glm::dvec3(o.mesh.positions[r.vertex]), 1.0)));
    for (int c = 0; c < 3; ++c) window.data[3 * i + size_t(c)] = float(w[c]);
    glm::vec2 keys = front_keys(o, r);
    faces.data[2 * i] = keys.x, faces.data[2 * i + 1] = keys.y;
  });
  f.put(kCreaseWindow, std::move(window));
  f.put(kCreaseFaces, std::move(faces));
});

// Beyond the tolerance, the float projection's error of each point.
PLUMBAGO_REFERENCE_BOUND(crease_point_window, kCreaseWindow.name, [](const ReferenceFrame& f) {
  Records records(f);
  Image bound = table_image(records.records.size(), 1);
  records.each([&](size_t i, const ObjectFrame& o, const CreaseRecord& r) {
    glm::dvec3 p(o.mesh.positions[r.vertex]);
    double e = std::max(projection_error_px(o.clip, f.scene.width, f.scene.height, p, 0), depth_error(o.view, p));
    if (e > kCreasePointPx) bound.data[i] = float(e);
  });
  return bound;
});

// FLT_MAX where a face around the segment may face the other way in float.
PLUMBAGO_REFERENCE_BOUND(crease_point_faces, kCreaseFaces.name, [](const ReferenceFrame& f) {
  Records records(f);
  Image bound = table_image(records.records.size(), 1);
  records.each([&](size_t i, const ObjectFrame& o, const CreaseRecord& r) {
    for (uint32_t face : r.faces)
      if (facing_ambiguous(o, face)) bound.data[i] = FLT_MAX;
  });
  return bound;
});

}  // namespace plumbago::reference

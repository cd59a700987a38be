// The ID image's triangles (Kalnins et al. 2002, §4.6): see common/strokes/id_image.hpp.
#include "common/strokes/id_image.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {

namespace {

struct ClipPoint {
  glm::dvec3 world;
  double d;  // linear view depth
};

// The polygon of a triangle in front of the near plane (Sutherland-Hodgman, one plane).
std::vector<ClipPoint> clipped_to_near(const ClipPoint (&corners)[3], double near) {
  std::vector<ClipPoint> out;
  for (int k = 0; k < 3; ++k) {
    const ClipPoint &a = corners[k], &b = corners[(k + 1) % 3];
    if (a.d >= near) out.push_back(a);
    if ((a.d >= near) != (b.d >= near)) {
      double t = (near - a.d) / (b.d - a.d);
      out.push_back({a.world + t * (b.world - a.world), near});
    }
  }
  return out;
}

class IdTriangles {
 public:
  explicit IdTriangles(const Scene& scene)
      : project_(scene.camera, scene.width, scene.height), near_(scene.camera.near) {}

  void face(const ClipPoint (&corners)[3], uint32_t key) {
    std::vector<ClipPoint> polygon = clipped_to_near(corners, near_);
    for (size_t k = 1; k + 1 < polygon.size(); ++k)
      for (const ClipPoint* c : {&polygon[0], &polygon[k], &polygon[k + 1]}) {
        glm::dvec3 w = project_(c->world);
        out.push_back({glm::vec2(w.x, w.y), float(near_ / std::max(c->d, near_)), key});
      }
  }

  // Segment a -> b of a path as a quad `width` px wide, placed at depth d (1 - bias).
  void segment(glm::dvec2 a, glm::dvec2 b, double da, double db, double width, double bias, uint32_t key) {
    glm::dvec2 along = b - a;
    double length = glm::length(along);
    if (!(length > 0)) return;
    glm::dvec2 n = glm::dvec2(-along.y, along.x) / length * (width / 2);
    da *= 1.0 - bias, db *= 1.0 - bias;
    IdVertex q[4] = {line_vertex(a - n, da, key), line_vertex(a + n, da, key), line_vertex(b + n, db, key),
                     line_vertex(b - n, db, key)};
    for (int k : {0, 1, 2, 0, 2, 3}) out.push_back(q[k]);
  }

  // The part [t0, t1] of segment a -> b whose quad `width` px wide can cover a pixel center.
  bool covers(glm::dvec2 a, glm::dvec2 b, double width, double& t0, double& t1) const {
    return clip_to_window(a, b, project_.width, project_.height, width / 2 + 1, t0, t1);
  }

  std::vector<IdVertex> out;

 private:
  IdVertex line_vertex(glm::dvec2 at, double d, uint32_t key) const {
    return {glm::vec2(at), float(near_ / std::max(d, near_)), key};
  }

  WindowProjection project_;
  double near_;
};

// The key a silhouette segment draws: the path's key << 8 | floor(255 s / L).
uint32_t silhouette_value(const WindowPath& path, double s_mid) {
  double byte = path.length_px > 0 ? std::floor(255.0 * s_mid / path.length_px) : 0.0;
  return path.key << 8 | uint32_t(std::clamp(byte, 0.0, 255.0));
}

// A silhouette segment's quad is drawn in pieces at most this long, each with the byte of its
// own midpoint: so a pixel's byte is within half a piece of the arc length there, however long
// the mesh's segments (a coarse mesh's run across whole faces). Only the part that can cover
// a pixel is drawn: a narrow field of view makes segments of millions of pixels.
constexpr double kSilhouettePiecePx = 1.0;

void add_silhouette_segment(const WindowPath& path, size_t k, const StrokesParams& p, IdTriangles& tri) {
  size_t next = (k + 1) % path.window.size();
  glm::dvec2 a = path.window[k], b = path.window[next];
  double t0, t1;
  if (!tri.covers(a, b, p.id_silhouette_px, t0, t1)) return;
  double length = glm::distance(a, b), inv_a = 1 / path.depth[k], inv_b = 1 / path.depth[next];
  int pieces = std::max(1, int(std::ceil((t1 - t0) * length / kSilhouettePiecePx)));
  auto at = [&](int i) { return t0 + (t1 - t0) * i / pieces; };
  auto depth_at = [&](double t) { return 1 / ((1 - t) * inv_a + t * inv_b); };  // 1/d is affine in the window
  // At d (1 - bias), or nearer by the lift: its segment's world length times id_silhouette_lift.
  const double keep = 1.0 - double(p.id_depth_bias),
               lift = double(p.id_silhouette_lift) * glm::distance(path.world[k], path.world[next]);
  auto placed = [&](double d) { return std::min(d * keep, d - lift); };
  for (int i = 0; i < pieces; ++i) {
    double u0 = at(i), u1 = at(i + 1), s_mid = path.arc_px[k] + length * (u0 + u1) / 2;
    tri.segment(a + u0 * (b - a), a + u1 * (b - a), placed(depth_at(u0)), placed(depth_at(u1)), p.id_silhouette_px, 0.0,
                silhouette_value(path, s_mid));
  }
}

// A path's quads, where `rule` draws its kind.
void add_path(const WindowPath& path, const StrokesParams& p, IdLineRule rule, IdTriangles& tri) {
  if (path.kind == LineKind::Decal || path.kind == LineKind::Hatching) return;  // tested against its faces' keys
  bool silhouette = path.kind == LineKind::Silhouette;
  if (silhouette != (rule == IdLineRule::Silhouettes) || (silhouette && !path.front_facing)) return;
  size_t n = path.window.size(), segments = path.closed ? n : n - 1;
  for (size_t k = 0; k < segments; ++k) {
    if (silhouette) {
      add_silhouette_segment(path, k, p, tri);
      continue;
    }
    size_t next = (k + 1) % n;
    tri.segment(path.window[k], path.window[next], path.depth[k], path.depth[next], p.id_crease_px,
                p.id_crease_depth_bias, path.key);
  }
}

}  // namespace

Image key_channels(const ImageU32& keys) {
  Image out(keys.width, keys.height, 2);
  for (size_t i = 0; i < keys.data.size(); ++i) {
    out.data[2 * i] = float(keys.data[i] >> 16);
    out.data[2 * i + 1] = float(keys.data[i] & 0xffffu);
  }
  return out;
}

ImageU32 keys_from_channels(const Image& channels) {
  ImageU32 out(channels.width, channels.height, 1);
  for (size_t i = 0; i < out.data.size(); ++i)
    out.data[i] = uint32_t(channels.data[2 * i]) << 16 | uint32_t(channels.data[2 * i + 1]);
  return out;
}

std::vector<uint32_t> gbuffer_first_keys(const Scene& scene) {
  std::vector<uint32_t> first = first_faces(scene), out;
  for (size_t o = 0; o < scene.objects.size(); ++o)
    if (scene.objects[o].style != Style::Sketchy) out.push_back(first[o] + 1);
  return out;
}

std::vector<IdVertex> id_sketchy_face_triangles(const Scene& scene, const WindowLines& lines) {
  IdTriangles tri(scene);
  glm::dmat4 view(scene.camera.view());
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    if (object.style != Style::Sketchy) continue;
    for (uint32_t f = 0; f < object.mesh->triangles.size(); ++f) {
      ClipPoint corners[3];
      for (int k = 0; k < 3; ++k) {
        glm::dvec3 w(object.transform * glm::vec4(object.mesh->positions[object.mesh->triangles[f][k]], 1.0f));
        corners[k] = {w, -(view * glm::dvec4(w, 1.0)).z};
      }
      tri.face(corners, lines.face_key(o, f));
    }
  }
  return std::move(tri.out);
}

std::vector<IdVertex> id_line_triangles(const Scene& scene, const WindowLines& lines, const StrokesParams& p,
                                        IdLineRule rule) {
  IdTriangles tri(scene);
  for (const WindowPath& path : lines.paths) add_path(path, p, rule, tri);
  return std::move(tri.out);
}

}  // namespace plumbago

// Feature lines in the window, keyed for the ID image: see common/strokes/strokes.hpp.
#include "common/strokes/strokes.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "common/strokes/decal.hpp"
#include "common/strokes/mobile_hatching.hpp"

namespace plumbago {

namespace {

bool drawn(const SceneObject& o, LineObjects which) {
  return which == LineObjects::Strokes ? o.style == Style::Strokes : o.style != Style::Sketchy;
}

uint64_t edge_key(uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); }

// The faces around each edge, for the crease and border segments.
class EdgeFaces {
 public:
  explicit EdgeFaces(const Mesh& mesh) {
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) faces_[edge_key(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3])].push_back(f);
  }
  const std::vector<uint32_t>& of(uint32_t a, uint32_t b) const {
    static const std::vector<uint32_t> none;
    auto it = faces_.find(edge_key(a, b));
    return it == faces_.end() ? none : it->second;
  }

 private:
  std::unordered_map<uint64_t, std::vector<uint32_t>> faces_;
};

}  // namespace

uint32_t vertex_of(const Mesh& mesh, const SurfacePoint& p) {
  int k = int(std::max_element(&p.bary[0], &p.bary[0] + 3) - &p.bary[0]);
  return mesh.triangles[p.face][k];
}

bool faces_eye(const Mesh& mesh, const glm::dmat4& m, uint32_t f, glm::dvec3 eye) {
  glm::dvec3 p[3];
  for (int k = 0; k < 3; ++k) p[k] = glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.triangles[f][k]]), 1.0));
  return glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), eye - p[0]) > 0;
}

struct LineMeshes {
  std::vector<std::optional<FeatureLineMesh>> lines;  // per scene object; none where not drawn
  std::vector<std::shared_ptr<const EdgeFaces>> edges;
};

namespace {

class PathBuilder {
 public:
  PathBuilder(const Scene& scene, const WindowProjection& project, WindowLines& out)
      : scene_(scene), project_(project), out_(out), eye_(scene.camera.eye) {}

  // Adds the pieces of `path` in front of the near plane.
  // `key`: a silhouette's start record (assign_keys adds the base); 0 for the others. A
  // silhouette keeps its first piece only, the one its chain's key names: its segments lie in
  // front of the near plane, but a backend's float chain may hold a point that double
  // precision puts just behind it. `projected`: the points' (x, y, d) where the backend
  // projected them (ChainPath::window), else none.
  void add(const FeaturePath& path, LineKind kind, uint32_t object, const EdgeFaces* edges, uint32_t key = 0,
           const std::vector<glm::dvec3>* projected = nullptr) {
    const SceneObject& o = scene_.objects[object];
    glm::dmat4 m(o.transform);
    WindowPath piece = empty(path, kind, object, key);
    size_t n = path.points.size();
    bool whole = true, kept = false;
    auto keep = [&] {
      if (kind != LineKind::Silhouette || !kept) kept = flush(piece) || kept;
    };
    for (size_t i = 0; i < n; ++i) {
      glm::dvec3 w = glm::dvec3(m * glm::dvec4(path.points[i].position, 1.0));
      glm::dvec3 win = projected ? projected->at(i) : project_(w);
      if (win.z < double(scene_.camera.near)) {
        whole = false;
        keep();
        piece = empty(path, kind, object, key);
        continue;
      }
      piece.surface.push_back(path.points[i]);
      piece.world.push_back(w);
      piece.window.push_back({win.x, win.y});
      piece.depth.push_back(win.z);
      if (edges && i + 1 < n)
        piece.front_faces.push_back(front_faces(*o.mesh, m, path.points[i], path.points[i + 1], object, *edges));
    }
    piece.closed = path.closed && whole;
    if (edges && piece.closed)
      piece.front_faces.push_back(front_faces(*o.mesh, m, path.points[n - 1], path.points[0], object, *edges));
    keep();
  }

  // Adds the pieces of surface stroke `index` (Kalnins et al. 2002, §3, §6), a decal or a hatch with its
  // weight: split where a point missed the surface, where the object changes and at the
  // near plane.
  // `object`: a hatch's group's object (points elsewhere count as missed), else kMissed.
  void add_decal(const ProjectedDecal& decal, uint32_t index, const HatchWeight& weight, uint32_t object) {
    WindowPath start = decal_piece(kMissed, index, decal.hatch.group, weight), piece = start;
    auto restart = [&](uint32_t object) {
      flush_decal(piece);
      piece = start;
      piece.object = object;
    };
    for (DecalPoint d : decal.points) {
      if (object != kMissed && d.object != object) d.object = kMissed;
      if (d.object != piece.object) restart(d.object);
      if (d.object == kMissed) continue;
      glm::dvec3 local = decal_point_local(scene_, d);
      glm::dvec3 w = glm::dvec3(glm::dmat4(scene_.objects[d.object].transform) * glm::dvec4(local, 1.0));
      glm::dvec3 win = project_(w);
      if (win.z < double(scene_.camera.near)) {
        restart(d.object);
        continue;
      }
      piece.surface.push_back({d.face, d.bary, local});
      piece.world.push_back(w);
      piece.window.push_back({win.x, win.y});
      piece.depth.push_back(win.z);
      piece.pressure.push_back(d.pressure);
    }
    flush_decal(piece);
  }

 private:
  WindowPath empty(const FeaturePath& path, LineKind kind, uint32_t object, uint32_t key) const {
    return {kind, object, false, path.front_facing, key, {}, {}, {}, {}, {}, {}, 0, {}, 0};
  }

  glm::uvec2 front_faces(const Mesh& mesh, const glm::dmat4& m, const SurfacePoint& a, const SurfacePoint& b,
                         uint32_t object, const EdgeFaces& edges) const {
    glm::uvec2 keys(0);
    int k = 0;
    for (uint32_t f : edges.of(vertex_of(mesh, a), vertex_of(mesh, b)))
      if (k < 2 && faces_eye(mesh, m, f, glm::dvec3(eye_))) keys[k++] = out_.face_key(object, f);
    return keys;
  }

  // `group`: a hatch's group, -1 for a decal.
  static WindowPath decal_piece(uint32_t object, uint32_t index, int group, const HatchWeight& weight) {
    return {group >= 0 ? LineKind::Hatching : LineKind::Decal,
            object,
            false,
            true,
            0,
            {},
            {},
            {},
            {},
            {},
            {},
            0,
            {},
            index,
            weight.alpha,
            weight.width,
            group};
  }

  // A decal's or hatch's segments test the faces of their ends.
  void flush_decal(WindowPath& piece) {
    for (size_t k = 0; k + 1 < piece.surface.size(); ++k)
      piece.front_faces.push_back(
          {out_.face_key(piece.object, piece.surface[k].face), out_.face_key(piece.object, piece.surface[k + 1].face)});
    flush(piece);
  }

  // Keeps a piece of two points or more, with its window arc lengths; whether it did.
  bool flush(WindowPath& piece) {
    if (piece.window.size() < 2) return false;
    piece.front_faces.resize(piece.closed ? piece.window.size() : piece.window.size() - 1);
    piece.arc_px.push_back(0);
    for (size_t i = 1; i < piece.window.size(); ++i)
      piece.arc_px.push_back(piece.arc_px.back() + glm::distance(piece.window[i - 1], piece.window[i]));
    piece.length_px = piece.arc_px.back();
    if (piece.closed) piece.length_px += glm::distance(piece.window.back(), piece.window.front());
    out_.paths.push_back(std::move(piece));
    return true;
  }

  const Scene& scene_;
  const WindowProjection& project_;
  WindowLines& out_;
  glm::vec3 eye_;
};

// Object o's silhouettes (Kalnins et al. 2002, §4.5): its segments with both ends in front of
// the near plane, chained (common/strokes/feature_lines.hpp), in the order of their start face.
void add_window_silhouettes(const Scene& scene, const WindowProjection& project, uint32_t object,
                            const FeatureLineMesh& mesh, const StrokesParams& p, std::vector<ChainPath>& out) {
  glm::dmat4 m(scene.objects[object].transform);
  glm::dvec3 eye = eye_in_object_space(m, glm::dvec3(scene.camera.eye));
  std::vector<double> g = mesh.silhouette_values(eye, p.silhouette_normalized);
  std::vector<FaceSilhouette> segments = mesh.face_silhouettes(g, eye);
  auto behind = [&](const SurfacePoint& end) {
    return project(glm::dvec3(m * glm::dvec4(end.position, 1.0))).z < double(scene.camera.near);
  };
  for (FaceSilhouette& s : segments) s.exists = s.exists && !behind(s.ends[0]) && !behind(s.ends[1]);
  uint32_t first = first_faces(scene)[object];
  for (SilhouettePath& s : mesh.silhouette_paths(segments, p.keep_back_facing))
    out.push_back({object, first + s.start_face, std::move(s.path)});
}

// Numbers the paths (creases and borders first; a silhouette by its start record) and checks
// that the keys fit 32 bits.
void assign_keys(WindowLines& lines) {
  std::stable_partition(lines.paths.begin(), lines.paths.end(),
                        [](const WindowPath& p) { return p.kind != LineKind::Silhouette; });
  uint64_t next = uint64_t(lines.face_count) + 1;
  for (WindowPath& p : lines.paths)
    if (p.kind != LineKind::Silhouette) p.key = uint32_t(next++);
  lines.silhouette_base = silhouette_base(lines.face_count, next - 1 - lines.face_count);
  for (WindowPath& p : lines.paths)
    if (p.kind == LineKind::Silhouette) p.key += lines.silhouette_base;
}

}  // namespace

uint32_t silhouette_base(uint32_t face_count, uint64_t crease_paths) {
  const uint64_t base = ((face_count + crease_paths) >> 8) + 1;
  if (base + face_count >= (uint64_t(1) << 24))
    throw std::length_error("the ID image's keys do not fit 32 bits: " + std::to_string(face_count) + " faces, " +
                            std::to_string(crease_paths) + " crease and border paths");
  return uint32_t(base);
}

const char* line_kind_name(LineKind kind) {
  switch (kind) {
    case LineKind::Crease:
      return "crease";
    case LineKind::Border:
      return "border";
    case LineKind::Silhouette:
      return "silhouette";
    case LineKind::Decal:
      return "decal";
    case LineKind::Hatching:
      break;
  }
  return "hatching";
}

WindowProjection::WindowProjection(const Camera& camera, int width, int height)
    : view(glm::dmat4(camera.view())),
      clip(glm::dmat4(camera.projection(float(width) / float(height))) * view),
      width(width),
      height(height) {}

glm::dvec3 WindowProjection::operator()(glm::dvec3 world) const {
  glm::dvec4 c = clip * glm::dvec4(world, 1.0);
  double d = -(view * glm::dvec4(world, 1.0)).z;
  return {(c.x / c.w * 0.5 + 0.5) * width, (c.y / c.w * 0.5 + 0.5) * height, d};
}

bool clip_to_window(glm::dvec2 a, glm::dvec2 b, double width, double height, double margin, double& t0, double& t1) {
  const glm::dvec2 d = b - a, lo(-margin), hi(width + margin, height + margin);
  t0 = 0, t1 = 1;
  for (int c = 0; c < 2; ++c) {
    if (d[c] == 0) {
      if (a[c] < lo[c] || a[c] > hi[c]) return false;
      continue;
    }
    double u = (lo[c] - a[c]) / d[c], v = (hi[c] - a[c]) / d[c];
    t0 = std::max(t0, std::min(u, v)), t1 = std::min(t1, std::max(u, v));
  }
  return t0 <= t1;
}

std::shared_ptr<const LineMeshes> line_meshes(const Scene& scene, const StrokesParams& p, LineObjects which) {
  auto out = std::make_shared<LineMeshes>();
  for (const SceneObject& o : scene.objects) {
    bool drawn_here = drawn(o, which);
    out->lines.push_back(drawn_here ? std::optional(FeatureLineMesh(*o.mesh, p.crease_deg)) : std::nullopt);
    out->edges.push_back(drawn_here ? std::make_shared<const EdgeFaces>(*o.mesh) : nullptr);
  }
  return out;
}

std::vector<uint32_t> first_faces(const Scene& scene) {
  std::vector<uint32_t> first{0};
  for (const SceneObject& o : scene.objects) first.push_back(first.back() + uint32_t(o.mesh->triangles.size()));
  return first;
}

const std::vector<uint32_t>& edge_faces(const LineMeshes& meshes, size_t object, uint32_t a, uint32_t b) {
  static const std::vector<uint32_t> none;
  const auto& edges = meshes.edges.at(object);
  return edges ? edges->of(a, b) : none;
}

const FeatureLineMesh* line_mesh(const LineMeshes& meshes, size_t object) {
  const auto& mesh = meshes.lines.at(object);
  return mesh && !mesh->corner_normals().empty() ? &*mesh : nullptr;
}

SurfaceStrokes surface_strokes(const Scene& scene, const DecalSurface& decals, const MobileHatching* mobile,
                               bool move_copies) {
  SurfaceStrokes out;
  const auto hatching = scene.params.get<HatchingParams>();
  out.hatching = hatch_states(scene, decals, hatching);
  std::vector<HatchWeight> weights = hatch_weights(out.hatching, decals);
  std::optional<MobileHatching> own_mobile;
  if (!mobile) mobile = &own_mobile.emplace(scene, decals);
  out.placed = mobile->place(scene, given_value(hatching.mobile_threshold), given_value(hatching.mobile_fade));
  for (uint32_t d = 0; d < decals.size(); ++d) {
    out.styles.push_back(decals[d].style);
    int group = decals[d].hatch.group;
    const uint32_t object = group >= 0 ? out.hatching[group].object : kMissed;
    if (weights[d].alpha == 0) continue;
    if (!mobile->moves(d)) {
      out.drawn.push_back({&decals[d], d, weights[d], object});
      continue;
    }
    const MobileHatching::Placement& at = out.placed[size_t(group)];
    std::vector<MobileHatching::Copy> moved;
    if (move_copies) moved = mobile->copies(decals, d, out.placed);
    for (size_t m = 0; m < at.u.size(); ++m) {
      HatchWeight weight = weights[d];
      weight.alpha *= at.alpha[m];
      if (weight.alpha == 0) continue;
      if (move_copies) out.copies.push_back(std::move(moved[m].decal));
      out.drawn.push_back({move_copies ? &out.copies.back() : &decals[d], d, weight, object, int(m)});
    }
  }
  return out;
}

WindowLines window_lines(const Scene& scene, const StrokesParams& p, LineObjects which, const LineMeshes* prepared,
                         const SurfaceStrokes* surface, const std::vector<ChainPath>* silhouettes, bool whole) {
  std::shared_ptr<const LineMeshes> made;
  if (!prepared) made = line_meshes(scene, p, which), prepared = made.get();
  WindowLines out;
  out.width = scene.width, out.height = scene.height;
  out.first_face = first_faces(scene);
  out.face_count = out.first_face.back();
  out.first_face.pop_back();
  WindowProjection project(scene.camera, scene.width, scene.height);
  PathBuilder builder(scene, project, out);
  std::vector<ChainPath> own;
  for (uint32_t i = 0; i < scene.objects.size(); ++i) {
    const FeatureLineMesh* mesh = line_mesh(*prepared, i);
    if (!mesh) continue;
    const FeatureLines& fixed = mesh->creases_and_borders();
    const EdgeFaces* edges = prepared->edges[i].get();
    if (whole) {
      for (const FeaturePath& path : fixed.creases) builder.add(path, LineKind::Crease, i, edges);
      for (const FeaturePath& path : fixed.borders) builder.add(path, LineKind::Border, i, edges);
    }
    if (!silhouettes) add_window_silhouettes(scene, project, i, *mesh, p, own);
  }
  for (const ChainPath& c : silhouettes ? *silhouettes : own)
    builder.add(c.path, LineKind::Silhouette, c.object, nullptr, c.start_record,
                c.window.empty() ? nullptr : &c.window);
  assign_keys(out);
  if (!surface) return out;
  out.hatching = surface->hatching;
  out.decal_styles = surface->styles;
  if (whole)
    for (const SurfaceStroke& s : surface->drawn) builder.add_decal(*s.decal, s.index, s.weight, s.object);
  return out;
}

}  // namespace plumbago

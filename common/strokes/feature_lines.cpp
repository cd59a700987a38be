// Feature lines (Kalnins et al. 2002, §4.5): see common/strokes/feature_lines.hpp for the definitions.
#include "common/strokes/feature_lines.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include <tbb/parallel_for.h>

#include "common/mesh/mesh_topology.hpp"

namespace plumbago {
namespace {

constexpr double kZeroG = -1e-8;  // Kalnins et al. 2002, §4.5: g = 0 exactly is taken as -1e-8
constexpr int32_t kNone = -1;

enum class EdgeKind : uint8_t { smooth, crease, border };

// The mesh in double precision with its adjacency, face normals and edge kinds.
struct Geometry {
  const Mesh& mesh;
  MeshTopology topology;
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> face_area_normals;  // cross(b - a, c - a): twice the area, outward
  std::vector<glm::dvec3> face_unit_normals;  // zero for a zero-area face
  std::vector<EdgeKind> edge_kinds;

  glm::dvec3 corner(uint32_t f, int k) const { return positions[mesh.triangles[f][k]]; }
};

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::dvec3 unit_or_zero(glm::dvec3 v) {
  double len = glm::length(v);
  return len > 0 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

// The corner (0, 1, 2) of face f at vertex v, or -1.
int corner_of(const Mesh& mesh, uint32_t f, uint32_t v) {
  for (int k = 0; k < 3; ++k)
    if (mesh.triangles[f][k] == v) return k;
  return -1;
}

// Kalnins et al. 2002, §4.5: a crease when n1·n2 < cos(crease_deg); a border when the edge has one face.
EdgeKind classify_edge(const MeshTopology::Edge& e, const std::vector<glm::dvec3>& unit_normals, double cos_crease) {
  if (e.face[1] < 0) return EdgeKind::border;
  glm::dvec3 n1 = unit_normals[size_t(e.face[0])], n2 = unit_normals[size_t(e.face[1])];
  if (n1 == glm::dvec3(0.0) || n2 == glm::dvec3(0.0)) return EdgeKind::smooth;  // no dihedral angle
  return glm::dot(n1, n2) < cos_crease ? EdgeKind::crease : EdgeKind::smooth;
}

Geometry build_geometry(const Mesh& mesh, double crease_deg) {
  Geometry g{mesh, build_topology(mesh), {}, {}, {}, {}};
  g.positions.assign(mesh.positions.begin(), mesh.positions.end());
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    glm::dvec3 a = g.corner(f, 0), b = g.corner(f, 1), c = g.corner(f, 2);
    g.face_area_normals.push_back(glm::cross(b - a, c - a));
    g.face_unit_normals.push_back(unit_or_zero(g.face_area_normals.back()));
  }
  double cos_crease = std::cos(crease_deg * std::numbers::pi / 180.0);
  for (const auto& e : g.topology.edges) g.edge_kinds.push_back(classify_edge(e, g.face_unit_normals, cos_crease));
  return g;
}

// --- chaining edges into paths ---------------------------------------------------------

// A chain of mesh vertices joined by the listed edges: edges[i] joins vertices[i] and
// vertices[i + 1] (and, when closed, the last edge joins the last vertex to the first).
struct VertexChain {
  std::vector<uint32_t> vertices, edges;
  bool closed = false;
};

// The crease and border edges around each vertex.
std::vector<std::vector<uint32_t>> feature_edges_of_vertices(const Geometry& g) {
  std::vector<std::vector<uint32_t>> around(g.positions.size());
  for (uint32_t e = 0; e < g.topology.edges.size(); ++e)
    if (g.edge_kinds[e] != EdgeKind::smooth) {
      around[g.topology.edges[e].from].push_back(e);
      around[g.topology.edges[e].to].push_back(e);
    }
  return around;
}

uint32_t other_end(const MeshTopology::Edge& e, uint32_t v) { return e.from == v ? e.to : e.from; }

// Walks from vertex `start` along `edge`, through vertices of degree 2, until a vertex of
// another degree, an edge already taken, or `start` again (then the chain is closed).
VertexChain walk_chain(const Geometry& g, const std::vector<std::vector<uint32_t>>& around, std::vector<bool>& taken,
                       uint32_t start, uint32_t edge) {
  VertexChain chain;
  chain.vertices.push_back(start);
  uint32_t v = start;
  while (!taken[edge]) {
    taken[edge] = true;
    chain.edges.push_back(edge);
    v = other_end(g.topology.edges[edge], v);
    if (v == start && around[v].size() == 2) {
      chain.closed = true;
      break;
    }
    chain.vertices.push_back(v);
    if (around[v].size() != 2) break;
    edge = around[v][0] == edge ? around[v][1] : around[v][0];
  }
  return chain;
}

// Kalnins et al. 2002, §4.5: maximal paths of the crease+border graph; paths start at vertices of degree
// other than 2, and what is left afterwards is closed loops.
std::vector<VertexChain> chain_feature_edges(const Geometry& g) {
  auto around = feature_edges_of_vertices(g);
  std::vector<bool> taken(g.topology.edges.size(), false);
  std::vector<VertexChain> chains;
  for (uint32_t v = 0; v < around.size(); ++v)
    if (around[v].size() != 2)
      for (uint32_t e : around[v])
        if (!taken[e]) chains.push_back(walk_chain(g, around, taken, v, e));
  for (uint32_t v = 0; v < around.size(); ++v)
    for (uint32_t e : around[v])
      if (!taken[e]) chains.push_back(walk_chain(g, around, taken, v, e));
  return chains;
}

// A vertex as a surface point of the lowest-index face holding it (`fallback` otherwise).
SurfacePoint vertex_point(const Geometry& g, uint32_t v, uint32_t fallback) {
  uint32_t face = fallback;
  for (uint32_t f : g.topology.faces_of(v))
    if (corner_of(g.mesh, f, v) >= 0) {
      face = f;
      break;
    }
  SurfacePoint p{face, glm::dvec3(0.0), g.positions[v]};
  int k = corner_of(g.mesh, face, v);
  if (k >= 0) p.bary[k] = 1.0;
  return p;
}

// --- cutting paths where a per-segment label changes -----------------------------------

// Points with one label per segment (segment i runs from point i to point i + 1, the
// last one back to point 0 when closed).
struct LabeledPath {
  std::vector<SurfacePoint> points;
  std::vector<int> labels;
  bool closed = false;
};

// Runs of equal label: a closed path whose segments all share a label stays closed;
// otherwise every run is an open path, a closed one being started at a label change.
std::vector<std::pair<FeaturePath, int>> split_by_label(const LabeledPath& path) {
  std::vector<std::pair<FeaturePath, int>> runs;
  const size_t n = path.points.size(), segments = path.labels.size();
  if (segments == 0) return runs;
  bool uniform = std::all_of(path.labels.begin(), path.labels.end(), [&](int l) { return l == path.labels[0]; });
  if (path.closed && uniform) {
    runs.push_back({FeaturePath{path.points, true, true}, path.labels[0]});
    return runs;
  }
  size_t first = 0;
  if (path.closed)
    while (path.labels[first] == path.labels[(first + segments - 1) % segments]) ++first;
  for (size_t s = 0; s < segments; ++s) {
    size_t i = (first + s) % segments;
    if (s == 0 || path.labels[i] != runs.back().second)
      runs.push_back({FeaturePath{{path.points[i]}, false, true}, path.labels[i]});
    runs.back().first.points.push_back(path.points[(i + 1) % n]);
  }
  return runs;
}

// --- creases and borders ---------------------------------------------------------------

LabeledPath chain_points(const Geometry& g, const VertexChain& chain) {
  LabeledPath path;
  path.closed = chain.closed;
  for (size_t i = 0; i < chain.vertices.size(); ++i) {
    uint32_t edge = chain.edges[std::min(i, chain.edges.size() - 1)];
    path.points.push_back(vertex_point(g, chain.vertices[i], uint32_t(g.topology.edges[edge].face[0])));
  }
  for (uint32_t e : chain.edges) path.labels.push_back(int(g.edge_kinds[e]));
  return path;
}

void add_creases_and_borders(const Geometry& g, FeatureLines& out) {
  for (const auto& chain : chain_feature_edges(g))
    for (auto& [path, kind] : split_by_label(chain_points(g, chain)))
      (EdgeKind(kind) == EdgeKind::crease ? out.creases : out.borders).push_back(std::move(path));
}

// --- crease-aware normals and g ----------------------------------------------------------

struct DisjointSets {
  std::vector<uint32_t> parent;
  explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t root(uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(uint32_t a, uint32_t b) { parent[root(a)] = root(b); }
};

// Face corners (3 f + k) joined across every smooth edge at both of its ends: each set
// is the fan of faces around a vertex between creases and borders.
DisjointSets corner_fans(const Geometry& g) {
  DisjointSets fans(3 * g.mesh.triangles.size());
  for (uint32_t e = 0; e < g.topology.edges.size(); ++e) {
    if (g.edge_kinds[e] != EdgeKind::smooth) continue;
    const auto& edge = g.topology.edges[e];
    auto f0 = uint32_t(edge.face[0]), f1 = uint32_t(edge.face[1]);
    for (uint32_t v : {edge.from, edge.to}) {
      int k0 = corner_of(g.mesh, f0, v), k1 = corner_of(g.mesh, f1, v);
      if (k0 >= 0 && k1 >= 0) fans.join(3 * f0 + uint32_t(k0), 3 * f1 + uint32_t(k1));
    }
  }
  return fans;
}

// Face f's contribution to the normal at its corner k, with Max's weights (N. Max 1999,
// "Weights for computing vertex normals from facet normals"): (e1 × e2) / (|e1|^2 |e2|^2),
// e1, e2 the corner's two edges, i.e. the unit face normal times sin(angle) / (|e1| |e2|).
// They are exact for a fan inscribed in a sphere, and do not depend on how a strip is
// cut into triangles (area weights tilt the rim normals of the procedural cylinder by
// pi / (3 n), 14 times its chord error). Zero for a zero-area face or a zero-length edge.
glm::dvec3 weighted_corner_normal(const Geometry& g, uint32_t f, int k) {
  glm::dvec3 e1 = g.corner(f, (k + 1) % 3) - g.corner(f, k), e2 = g.corner(f, (k + 2) % 3) - g.corner(f, k);
  double d = glm::dot(e1, e1) * glm::dot(e2, e2);
  glm::dvec3 n = d > 0 ? glm::cross(e1, e2) / d : glm::dvec3(0.0);
  return finite(n) ? n : glm::dvec3(0.0);
}

// Kalnins et al. 2002, §4.5 crease-aware vertex normals, one per face corner: the weighted face normals
// (above) summed over the corner's fan, normalized (zero where they sum to zero).
std::vector<glm::dvec3> crease_aware_corner_normals(const Geometry& g) {
  DisjointSets fans = corner_fans(g);
  const size_t corners = 3 * g.mesh.triangles.size();
  std::vector<glm::dvec3> sum(corners, glm::dvec3(0.0));
  for (uint32_t c = 0; c < corners; ++c) sum[fans.root(c)] += weighted_corner_normal(g, c / 3, int(c % 3));
  std::vector<glm::dvec3> normals(corners);
  for (uint32_t c = 0; c < corners; ++c) normals[c] = unit_or_zero(sum[fans.root(c)]);
  return normals;
}

// Kalnins et al. 2002, §4.5: g = n · normalize(eye - x), or the paper's n · (eye - x); 0 -> -1e-8.
double silhouette_test(glm::dvec3 normal, glm::dvec3 x, glm::dvec3 eye, bool normalized) {
  glm::dvec3 to_eye = normalized ? unit_or_zero(eye - x) : eye - x;
  double value = glm::dot(normal, to_eye);
  return value == 0 || !std::isfinite(value) ? kZeroG : value;
}

std::vector<double> corner_silhouette_values(const Geometry& g, const std::vector<glm::dvec3>& normals, glm::dvec3 eye,
                                             bool normalized) {
  std::vector<double> values(normals.size());
  tbb::parallel_for(size_t(0), normals.size(), [&](size_t c) {
    values[c] = silhouette_test(normals[c], g.corner(uint32_t(c / 3), int(c % 3)), eye, normalized);
  });
  return values;
}

// --- silhouette segments -----------------------------------------------------------------

// The corners of face f's slot in the edge's own direction (from -> to).
std::pair<int, int> slot_corners(const Geometry& g, uint32_t f, int slot) {
  const auto& edge = g.topology.edges[g.topology.face_edges[f][slot]];
  int ka = slot, kb = (slot + 1) % 3;
  if (g.mesh.triangles[f][ka] != edge.from) std::swap(ka, kb);
  return {ka, kb};
}

// The point at t from corner ka to corner kb of face f.
SurfacePoint point_on_edge(const Geometry& g, uint32_t f, int ka, int kb, double t) {
  glm::dvec3 a = g.corner(f, ka), b = g.corner(f, kb);
  SurfacePoint p{f, glm::dvec3(0.0), a + (b - a) * t};
  p.bary[ka] = 1 - t;
  p.bary[kb] = t;
  return p;
}

// Kalnins et al. 2002, §4.5: the crossing on the edge in slot `slot` of face f (corners slot, slot + 1),
// p = a + (b - a) g_a / (g_a - g_b), a -> b running the edge's own way (from -> to) so
// that both faces of the edge give the same point. The slot is one where g changes sign.
SurfacePoint edge_crossing(const Geometry& g, const std::vector<double>& values, uint32_t f, int slot) {
  auto [ka, kb] = slot_corners(g, f, slot);
  double ga = values[3 * f + uint32_t(ka)], gb = values[3 * f + uint32_t(kb)];
  return point_on_edge(g, f, ka, kb, ga / (ga - gb));  // opposite signs, neither 0: t in (0, 1)
}

bool sign_changes(const std::vector<double>& values, uint32_t f, int slot) {
  return (values[3 * f + uint32_t(slot)] > 0) != (values[3 * f + uint32_t((slot + 1) % 3)] > 0);
}

// The gradient of g interpolated linearly over face f, times (2 area)^2 (only its
// direction is used): sum over corners of g_i (N × e_i), e_i the edge opposite corner i
// running counter-clockwise, N = face_area_normals[f]. Zero for a zero-area face.
glm::dvec3 scaled_gradient(const Geometry& g, const std::vector<double>& values, uint32_t f) {
  glm::dvec3 n = g.face_area_normals[f], gradient(0.0);
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 opposite = g.corner(f, (i + 2) % 3) - g.corner(f, (i + 1) % 3);
    gradient += values[3 * f + uint32_t(i)] * glm::cross(n, opposite);
  }
  return gradient;
}

// Face f's segment, oriented by the sign of g at its lone corner (oriented_slots), and its
// facing: ∇g · (eye - m) >= 0 (Kalnins et al. 2002, §4.5 front/back).
FaceSilhouette face_segment(const Geometry& g, const std::vector<double>& values, glm::dvec3 eye, uint32_t f) {
  int slot[2], found = 0;
  for (int k = 0; k < 3 && found < 2; ++k)
    if (sign_changes(values, f, k)) slot[found++] = k;
  if (found < 2) return {};
  int c = lone_corner(slot[0], slot[1]);
  SegmentSlots o = oriented_slots(slot[0], slot[1], values[3 * f + uint32_t(c)] > 0);
  FaceSilhouette s{
      true, {o.entry, o.exit}, {edge_crossing(g, values, f, o.entry), edge_crossing(g, values, f, o.exit)}};
  glm::dvec3 mid = 0.5 * (s.ends[0].position + s.ends[1].position);
  s.front = glm::dot(scaled_gradient(g, values, f), eye - mid) >= 0;
  return s;
}

// The face across the smooth edge in face f's slot k and its slot on that edge; kNone across
// a crease, a border or a non-manifold edge.
std::pair<int32_t, int> face_across(const Geometry& g, uint32_t f, int k) {
  uint32_t e = g.topology.face_edges[f][k];
  const auto& edge = g.topology.edges[e];
  int32_t other = edge.face[0] == int32_t(f) ? edge.face[1] : edge.face[0];
  if (g.edge_kinds[e] != EdgeKind::smooth || other < 0 || uint32_t(other) == f) return {kNone, -1};
  for (int j = 0; j < 3; ++j)
    if (g.topology.face_edges[size_t(other)][j] == e) return {other, j};
  return {kNone, -1};
}

// The segment across the slot that face f's segment leaves by (end 1) or enters by (end 0),
// when it goes on through that edge the other way with the same facing; kNone otherwise.
int32_t linked(const Geometry& g, const std::vector<FaceSilhouette>& segments, uint32_t f, int end) {
  auto [other, slot] = face_across(g, f, segments[f].slots[end]);
  if (other == kNone) return kNone;
  const FaceSilhouette& s = segments[size_t(other)];
  return s.exists && s.front == segments[f].front && s.slots[1 - end] == slot ? other : kNone;
}

// A chain of segments: its faces from its start.
struct SilhouetteChain {
  std::vector<uint32_t> faces;
  bool closed = false;
};

// Kalnins et al. 2002, §4.5 chaining by the links: open chains from the segment with no
// predecessor, then loops from their lowest face; each face at most once. Ordered by start.
std::vector<SilhouetteChain> chain_segments(const Geometry& g, const std::vector<FaceSilhouette>& segments) {
  std::vector<bool> chained(segments.size(), false);
  std::vector<SilhouetteChain> chains;
  auto walk = [&](uint32_t start) {
    SilhouetteChain chain;
    int32_t f = int32_t(start);
    do {
      chained[size_t(f)] = true;
      chain.faces.push_back(uint32_t(f));
      f = linked(g, segments, uint32_t(f), 1);
    } while (f != kNone && !chained[size_t(f)]);
    chain.closed = f == int32_t(start);
    chains.push_back(std::move(chain));
  };
  for (uint32_t f = 0; f < segments.size(); ++f)
    if (segments[f].exists && linked(g, segments, f, 0) == kNone) walk(f);
  for (uint32_t f = 0; f < segments.size(); ++f)
    if (segments[f].exists && !chained[f]) walk(f);
  std::sort(chains.begin(), chains.end(), [](const auto& a, const auto& b) { return a.faces[0] < b.faces[0]; });
  return chains;
}

// A chain's crossings, each on its own face: each face's entry, then the last face's exit of
// an open chain.
FeaturePath chain_path(const std::vector<FaceSilhouette>& segments, const SilhouetteChain& chain) {
  FeaturePath path{{}, chain.closed, segments[chain.faces[0]].front};
  for (uint32_t f : chain.faces) path.points.push_back(segments[f].ends[0]);
  if (!chain.closed) path.points.push_back(segments[chain.faces.back()].ends[1]);
  return path;
}

}  // namespace

glm::dvec3 eye_in_object_space(const glm::dmat4& object_to_world, glm::dvec3 eye_world) {
  glm::dvec4 e = glm::inverse(object_to_world) * glm::dvec4(eye_world, 1.0);
  return glm::dvec3(e) / e.w;
}

// The view-independent part: adjacency, crease-aware normals, creases and borders.
struct FeatureLineMesh::Impl {
  Impl(const Mesh& mesh, double crease_deg)
      : g(build_geometry(mesh, crease_deg)), normals(crease_aware_corner_normals(g)) {
    add_creases_and_borders(g, fixed);
  }
  Geometry g;
  std::vector<glm::dvec3> normals;
  FeatureLines fixed;  // creases and borders
};

FeatureLineMesh::FeatureLineMesh(const Mesh& mesh, double crease_deg)
    : impl_(mesh.triangles.empty() ? nullptr : std::make_shared<const Impl>(mesh, crease_deg)) {}

FeatureLines FeatureLineMesh::lines(const glm::dmat4& object_to_world, glm::dvec3 eye_world,
                                    const FeatureLineOptions& options) const {
  if (!impl_) return {};
  FeatureLines out = impl_->fixed;
  glm::dvec3 eye = eye_in_object_space(object_to_world, eye_world);
  std::vector<double> values = silhouette_values(eye, options.silhouette_normalized);
  for (SilhouettePath& p : silhouette_paths(face_silhouettes(values, eye), options.keep_back_facing))
    out.silhouettes.push_back(std::move(p.path));
  return out;
}

const FeatureLines& FeatureLineMesh::creases_and_borders() const {
  static const FeatureLines none;
  return impl_ ? impl_->fixed : none;
}

const std::vector<glm::dvec3>& FeatureLineMesh::corner_normals() const {
  static const std::vector<glm::dvec3> none;
  return impl_ ? impl_->normals : none;
}

uint32_t FeatureLineMesh::reversed_slots(uint32_t f) const {
  const Geometry& g = impl_->g;
  uint32_t bits = 0;
  for (int k = 0; k < 3; ++k)
    if (g.mesh.triangles[f][k] != g.topology.edges[g.topology.face_edges[f][k]].from) bits |= 1u << k;
  return bits;
}

std::pair<int32_t, int> FeatureLineMesh::across(uint32_t f, int k) const { return face_across(impl_->g, f, k); }

std::vector<double> FeatureLineMesh::silhouette_values(glm::dvec3 eye_object, bool normalized) const {
  return corner_silhouette_values(impl_->g, impl_->normals, eye_object, normalized);
}

FaceSilhouette FeatureLineMesh::face_silhouette(const std::vector<double>& values, glm::dvec3 eye_object,
                                                uint32_t f) const {
  return face_segment(impl_->g, values, eye_object, f);
}

SurfacePoint FeatureLineMesh::slot_point(uint32_t f, int slot, double t) const {
  auto [ka, kb] = slot_corners(impl_->g, f, slot);
  return point_on_edge(impl_->g, f, ka, kb, t);
}

std::vector<FaceSilhouette> FeatureLineMesh::face_silhouettes(const std::vector<double>& values,
                                                              glm::dvec3 eye_object) const {
  std::vector<FaceSilhouette> segments(impl_->g.mesh.triangles.size());
  tbb::parallel_for(size_t(0), segments.size(),
                    [&](size_t f) { segments[f] = face_segment(impl_->g, values, eye_object, uint32_t(f)); });
  return segments;
}

std::vector<SilhouettePath> FeatureLineMesh::silhouette_paths(const std::vector<FaceSilhouette>& segments,
                                                              bool keep_back_facing) const {
  std::vector<SilhouettePath> out;
  for (const SilhouetteChain& chain : chain_segments(impl_->g, segments)) {
    FeaturePath path = chain_path(segments, chain);
    if (path.front_facing || keep_back_facing) out.push_back({chain.faces[0], std::move(path)});
  }
  return out;
}

std::vector<double> silhouette_function(const Mesh& mesh, glm::dvec3 eye_object, const FeatureLineOptions& options) {
  Geometry g = build_geometry(mesh, options.crease_deg);
  return corner_silhouette_values(g, crease_aware_corner_normals(g), eye_object, options.silhouette_normalized);
}

FeatureLines feature_lines(const Mesh& mesh, const glm::dmat4& object_to_world, glm::dvec3 eye_world,
                           const FeatureLineOptions& options) {
  return FeatureLineMesh(mesh, options.crease_deg).lines(object_to_world, eye_world, options);
}

}  // namespace plumbago

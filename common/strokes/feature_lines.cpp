// Feature lines (Kalnins et al. 2002, §4.5): see common/strokes/feature_lines.hpp for the definitions.
#include "common/strokes/feature_lines.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

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
  for (uint32_t c = 0; c < normals.size(); ++c)
    values[c] = silhouette_test(normals[c], g.corner(c / 3, int(c % 3)), eye, normalized);
  return values;
}

// --- silhouette segments -----------------------------------------------------------------

// The segment of g = 0 in one face: the two face slots (k: edge from corner k to k + 1)
// where g changes sign, and whether it is front-facing.
struct FaceSegment {
  int slot[2] = {-1, -1};
  bool front = true;
  bool exists() const { return slot[0] >= 0; }
};

// Kalnins et al. 2002, §4.5: the crossing on the edge in slot `slot` of face f (corners slot, slot + 1),
// p = a + (b - a) g_a / (g_a - g_b), a -> b running the edge's own way (from -> to) so
// that both faces of the edge give the same point. The slot is one where g changes sign.
SurfacePoint edge_crossing(const Geometry& g, const std::vector<double>& values, uint32_t f, int slot) {
  const auto& edge = g.topology.edges[g.topology.face_edges[f][slot]];
  int ka = slot, kb = (slot + 1) % 3;
  if (g.mesh.triangles[f][ka] != edge.from) std::swap(ka, kb);
  double ga = values[3 * f + uint32_t(ka)], gb = values[3 * f + uint32_t(kb)];
  double t = ga / (ga - gb);  // opposite signs, neither 0: t in (0, 1)
  glm::dvec3 a = g.corner(f, ka), b = g.corner(f, kb);
  SurfacePoint p{f, glm::dvec3(0.0), a + (b - a) * t};
  p.bary[ka] = 1 - t;
  p.bary[kb] = t;
  return p;
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

FaceSegment face_segment(const Geometry& g, const std::vector<double>& values, glm::dvec3 eye, uint32_t f) {
  FaceSegment s;
  int found = 0;
  for (int k = 0; k < 3 && found < 2; ++k)
    if (sign_changes(values, f, k)) s.slot[found++] = k;
  if (found < 2) return FaceSegment{};
  glm::dvec3 mid =
      0.5 * (edge_crossing(g, values, f, s.slot[0]).position + edge_crossing(g, values, f, s.slot[1]).position);
  s.front = glm::dot(scaled_gradient(g, values, f), eye - mid) >= 0;  // Kalnins et al. 2002, §4.5 front/back
  return s;
}

// A face and one of its slots.
struct FaceSlot {
  int32_t face = kNone;
  int slot = -1;
};

// The slot of face f that lies on edge e and where g changes sign, or -1.
int crossing_slot_on_edge(const Geometry& g, const std::vector<double>& values, uint32_t f, uint32_t e) {
  for (int k = 0; k < 3; ++k)
    if (g.topology.face_edges[f][k] == e && sign_changes(values, f, k)) return k;
  return -1;
}

// Where the path goes on through slot `slot` of face f: the other face of that edge and
// its slot on the edge, when the edge is smooth and that face holds a segment crossing
// it; none otherwise (a crease, a border, no matching segment).
FaceSlot face_across(const Geometry& g, const std::vector<double>& values, const std::vector<FaceSegment>& segments,
                     uint32_t f, int slot) {
  uint32_t e = g.topology.face_edges[f][slot];
  if (g.edge_kinds[e] != EdgeKind::smooth) return {};
  const auto& edge = g.topology.edges[e];
  int32_t other = edge.face[0] == int32_t(f) ? edge.face[1] : edge.face[0];
  if (other < 0 || uint32_t(other) == f || !segments[size_t(other)].exists()) return {};
  int k = crossing_slot_on_edge(g, values, uint32_t(other), e);
  if (k < 0) return {};
  return {other, k};
}

int other_slot(const FaceSegment& s, int slot) { return s.slot[0] == slot ? s.slot[1] : s.slot[0]; }

// A traced silhouette: the faces in order, and the slot through which it enters each (the
// first entry is where an open path begins) and leaves the last one.
struct FaceChain {
  std::vector<uint32_t> faces;
  std::vector<int> entry_slots;
  int exit_slot = -1;
  bool closed = false;
};

// Traces from face `start`, entering through slot `entry`, face to face, each face at
// most once (`visited`), so at most one step per face of the mesh.
FaceChain trace_faces(const Geometry& g, const std::vector<double>& values, const std::vector<FaceSegment>& segments,
                      std::vector<bool>& visited, uint32_t start, int entry) {
  FaceChain chain;
  uint32_t f = start;
  while (true) {
    visited[f] = true;
    chain.faces.push_back(f);
    chain.entry_slots.push_back(entry);
    chain.exit_slot = other_slot(segments[f], entry);
    FaceSlot next = face_across(g, values, segments, f, chain.exit_slot);
    if (next.face == int32_t(start) && chain.faces.size() > 1 && next.slot == chain.entry_slots[0]) {
      chain.closed = true;
      break;
    }
    if (next.face == kNone || visited[size_t(next.face)]) break;
    f = uint32_t(next.face);
    entry = next.slot;
  }
  return chain;
}

// Kalnins et al. 2002, §4.5 tracing: open paths from their dead ends (a crease, a border, a face without a
// matching segment), then closed loops from whatever is left.
std::vector<FaceChain> trace_silhouettes(const Geometry& g, const std::vector<double>& values,
                                         const std::vector<FaceSegment>& segments) {
  std::vector<bool> visited(segments.size(), false);
  std::vector<FaceChain> chains;
  for (uint32_t f = 0; f < segments.size(); ++f)
    for (int end = 0; end < 2; ++end)
      if (segments[f].exists() && !visited[f] &&
          face_across(g, values, segments, f, segments[f].slot[end]).face == kNone)
        chains.push_back(trace_faces(g, values, segments, visited, f, segments[f].slot[end]));
  for (uint32_t f = 0; f < segments.size(); ++f)
    if (segments[f].exists() && !visited[f])
      chains.push_back(trace_faces(g, values, segments, visited, f, segments[f].slot[0]));
  return chains;
}

// A crossing as a path point: on a smooth edge it carries that edge's face[0] (when that
// face sees the crossing too), else the face the path runs in.
SurfacePoint crossing_point(const Geometry& g, const std::vector<double>& values, uint32_t f, int slot) {
  uint32_t e = g.topology.face_edges[f][slot];
  const auto& edge = g.topology.edges[e];
  if (g.edge_kinds[e] == EdgeKind::smooth && edge.face[0] >= 0 && uint32_t(edge.face[0]) != f) {
    int k = crossing_slot_on_edge(g, values, uint32_t(edge.face[0]), e);
    if (k >= 0) return edge_crossing(g, values, uint32_t(edge.face[0]), k);
  }
  return edge_crossing(g, values, f, slot);
}

// (n_f × d) · ∇g > 0 for the segment of face f from a to b: the visible side on the left.
double left_side_visibility(const Geometry& g, const std::vector<double>& values, uint32_t f, glm::dvec3 a,
                            glm::dvec3 b) {
  return glm::dot(glm::cross(g.face_area_normals[f], b - a), scaled_gradient(g, values, f));
}

// The chain's points and facing labels, oriented with g > 0 on the left (see header).
LabeledPath chain_points(const Geometry& g, const std::vector<double>& values, const std::vector<FaceSegment>& segments,
                         const FaceChain& chain) {
  LabeledPath path;
  path.closed = chain.closed;
  for (size_t i = 0; i < chain.faces.size(); ++i) {
    path.points.push_back(crossing_point(g, values, chain.faces[i], chain.entry_slots[i]));
    path.labels.push_back(segments[chain.faces[i]].front ? 1 : 0);
  }
  if (!chain.closed) path.points.push_back(crossing_point(g, values, chain.faces.back(), chain.exit_slot));
  for (size_t i = 0; i < chain.faces.size(); ++i) {
    double side = left_side_visibility(g, values, chain.faces[i], path.points[i].position,
                                       path.points[(i + 1) % path.points.size()].position);
    if (side == 0) continue;
    if (side < 0) {
      std::reverse(path.points.begin(), path.points.end());
      std::reverse(path.labels.begin(), path.labels.end());
      if (path.closed) {  // keep segment i from point i to point i + 1
        std::rotate(path.points.begin(), path.points.end() - 1, path.points.end());
      }
    }
    break;
  }
  return path;
}

void add_silhouettes(const Geometry& g, const std::vector<glm::dvec3>& normals, glm::dvec3 eye,
                     const FeatureLineOptions& options, FeatureLines& out) {
  auto values = corner_silhouette_values(g, normals, eye, options.silhouette_normalized);
  std::vector<FaceSegment> segments(g.mesh.triangles.size());
  for (uint32_t f = 0; f < segments.size(); ++f) segments[f] = face_segment(g, values, eye, f);
  for (const auto& chain : trace_silhouettes(g, values, segments))
    for (auto& [path, front] : split_by_label(chain_points(g, values, segments, chain))) {
      path.front_facing = front != 0;
      if (path.front_facing || options.keep_back_facing) out.silhouettes.push_back(std::move(path));
    }
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
  add_silhouettes(impl_->g, impl_->normals, eye_in_object_space(object_to_world, eye_world), options, out);
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

std::pair<int32_t, int> FeatureLineMesh::across(uint32_t f, int k) const {
  const Geometry& g = impl_->g;
  uint32_t e = g.topology.face_edges[f][k];
  const auto& edge = g.topology.edges[e];
  int32_t other = edge.face[0] == int32_t(f) ? edge.face[1] : edge.face[0];
  if (g.edge_kinds[e] != EdgeKind::smooth || other < 0 || uint32_t(other) == f) return {kNone, -1};
  for (int j = 0; j < 3; ++j)
    if (g.topology.face_edges[size_t(other)][j] == e) return {other, j};
  return {kNone, -1};
}

std::vector<double> FeatureLineMesh::silhouette_values(glm::dvec3 eye_object, bool normalized) const {
  return corner_silhouette_values(impl_->g, impl_->normals, eye_object, normalized);
}

FaceSilhouette FeatureLineMesh::face_silhouette(const std::vector<double>& values, glm::dvec3 eye_object,
                                                uint32_t f) const {
  FaceSegment s = face_segment(impl_->g, values, eye_object, f);
  if (!s.exists()) return {};
  return {true,
          {s.slot[0], s.slot[1]},
          {edge_crossing(impl_->g, values, f, s.slot[0]), edge_crossing(impl_->g, values, f, s.slot[1])},
          s.front};
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

// Feature lines of a triangle mesh as geometry (Kalnins et al. 2002, §4.5):
// creases, borders and silhouettes, in double precision, with no GL and no ray tracer,
// so that both backends draw the same paths.
//
// Frames: `eye_world` is the eye in world space; it is taken into object space with
// inverse(object_to_world), and everything else (the test g, the path positions) is in
// the mesh's own object space. The sign of n·(eye - x) does not change under an affine
// map (normals go by the inverse transpose), so the silhouette is the same set either way.
//
// Creases and borders (Kalnins et al. 2002, §4.5):
//   - an edge is a crease when its two face normals satisfy n1·n2 < cos(crease_deg)
//     (default 60°: n1·n2 < 0.5); an edge next to a zero-area face (no normal) is not;
//   - a border is an edge with one face (build_topology's face[1] = -1, which includes
//     the edges of faces it split off from non-manifold input);
//   - both are chained into maximal paths in the crease+border graph: a path passes
//     through vertices of degree 2 and ends at vertices of any other degree; a
//     component whose vertices all have degree 2 is a closed loop. A chain is then cut
//     where it changes from crease to border, since they are reported apart.
//   - a path point at a vertex carries the lowest-index face holding that vertex.
//
// Silhouettes (Kalnins et al. 2002, §4.5, "the zero set of n·(c - x)"):
//   - g = n · normalize(eye - x) per face corner (`silhouette_normalized`, the default),
//     or the paper's literal g = n · (eye - x); n is the crease-aware vertex normal: the
//     weighted average of the face normals of the fan of faces around the vertex reached
//     from this corner without crossing a crease or border edge. The weights are Max's
//     (1999), sin(corner angle) / (|e1| |e2|), exact on a sphere and independent of how
//     a strip is triangulated; the Mesh's own normals are area-weighted and not used. So
//     g has one value per vertex on smooth surface and one per side of a crease. g = 0
//     exactly (and any non-finite g) is taken as -1e-8.
//   - a face holds a segment where g changes sign along two of its edges; the crossing on
//     edge ab is p = a + (b - a) g_a / (g_a - g_b), computed along the edge's own
//     direction (MeshTopology::Edge from -> to) so that both faces give the same point.
//   - segments are chained face to face (Kalnins et al. 2002, §4.5): a segment links to the
//     segment across the smooth edge it leaves by when that one enters through the same edge
//     with the same facing; never across a crease or border edge. Links go both ways, so
//     each chain is an open path, started at its segment without a predecessor, or a closed
//     loop, started at its lowest face; chains are ordered by their start face. Nothing in
//     a chain depends on the order work is done in, so a GPU ranking the links in parallel
//     finds the same chains (common/strokes/silhouette_chains.hpp). A path point is a
//     crossing on its own face: each face's entry, then an open chain's last exit.
//   - orientation: a segment runs with the visible side (g > 0) on its left, seen from the
//     side the face normal points to. For a counter-clockwise face whose slots s0 < s1
//     change sign around the lone corner c (oriented_slots), that is from slot c to slot
//     c - 1 when g(c) > 0 and the other way otherwise: the signs alone decide it.
//   - front/back (Kalnins et al. 2002, §4.5). ∇g is the gradient of g interpolated linearly
//     over the face, in the face's plane. A segment is front-facing when ∇g · (eye - m) >= 0,
//     m its midpoint: g grows towards the eye, i.e. the surface bends away from the viewer
//     (positive radial curvature), as on the whole silhouette of a convex object seen
//     from outside; zero-area faces (∇g = 0) count as front-facing. The wording "the
//     gradient points away from the eye side" (docs/readings.md) is the same test with g of
//     the opposite sign, n·(x - c). Links join only segments of one facing, so a path is
//     all front- or all back-facing; back-facing paths are dropped unless
//     `keep_back_facing`, and kept ones say which they are.
//
// Robustness: every face and every edge is visited a bounded number of times, so the
// chaining ends on any input (non-manifold edges, zero-area or repeated faces, vertices
// where g = 0); no position is NaN for finite input. A silhouette path has at most one
// point more than its faces, a crease or border path one more than its edges.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <utility>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago {

struct SurfacePoint {
  uint32_t face = 0;         // mesh triangle index
  glm::dvec3 bary{0.0};      // weights of the triangle's corners 0, 1, 2 (sum 1)
  glm::dvec3 position{0.0};  // object space: the barycentric combination of the corners
};

struct FeaturePath {
  std::vector<SurfacePoint> points;
  bool closed = false;       // the last point joins the first (not repeated)
  bool front_facing = true;  // silhouettes only; creases and borders are always true
};

struct FeatureLines {
  std::vector<FeaturePath> creases, borders, silhouettes;
};

struct FeatureLineOptions {
  double crease_deg = 60.0;           // strokes.crease_deg
  bool keep_back_facing = false;      // hidden-line mode: keep back-facing silhouettes
  bool silhouette_normalized = true;  // strokes.silhouette_normalized
};

// The slots a segment that crosses slots s0 < s1 enters and leaves by. The corner c between
// them is the one whose g has the other sign; for a counter-clockwise face, the segment from
// slot c - 1 to slot c has c on its right, so it runs from slot c to slot c - 1 when
// g(c) > 0 and the other way otherwise.
struct SegmentSlots {
  int entry, exit;
};
constexpr int lone_corner(int s0, int s1) { return s1 == s0 + 1 ? s1 : 0; }
constexpr SegmentSlots oriented_slots(int s0, int s1, bool lone_corner_positive) {
  int c = lone_corner(s0, s1), before = (c + 2) % 3;
  return lone_corner_positive ? SegmentSlots{c, before} : SegmentSlots{before, c};
}

// The silhouette segment of one face on its own (what a GPU computes face by face): the
// slots it enters and leaves by (slot k: the edge from corner k to k + 1), its crossings
// there (on the face's own slots) and its facing.
struct FaceSilhouette {
  bool exists = false;
  int slots[2] = {-1, -1};  // entry, exit
  SurfacePoint ends[2];     // the crossings it enters and leaves by
  bool front = true;
};

// A chain of silhouette segments (see above) as a path, and the face it starts at.
struct SilhouettePath {
  uint32_t start_face;
  FeaturePath path;
};

// What does not depend on the eye, made once per mesh and crease angle (adjacency,
// crease-aware normals, the creases and borders); `lines` adds the silhouettes for an eye.
// The mesh must outlive it; copies share the data.
class FeatureLineMesh {
 public:
  FeatureLineMesh(const Mesh& mesh, double crease_deg);
  // feature_lines(mesh, ...) below; options.crease_deg is the constructor's.
  FeatureLines lines(const glm::dmat4& object_to_world, glm::dvec3 eye_world, const FeatureLineOptions& options) const;

  // The pieces `lines` is made of, for a backend that computes them itself (a mesh with
  // faces only). The creases and borders (no silhouettes): they do not depend on the eye.
  const FeatureLines& creases_and_borders() const;
  // The crease-aware normal of each face corner (3 f + k); zero where the fan has no area.
  const std::vector<glm::dvec3>& corner_normals() const;
  // Bit k set: the edge in face f's slot k runs against the face (from corner k + 1 to
  // k), so the crossing rule starts there and both faces of the edge give one point.
  uint32_t reversed_slots(uint32_t f) const;
  // The face across the smooth edge in face f's slot k and its slot on that edge; face -1
  // across a crease, a border or a non-manifold edge (a path stops there).
  std::pair<int32_t, int> across(uint32_t f, int k) const;
  // g per face corner (silhouette_function below) for an eye in object space.
  std::vector<double> silhouette_values(glm::dvec3 eye_object, bool normalized) const;
  FaceSilhouette face_silhouette(const std::vector<double>& values, glm::dvec3 eye_object, uint32_t f) const;
  // The point at t on face f's slot, p = a + (b - a) t with a -> b the edge's own way (the
  // crossing rule above): where a backend that found the segment itself placed its crossing.
  SurfacePoint slot_point(uint32_t f, int slot, double t) const;
  // Every face's segment, in parallel; `lines` chains them all.
  std::vector<FaceSilhouette> face_silhouettes(const std::vector<double>& values, glm::dvec3 eye_object) const;
  // The chains of the faces whose segment exists, as paths of crossings ordered by their start
  // face, the back-facing ones only when `keep_back_facing`: a caller that drops segments
  // (the near plane, common/strokes/strokes.hpp) chains what is left.
  std::vector<SilhouettePath> silhouette_paths(const std::vector<FaceSilhouette>& segments,
                                               bool keep_back_facing) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

// All three kinds of feature line (Kalnins et al. 2002, §4.5) for one mesh and one eye (see above for the frames).
FeatureLines feature_lines(const Mesh& mesh, const glm::dmat4& object_to_world, glm::dvec3 eye_world,
                           const FeatureLineOptions& options = {});

// The eye in the object space of `object_to_world`.
glm::dvec3 eye_in_object_space(const glm::dmat4& object_to_world, glm::dvec3 eye_world);

// The silhouette test g of Kalnins et al. 2002, §4.5 per face corner (index 3 f + k), with the
// g = 0 -> -1e-8 rule applied; `eye_object` in object space. Exposed for tests.
std::vector<double> silhouette_function(const Mesh& mesh, glm::dvec3 eye_object,
                                        const FeatureLineOptions& options = {});

}  // namespace plumbago

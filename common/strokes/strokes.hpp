// The lines of stroke-based rendering in the window (Kalnins et al. 2002
// §4.5-4.6): the feature lines of common/strokes/feature_lines.hpp, for one camera, projected to
// window pixels and keyed for the ID reference image. Both backends draw and test exactly
// these paths; the `lines` command writes them.
//
// Keys (Kalnins et al. 2002, §4.6; one 32-bit space, 0 = nothing):
//   - face f of object o (every object of the scene, in order): first_face[o] + f + 1;
//   - crease and border path i: face_count + 1 + i;
//   - a silhouette path: silhouette_base + its start record (its chain's first face, as
//     first_face[o] + f: common/strokes/silhouette_paths.hpp), drawn as key << 8 | floor(255 s / L),
//     with silhouette_base the smallest key whose shifted values lie above every other key.
//     So a silhouette's key depends on its own chain only, not on how many come before it;
//   - decal and hatching paths (Kalnins et al. 2002, §3, §6, common/strokes/decal.hpp, common/strokes/hatching.hpp)
//     have none: they are not drawn in the ID image, their samples test their faces' keys.
// A scene whose keys do not fit 32 bits is refused (std::length_error, with the counts).
//
// Window coordinates are docs/conventions.md's (pixels, origin bottom-left); depth is linear view depth
// d = -z_view. A path point nearer than the near plane is dropped and splits its path; a
// silhouette segment with an end there is dropped before the segments are chained, so its
// pieces are chains of their own (as the GPU's tables, common/strokes/silhouette_segments.hpp).
//
// Order: the creases and borders (object by object, its creases then its borders), then the
// silhouettes (object by object, by their start face: chains, common/strokes/feature_lines.hpp);
// keys follow that order.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/scene.hpp"
#include "common/strokes/feature_lines.hpp"
#include "common/strokes/hatching.hpp"
#include "common/strokes/mobile_hatching.hpp"

namespace plumbago {

struct StrokesParams {
  static constexpr const char* stage = "strokes";
  float crease_deg;
  bool silhouette_normalized, keep_back_facing, crease_under_silhouettes, coherent;
  float id_crease_px, id_silhouette_px, id_depth_bias, id_silhouette_lift, id_crease_depth_bias, vis_step_px;
  template <class V>
  void visit(V& v) {
    v.real(crease_deg, "crease_deg", 60.0, 0.0, 180.0,
           "an edge is a crease when its face normals differ by more (Kalnins et al. 2002, §4.5)");
    v.boolean(silhouette_normalized, "silhouette_normalized", true,
              "g = n.normalize(eye - x); false: the paper's literal n.(eye - x) (Kalnins et al. 2002, §4.5)");
    v.boolean(keep_back_facing, "keep_back_facing", false,
              "keep back-facing silhouettes (hidden-line mode, Kalnins et "
              "al. 2002, §4.5)");
    v.real(id_crease_px, "id_crease_px", 2.0, 0.5, 16.0,
           "width of crease and border quads in the ID image (Kalnins et "
           "al. 2002, §4.6)");
    v.real(id_silhouette_px, "id_silhouette_px", 3.0, 0.5, 16.0,
           "width of silhouette quads in the ID image (Kalnins et al. 2002, §4.6)");
    v.real(id_depth_bias, "id_depth_bias", 0.005, 0.0, 0.5,
           "silhouette quads are depth-tested at d (1 - bias) against the faces (Kalnins et al. 2002, §4.6; relative, "
           "linear view depth)");
    v.real(id_silhouette_lift, "id_silhouette_lift", 0.0, 0.0, 16.0,
           "silhouette quads also come at least this many times their segment's world length nearer (on a coarse "
           "mesh the facets that graze a smooth silhouette lie about a face from it, beyond a relative bias; "
           "experiments/stroke_visibility)");
    v.real(id_crease_depth_bias, "id_crease_depth_bias", 1e-4, 0.0, 0.5,
           "crease and border quads are depth-tested at d (1 - bias) against the faces (relative, linear view depth; "
           "they need none to show, as their front-facing faces pass the test, only to clear depth ties)");
    v.boolean(crease_under_silhouettes, "crease_under_silhouettes", false,
              "a crease or border sample hidden in the ID image also shows where its pixel, before the silhouettes' "
              "quads, holds its key or a front-facing face next to it: creases beside silhouettes on coarse meshes "
              "kept, a pixel more shown where a crease goes behind a surface (experiments/stroke_visibility)");
    v.real(vis_step_px, "vis_step_px", 2.0, 0.25, 64.0,
           "visibility samples along a path, pixels apart (Kalnins et al. "
           "2002, §4.6)");
    v.boolean(coherent, "coherent", true,
              "silhouette brush parameters carried over the surface from each frame of a camera path to the next "
              "(Kalnins et al. 2003; false: restarted at each visible run, Kalnins et al. 2002, §4.1)");
  }
};

enum class LineKind : uint8_t { Crease, Border, Silhouette, Decal, Hatching };
const char* line_kind_name(LineKind kind);

struct WindowPath {
  LineKind kind;
  uint32_t object;  // index in scene.objects
  bool closed, front_facing;
  uint32_t key;                       // its key (a silhouette's before the shift)
  std::vector<SurfacePoint> surface;  // object space
  std::vector<glm::dvec3> world;
  std::vector<glm::dvec2> window;  // pixels, origin bottom-left
  std::vector<double> depth;       // linear view depth
  // Creases and borders: per segment (point k to k + 1, the closing one last), the keys
  // of its adjacent faces that face the eye (0 where none). Decals and hatches: the keys of
  // the faces its two ends lie on.
  std::vector<glm::uvec2> front_faces;
  std::vector<double> arc_px;  // window arc length at each point (the closing point last)
  double length_px = 0;        // the whole window length (closed: around the loop)
  // Decals and hatches: the drawn pressure at each point, the index of its surface stroke
  // in WindowLines::decal_styles, and (hatches) this frame's factors of alpha and width
  // (common/strokes/hatching.hpp 4.).
  std::vector<double> pressure;
  uint32_t decal = 0;
  double alpha_scale = 1, width_scale = 1;
  int hatch_group = -1;  // a hatch's group: its index in WindowLines::hatching
};

struct WindowLines {
  std::vector<WindowPath> paths;     // creases and borders first, then silhouettes, then decals and hatches
  std::vector<uint32_t> first_face;  // per scene object
  uint32_t face_count = 0, silhouette_base = 0;
  int width = 0, height = 0;
  std::vector<StrokeStyle> decal_styles;  // per surface stroke (common/strokes/decal.hpp DecalSurface)
  std::vector<HatchGroupState> hatching;  // per hatching group: its level of detail this frame

  uint32_t face_key(uint32_t object, uint32_t face) const { return first_face[object] + face + 1; }
};

// Where each scene object's face keys start, less one (first_face above), then the scene's
// face count.
std::vector<uint32_t> first_faces(const Scene& scene);

// WindowLines::silhouette_base for `face_count` faces and `crease_paths` crease and border
// paths; throws std::length_error where the keys do not fit 32 bits.
uint32_t silhouette_base(uint32_t face_count, uint64_t crease_paths);

// Which objects' lines: those drawn with strokes, or every object but the sketchy ones
// (the `lines` command: pencil objects too).
enum class LineObjects { Strokes, AllButSketchy };

// What window_lines needs of each drawn object that does not depend on the view: the
// feature lines' mesh data (common/strokes/feature_lines.hpp FeatureLineMesh) and the faces
// around each edge. A renderer makes it once and keeps it across its frames.
struct LineMeshes;
std::shared_ptr<const LineMeshes> line_meshes(const Scene& scene, const StrokesParams& p, LineObjects which);
// Scene object `object`'s feature-line mesh; null where it is not drawn or has no faces.
const FeatureLineMesh* line_mesh(const LineMeshes& meshes, size_t object);

// The faces of scene object `object`'s mesh around the edge between vertices a and b, in the
// order the crease test reads them; none where the object has no feature lines.
const std::vector<uint32_t>& edge_faces(const LineMeshes& meshes, size_t object, uint32_t a, uint32_t b);
// The mesh vertex a crease or border point sits on.
uint32_t vertex_of(const Mesh& mesh, const SurfacePoint& p);
// Whether face f faces the world point `eye`: n·(eye - p0) > 0 in world space, in double.
bool faces_eye(const Mesh& mesh, const glm::dmat4& object_to_world, uint32_t f, glm::dvec3 eye);

// One silhouette path as window_lines takes it: its object, its start record (its key, less
// the base), its points on the surface and, where the backend projected them itself, their
// window positions and linear view depths (x, y, d); else window_lines projects them.
struct ChainPath {
  uint32_t object, start_record;
  FeaturePath path;
  std::vector<glm::dvec3> window = {};
};

// One surface stroke as a frame draws it (Kalnins et al. 2002, §3, §6): a decal, a hatch, or
// one of this frame's copies of a mobile hatch; its index in the DecalSurface (its style's in
// WindowLines::decal_styles), its weight this frame (a copy's alpha times its hatch's), and
// the object its hatch's group lies on (its points elsewhere count as missed), else kMissed;
// a copy's placement among its group's (SurfaceStrokes::placed), else -1.
struct SurfaceStroke {
  const ProjectedDecal* decal;
  uint32_t index;
  HatchWeight weight;
  uint32_t object;
  int copy = -1;
};
// A frame's surface strokes: the hatching groups' levels of detail and the mobile groups'
// placements, every stroke's style, and the strokes drawn (weight alpha above 0), in the
// order window_lines places them: by index, a mobile hatch as its copies. Move-only: `drawn`
// points into `copies`.
struct SurfaceStrokes {
  SurfaceStrokes() = default;
  SurfaceStrokes(SurfaceStrokes&&) = default;
  SurfaceStrokes& operator=(SurfaceStrokes&&) = default;
  std::vector<HatchGroupState> hatching;
  std::vector<MobileHatching::Placement> placed;  // per hatching group
  std::vector<StrokeStyle> styles;
  std::vector<SurfaceStroke> drawn;
  std::deque<ProjectedDecal> copies;  // a deque: its elements stay where they are
};
// `decals`' strokes this frame; `mobile`: its mobile hatching groups (common/strokes/mobile_hatching.hpp),
// made once by a backend that keeps its decals; none: made here. `move_copies` false: a mobile
// hatch's copies keep its points, unmoved (a backend that moves them itself, from `placed`).
SurfaceStrokes surface_strokes(const Scene& scene, const DecalSurface& decals, const MobileHatching* mobile = nullptr,
                               bool move_copies = true);

// `prepared` (from line_meshes with the same scene, parameters and `which`) or none;
// `surface`: the decals and hatches (surface_strokes), placed after the feature lines, or
// none. `silhouettes`: the silhouettes a backend chained itself
// (common/strokes/silhouette_paths.hpp), in front of the near plane, in start order; none:
// chained here in double. `whole`: false leaves out the paths a backend makes itself, the
// creases, borders, decals and hatches (the silhouettes' keys then count no crease), but
// keeps the hatching groups and the decals' styles.
WindowLines window_lines(const Scene& scene, const StrokesParams& p, LineObjects which = LineObjects::Strokes,
                         const LineMeshes* prepared = nullptr, const SurfaceStrokes* surface = nullptr,
                         const std::vector<ChainPath>* silhouettes = nullptr, bool whole = true);

// The part [t0, t1] of window segment a -> b within `margin` px of the window (Liang-Barsky);
// false when none is.
bool clip_to_window(glm::dvec2 a, glm::dvec2 b, double width, double height, double margin, double& t0, double& t1);

// The window position and linear depth of a world point (docs/conventions.md), in double.
struct WindowProjection {
  WindowProjection(const Camera& camera, int width, int height);
  glm::dvec3 operator()(glm::dvec3 world) const;  // (x, y, d)
  glm::dmat4 view, clip;
  int width, height;
};

}  // namespace plumbago

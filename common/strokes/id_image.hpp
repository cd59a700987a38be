// The ID reference image (Kalnins et al. 2002 §4.6): a 32-bit key per pixel,
// 0 where nothing is drawn, made with the same rules on both backends:
//   1. faces, with their face keys: the G-buffer's (docs/stages.md, gbuffer), which holds every
//      object but the sketchy ones, each pixel at z = near / d, d its depth there; then the
//      faces of the sketchy objects (common/sketchy/sketchy.hpp), drawn as triangles clipped
//      to the near plane;
//   2. crease and border paths as window-space quads `strokes.id_crease_px` wide, with the
//      path key;
//   3. front-facing silhouette paths as quads `strokes.id_silhouette_px` wide, each segment
//      cut into equal pieces at most 1 px long, each piece with key << 8 | floor(255 s / L),
//      s the window arc length at its midpoint and L the path's (common/strokes/strokes.hpp
//      numbers the keys). (Whole segments would give a coarse mesh's pixels the byte of a
//      midpoint many pixels away, and its samples would fail the test of
//      common/strokes/visibility.hpp.)
// A segment's quad runs along it with its width centered on it (no caps).
//
// Under strokes.crease_under_silhouettes a second key image comes out, the one before rule 3
// (id_image.crease_ids, 1 x 1 of 0 without the parameter), where creases and borders are
// tested too (common/strokes/visibility.hpp). A silhouette is a line, not a surface: its
// quad, 3 px wide and drawn nearer by its bias, covers a crease running within a pixel or two
// of it, and the crease's faces, wherever the two run side by side (a coarse mesh's legs).
//
// Depth: each triangle vertex carries z = near / d, d its linear view depth: 1/d, and so z, is
// affine in window space on a planar triangle, so interpolating z affinely over the
// window is exact (perspective-correct) and the same rule on both backends. A line vertex
// is placed at d (1 - bias) (an explicit bias, not glPolygonOffset's implementation-defined
// units): a silhouette's `strokes.id_depth_bias`, as it lies off the facets, which graze
// it (under `strokes.id_silhouette_lift` k, at min(d (1 - bias), d - k l), l its segment's
// world length: on a coarse mesh those facets lie about a face off it); a crease's or
// border's `strokes.id_crease_depth_bias`, which only clears depth ties with its own faces
// (its test also accepts its front-facing faces, so it needs none to show, and a larger one
// lets a line just behind a surface through). A pixel keeps the triangle with the largest z (the
// nearest; GL_GREATER, the buffer cleared to 0); equal z keeps the first drawn.
//
// Rasterization (both backends, docs/conventions.md): a triangle covers the pixel centers inside it and
// those on its top or left edges; vertices are snapped to 1/256 px (GL_SUBPIXEL_BITS = 8
// on llvmpipe and the common GPUs); z is interpolated with the barycentrics of the
// (snapped) window triangle.
//
// The faces come from the G-buffer because the frame has rasterized them there already:
// a second raster of every face would cost as much again (the Ogre's strokes frame on
// llvmpipe: bench/results).
//
// The silhouettes: the reference chains them in double (common/strokes/strokes.hpp); the GPU
// reads its own chains (common/strokes/silhouette_paths.hpp), which follow the same rule, and
// places and projects their points in double itself (gpu/strokes/silhouette_points.hpp).
//
// Output: the key as two channels, (key >> 16, key & 0xffff), each exact as a float.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/stage.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/strokes/hatching.hpp"
#include "common/strokes/line_meshes.hpp"
#include "common/strokes/silhouette_paths.hpp"
#include "common/strokes/strokes.hpp"
#include "common/util/image.hpp"

namespace plumbago {

struct IdVertex {
  glm::vec2 window;  // pixels, origin bottom-left
  float z;           // near / d
  uint32_t key;
};

// Rule 1 on the G-buffer: per G-buffer object o (the scene's objects but the sketchy ones, in
// order), the key of its face 0, so that a pixel with ids (o + 1, t) holds key first[o] + t.
std::vector<uint32_t> gbuffer_first_keys(const Scene& scene);
// The z of a G-buffer pixel at depth d.
inline float face_z(double near, double d) { return float(near / std::max(d, near)); }

// Rule 1's sketchy faces as triangles, three vertices each (the reference's; the GPU draws
// them from the meshes it keeps, shaders/strokes/id_faces.vert, clipped by the rasterizer).
std::vector<IdVertex> id_sketchy_face_triangles(const Scene& scene, const WindowLines& lines);
// Rule 2 (the creases and borders) or rule 3 (the silhouettes), in drawing order.
enum class IdLineRule { CreasesAndBorders, Silhouettes };
std::vector<IdVertex> id_line_triangles(const Scene& scene, const WindowLines& lines, const StrokesParams& p,
                                        IdLineRule rule);

constexpr int kSubpixelBits = 8;

// The key image as the output's two channels, and back.
Image key_channels(const ImageU32& keys);
ImageU32 keys_from_channels(const Image& channels);

// Where two surfaces' z lie this close (relative, plus a subpixel of their z slopes) the
// backends may keep either: a depth tie (reference/strokes/id_image.cpp).
constexpr double kDepthTie = 1e-5;

inline constexpr Buffer kIds{"id_image.ids"};
inline constexpr Buffer kCreaseIds{"id_image.crease_ids"};  // rules 1 and 2: before the silhouettes
// The frame's lines in the window: feature lines, decals and hatching (common/strokes/strokes.hpp).
inline constexpr Slot<WindowLines> kWindowLines{"id_image.lines"};
// Reference only: where rounding decides the ID (what the parity bounds of kIds and
// kCreaseIds read).
inline constexpr Slot<Image> kAmbiguousIds{"id_image.ambiguous"};
inline constexpr Slot<Image> kAmbiguousCreaseIds{"id_image.crease_ambiguous"};

struct IdImageStage {
  using Params = TypeList<StrokesParams, HatchingParams>;
  static StageDesc describe() {
    return {
        .name = "id_image",
        .kind = StageKind::Frame,
        .doc = "ID reference image: faces, crease and silhouette quads (Kalnins et al. 2002, §4.6)",
        .params = {"strokes"},
        .inputs = {{.handle = kLineMeshes},
                   {.handle = kGBuffer.ids},
                   {.handle = kGBuffer.depth},
                   {.handle = kSilhouettePaths},
                   {.handle = kSilhouetteCrossings}},
        .outputs =
            {{.handle = kIds,
              .channels = 2,
              .texel = Texel::Uint,
              .doc = "the key, as (key >> 16, key & 0xffff)",
              .tolerance_why = "fed the same G-buffer, whose faces both copy; the sketchy faces and the lines "
                               "are the same triangles, rasterized with the same rules: exact except where "
                               "rounding decides, which a derived bound allows and the note counts: depth ties "
                               "(the nearest surfaces within 1e-5 relative plus a subpixel of z slope) and "
                               "edges within a subpixel of the pixel center (torus 800x600: 62 px, 0.01%)"},
             {.handle = kCreaseIds,
              .channels = 2,
              .texel = Texel::Uint,
              .doc = "under strokes.crease_under_silhouettes, the key before the silhouettes' quads (faces, "
                     "creases and borders), which crease and border samples also test; else 1 x 1 of 0",
              .tolerance_why = "the same triangles as id_image.ids, fewer: exact except where rounding "
                               "decides, the same derived bound"},
             {.handle = kWindowLines,
              .channels = 0,
              .texel = Texel::Host,
              .doc = "the lines in the window, their keys and surface points (CPU; a GPU frame makes its creases, "
                     "borders and silhouettes on the GPU, and here only for its counts and dumps)"},
             {.handle = kAmbiguousIds, .texel = Texel::Host, .doc = "reference only: 1 where rounding decides the key"},
             {.handle = kAmbiguousCreaseIds,
              .texel = Texel::Host,
              .doc = "reference only: 1 where rounding decides the key before the silhouettes"}},
        .effects = {"strokes"}};
  }
};

}  // namespace plumbago

// Sketchy composite and depth sprite (Nienhaus & Döllner §3.2-3.4, §4),
// CPU reference; the twin of shaders/sketchy/sketchy_composite.frag.
#pragma once

#include "common/scene/gbuffer.hpp"
#include "common/sketchy/sketchy.hpp"
#include "reference/sketchy/sketchy_maps.hpp"

namespace plumbago::reference {

struct SketchyFrame {
  Image color;  // 3 ch: the sketch over `under` wherever its depth sprite is nearer
  Image depth;  // 1 ch: normalized depth of the sprite where the sketch was drawn, 1 elsewhere
};

// What the composite reads besides the maps: the sketchy G-buffer (depth, near, far),
// the noise textures, and for the object style the enlarged geometry's noise
// coordinates (reference/sketchy/sketchy_enlarged.hpp; empty otherwise).
struct SketchyInputs {
  const SketchyMaps& maps;
  const GBuffer& gbuffer;
  const SketchyNoise& noise;
  const Image& noise_coordinates;
};

// (u, v) of Nienhaus & Döllner 2004, §3.2 at pixel center `center` for edge copy `copy`, centered on 0: the
// sketch's perturbation before M_e and M_s turn it into pixel offsets.
glm::vec2 uncertainty(const SketchyInputs& in, const SketchyParams& p, glm::vec2 center, int copy);

// `under_color` (3 ch; empty = white paper) and `under_depth` (linear; empty = nothing)
// are what the ordinary objects drew; the sketch composes with them by depth (Nienhaus & Döllner 2004, §3.3).
SketchyFrame sketchy_composite(const SketchyInputs& in, const SketchyParams& p, const Image& under_color,
                               const Image& under_depth);

// Parity (docs/conventions.md). The sprite's depth is read at nearest texels, floor(p + M (u, v)), a
// discrete choice: where a sample position lies on a texel edge, positions a rounding
// apart read adjacent texels. The backends round differently, both within what GL
// allows: GLSL may contract p + M_s (u, v) into fmas (llvmpipe does; the CPU adds the
// rounded products), and llvmpipe's filter lerps as fma(w, y - x, x) where the reference
// sampler's glm::mix takes x (1 - w) + y w, which moves (u, v) by an ulp or two. Off
// those ties the sprite's depth agrees bit for bit (measured on the sketchy scenes).
//
// The most the backends' sample positions can differ, in pixels, derived from binary32
// rounding (u = 2^-24) with +, -, *, / correctly rounded and any order or contraction:
//   eps = 4 u (C + 2 R) + ||M|| dT,
// C = max(width, height) (the pixel center), ||M|| = the largest row sum of |M| over the
// matrices read (M_s, M_e or the copies' turned M_e), R = ||M|| max|(u, v)| (1.5; 0.5
// rough): four roundings at most of p + M (u, v) per backend. dT bounds the difference of
// (u, v): 0 for the rough style (texelFetch), else per backend 4 u per lerp, 2 (3 for
// the 3D noise) lerp levels, sum_i 2^-i < 2, the octaves' n sums below 2 and the
// centering, and when the noise size is not a power of two one rounding of the texel
// coordinate |x| + size each (a backend may wrap s before scaling it or after) times
// the noise's largest step between adjacent texels.
float sample_position_tolerance(const SketchyInputs& in, const SketchyParams& p);

// Per pixel, the largest change of the sprite's normalized depth (sketchy_composite's
// `depth`, over white paper: 1 where nothing is drawn) that moving every sample position
// by up to `eps` pixels in x and y can cause: the depth step between the texels such a
// move can pick (about |grad d| x 1 texel / (far - near) on a smooth surface), or the
// jump to another sample or to 1 where the shade sample's coverage or the edge sample's
// darkness test can flip. 0 where no sample position lies within `eps` of a texel edge
// and no darkness within rounding of sketchy.dark_edge: there the backends must agree
// to tolerance::kFloat (common/core/stage.hpp), elsewhere to kFloat + this bound.
Image sprite_depth_tie_bound(const SketchyInputs& in, const SketchyParams& p, float eps);

}  // namespace plumbago::reference

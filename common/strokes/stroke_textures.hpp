// Stroke textures (Kalnins et al. 2002 §4.2): the generated family of 2D
// textures a stroke ribbon samples, one channel in [0, 1] that multiplies the stroke's
// alpha. Texel (x, y) covers u = (x + 0.5) / width along the stroke (GL_REPEAT: the
// texture tiles in u without a seam) and v = (y + 0.5) / height across it (GL_CLAMP_TO_EDGE;
// v = 0 and v = 1 are the ribbon's two sides, base_stroke.hpp).
//
// Every kind is its grain g(u, v) times a cross-section c(v), the soft edge that takes
// the place of GL_LINE_SMOOTH (Kalnins et al. 2002, §4.1):
//   c(v) = smoothstep(0, e, v) smoothstep(0, e, 1 - v)
// full value over the middle, falling smoothly to ~0 at both sides over the outer share e
// of the width. The grains are sums of smooth value noise (random values on a lattice,
// quintic interpolation), periodic in u, with lattice cells chosen per kind:
//   - pencil: streaks of the lead along u (cells long in u, thin in v) over a fine grain;
//     e = 0.25, mean ~0.6 over the middle;
//   - charcoal: coarse blotches that break the stroke (smoothstep of a coarse noise), over
//     a coarse grain; e = 0.3, the lowest mean (~0.45) and the largest variance;
//   - ink: nearly solid, a faint streak; e = 0.15, the highest mean (~0.95), the least variance.
// Deterministic in (seed, kind): each noise is seeded from the seed and its own name
// ("stroke-texture-<kind>-<layer>", common/util/random.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/util/image.hpp"

namespace plumbago {

enum class StrokeTextureKind { Pencil, Charcoal, Ink };

// The kinds' names in enum order: "pencil", "charcoal", "ink".
const std::vector<std::string>& stroke_texture_names();

constexpr int kStrokeTextureWidth = 256;  // texels along the stroke (u)
constexpr int kStrokeTextureHeight = 32;  // texels across the stroke (v)

// kStrokeTextureWidth x kStrokeTextureHeight, 1 channel, values in [0, 1].
Image stroke_texture(StrokeTextureKind kind, uint32_t seed);

}  // namespace plumbago

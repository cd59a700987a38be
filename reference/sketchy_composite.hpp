// Sketchy composite and depth sprite (SPEC 3.2-3.5; Nienhaus & Döllner §3.2-3.4, §4),
// CPU reference; the twin of shaders/sketchy_composite.frag.
#pragma once

#include "common/gbuffer.hpp"
#include "common/sketchy.hpp"
#include "reference/sketchy_maps.hpp"

namespace plumbago::reference {

struct SketchyFrame {
  Image color;  // 3 ch: the sketch over `under` wherever its depth sprite is nearer
  Image depth;  // 1 ch: normalized depth of the sprite where the sketch was drawn, 1 elsewhere
};

// What the composite reads besides the maps: the sketchy G-buffer (depth, near, far),
// the noise textures, and for the object style the enlarged geometry's noise
// coordinates (reference/sketchy_enlarged.hpp; empty otherwise).
struct SketchyInputs {
  const SketchyMaps& maps;
  const GBuffer& gbuffer;
  const SketchyNoise& noise;
  const Image& noise_coordinates;
};

// (u, v) of SPEC 3.2 at pixel center `center` for edge copy `copy`, centered on 0: the
// sketch's perturbation before M_e and M_s turn it into pixel offsets.
glm::vec2 uncertainty(const SketchyInputs& in, const SketchyParams& p, glm::vec2 center, int copy);

// `under_color` (3 ch; empty = white paper) and `under_depth` (linear; empty = nothing)
// are what the ordinary objects drew; the sketch composes with them by depth (SPEC 3.4).
SketchyFrame sketchy_composite(const SketchyInputs& in, const SketchyParams& p, const Image& under_color,
                               const Image& under_depth);

}  // namespace plumbago::reference

// Sketchy composite and depth sprite on the GPU (Nienhaus & Döllner 2004, §3.2-3.4), the twin of
// reference/sketchy/sketchy_composite.cpp.
#pragma once

#include "common/sketchy/sketchy.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago::gpu {

// The noise textures of common/sketchy/sketchy.hpp's SketchyNoise on the GPU (1x1 stand-ins for
// what the style does not read).
struct SketchyNoiseTextures {
  Texture perlin, white, perlin_3d;
};
SketchyNoiseTextures upload_sketchy_noise(const SketchyNoise& noise);

struct SketchyCompositeInputs {
  const Texture& edge_map;        // RG32F (gpu/sketchy/sketchy_maps.hpp)
  const Texture& shade_map;       // RGBA8
  const GBufferTargets& gbuffer;  // the sketchy objects' depth, near, far
  const SketchyNoiseTextures& noise;
  const Texture& noise_coordinates;  // object style (gpu/sketchy/sketchy_enlarged.hpp); any texture otherwise
};

class SketchyCompositePass {
 public:
  SketchyCompositePass();
  // Draws the sketch into `color` (RGBA8) where its depth sprite passes the depth test
  // against `under_depth` (the ordinary objects' depth buffer), or an empty depth buffer
  // when `under_depth` is null; over what `color` holds, or over white paper `on_paper`
  // (no pipeline drew into it this frame). `sprite_depth` (R32F): the sprite's
  // normalized depth where the sketch was drawn, 1 elsewhere. Only `reach` (the sketchy
  // objects' covered_rect grown by sketch_reach, common/sketchy/sketchy.hpp) runs the shader:
  // outside it both samples are exterior and the fragment would be discarded.
  void run(const SketchyCompositeInputs& in, const SketchyParams& p, Texture& color, bool on_paper,
           const Renderbuffer* under_depth, Texture& sprite_depth, const PixelRect& reach);

 private:
  void set_uniforms(const SketchyCompositeInputs& in, const SketchyParams& p);
  Program program_;
  Framebuffer fbo_;
  VertexArray empty_;
  Renderbuffer own_depth_;
};

}  // namespace plumbago::gpu

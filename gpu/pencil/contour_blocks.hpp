// The blocks of pixels that multiple contour drawing skips when no copy of theirs can read
// a d' > 0 (shaders/pencil/contour_blocks.frag; gpu/pencil/multi_contour.hpp): marked where d' is drawn
// (gpu/pencil/edge_detect.hpp) or from d' itself.
#pragma once

#include <string>

#include "common/core/handle.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

constexpr int kContourBlock = 8;  // pixels per side of a block

// `#define CONTOUR_BLOCK n` for the shaders.
std::string contour_block_define();
// Makes `t` a texture of one texel a block (R32F) for a width x height window, unless it is one.
void fit_to_blocks(Texture& t, int width, int height);
// The blocks' marks for a window: 1 where some d' > 0, else 0.
Texture make_contour_block_marks(int width, int height);
inline constexpr Shared<Texture> kContourBlockMarks{"contour_blocks.marks"};

}  // namespace plumbago::gpu

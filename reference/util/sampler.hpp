// The GL-exact texture sampler every reference pass uses (docs/conventions.md): texel centers at
// (k + 0.5) / size, GL_NEAREST and GL_LINEAR (bilinear; trilinear across the layers of
// a 3D texture), GL_REPEAT and GL_CLAMP_TO_EDGE, following the formulas of the OpenGL
// 4.5 core specification §8.14 (u = s * size - 1/2, i0 = floor(u), alpha = frac(u)).
// Passes never hand-roll filtering.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "common/util/image.hpp"

namespace plumbago::reference {

enum class Filter { Nearest, Linear };
enum class Wrap { Repeat, ClampToEdge };

struct SamplerState {
  Filter filter = Filter::Linear;
  Wrap wrap_s = Wrap::ClampToEdge, wrap_t = Wrap::ClampToEdge, wrap_r = Wrap::ClampToEdge;
  // Bits of the bilinear weight alpha (0 = exact float). GPUs quantize it (llvmpipe and
  // most hardware: 8 bits); tests state which they use.
  int weight_bits = 0;
};

// texture(sampler2D, (s, t)) on `img` (any channel count; missing channels read 0, alpha 1).
glm::vec4 sample(const Image& img, glm::vec2 st, const SamplerState& state);

// texture(sampler3D, (s, t, r)) on a stack of equally sized layers (layer 0 at r = 0.5/n).
glm::vec4 sample(const std::vector<Image>& layers, glm::vec3 str, const SamplerState& state);

// texelFetch with the coordinate clamped into the image.
glm::vec4 fetch(const Image& img, glm::ivec2 texel);

}  // namespace plumbago::reference

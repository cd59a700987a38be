#include "reference/util/sampler.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago::reference {

namespace {

// GL §8.14.2: wrap an integer texel coordinate.
int wrapped(int i, int size, Wrap wrap) {
  if (wrap == Wrap::ClampToEdge) return std::clamp(i, 0, size - 1);
  int m = i % size;
  return m < 0 ? m + size : m;
}

// One axis of a lookup: the two texels and the weight of the second.
struct Taps {
  int i0, i1;
  float alpha;
};

float quantized(float alpha, int bits) {
  if (bits <= 0) return alpha;
  float scale = float(1 << bits);
  return std::floor(alpha * scale) / scale;
}

Taps taps(float coord, int size, Filter filter, Wrap wrap, int weight_bits) {
  float u = coord * float(size);
  if (filter == Filter::Nearest) {
    int i = wrapped(int(std::floor(u)), size, wrap);
    return {i, i, 0.0f};
  }
  u -= 0.5f;
  float i0 = std::floor(u);
  return {wrapped(int(i0), size, wrap), wrapped(int(i0) + 1, size, wrap), quantized(u - i0, weight_bits)};
}

glm::vec4 texel(const Image& img, int x, int y) {
  glm::vec4 v(0, 0, 0, 1);
  for (int c = 0; c < std::min(img.channels, 4); ++c) v[c] = img.at(x, y, c);
  return v;
}

glm::vec4 bilinear(const Image& img, const Taps& s, const Taps& t) {
  glm::vec4 bottom = glm::mix(texel(img, s.i0, t.i0), texel(img, s.i1, t.i0), s.alpha);
  glm::vec4 top = glm::mix(texel(img, s.i0, t.i1), texel(img, s.i1, t.i1), s.alpha);
  return glm::mix(bottom, top, t.alpha);
}

}  // namespace

glm::vec4 sample(const Image& img, glm::vec2 st, const SamplerState& state) {
  Taps s = taps(st.x, img.width, state.filter, state.wrap_s, state.weight_bits);
  Taps t = taps(st.y, img.height, state.filter, state.wrap_t, state.weight_bits);
  return bilinear(img, s, t);
}

glm::vec4 sample(const std::vector<Image>& layers, glm::vec3 str, const SamplerState& state) {
  const Image& first = layers.front();
  Taps s = taps(str.x, first.width, state.filter, state.wrap_s, state.weight_bits);
  Taps t = taps(str.y, first.height, state.filter, state.wrap_t, state.weight_bits);
  Taps r = taps(str.z, int(layers.size()), state.filter, state.wrap_r, state.weight_bits);
  return glm::mix(bilinear(layers[size_t(r.i0)], s, t), bilinear(layers[size_t(r.i1)], s, t), r.alpha);
}

glm::vec4 fetch(const Image& img, glm::ivec2 p) {
  return texel(img, std::clamp(p.x, 0, img.width - 1), std::clamp(p.y, 0, img.height - 1));
}

}  // namespace plumbago::reference

#include "reference/sketchy/sketchy_composite.hpp"
#include "common/sketchy/sketchy_composite.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "reference/core/stage.hpp"
#include "reference/util/rows.hpp"
#include "reference/util/sampler.hpp"

namespace plumbago::reference {

namespace {

const SamplerState kRepeat{Filter::Linear, Wrap::Repeat, Wrap::Repeat, Wrap::Repeat};
const SamplerState kClamp{Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, Wrap::ClampToEdge};

// T(s, t) = sum_i |N(2^i (s, t))| / 2^i (Nienhaus & Döllner 2004, §3.2)
float turbulence(const Image& noise, glm::vec2 st, int octaves) {
  float t = 0, f = 1;
  for (int i = 0; i < octaves; ++i, f *= 2) t += std::abs(sample(noise, st * f, kRepeat).x) / f;
  return t;
}

// The same over a 3D noise texture (object style, Nienhaus & Döllner 2004, §3.4, §4).
float turbulence(const std::vector<Image>& noise, glm::vec3 q, int octaves) {
  float t = 0, f = 1;
  for (int i = 0; i < octaves; ++i, f *= 2) t += std::abs(sample(noise, q * f, kRepeat).x) / f;
  return t;
}

glm::ivec2 nearest_texel(const Image& img, glm::vec2 q) {
  return glm::clamp(glm::ivec2(glm::floor(q)), glm::ivec2(0), glm::ivec2(img.width - 1, img.height - 1));
}

struct EdgeSample {
  float darkness, depth;
  bool dark;
};

// e = edge(p + delta_e): darkness filtered, its depth from the nearest texel.
EdgeSample edge_sample(const SketchyInputs& in, const SketchyParams& p, glm::vec2 q) {
  const Image& edge = in.maps.edge;
  float d = sample(edge, q / glm::vec2(edge.width, edge.height), kClamp).x;
  float depth = edge.at(nearest_texel(edge, q).x, nearest_texel(edge, q).y, 1);
  return {d, depth, d > p.dark_edge && depth < in.gbuffer.far};
}

struct Sketch {
  bool drawn = false;
  glm::vec3 color{1.0f};
  float depth = 0;  // linear
};

// Default, rough and object styles: e * c.rgb inside the shade map, e * white outside
// (Nienhaus & Döllner 2004, §3.2); the sprite takes the nearer of the drawn samples' depths (Nienhaus & Döllner 2004,
// §3.3).
Sketch edge_and_shade(const SketchyInputs& in, const SketchyParams& p, glm::vec2 center) {
  glm::vec2 uv = uncertainty(in, p, center, 0);
  EdgeSample e = edge_sample(in, p, center + edge_matrix(p) * uv);
  glm::ivec2 s = nearest_texel(in.maps.shade, center + shade_matrix(p) * uv);
  bool interior = in.maps.shade.at(s.x, s.y, 3) > 0.5f;
  Sketch out;
  out.drawn = e.dark || interior;
  out.depth = std::min(e.dark ? e.depth : in.gbuffer.far, interior ? in.gbuffer.depth.at(s.x, s.y) : in.gbuffer.far);
  glm::vec3 c =
      interior ? glm::vec3(in.maps.shade.at(s.x, s.y, 0), in.maps.shade.at(s.x, s.y, 1), in.maps.shade.at(s.x, s.y, 2))
               : glm::vec3(1.0f);
  out.color = (1.0f - e.darkness) * c;
  return out;
}

// Repeat style: edge copy k drawn with its own matrix and ink, no shade map (Nienhaus & Döllner 2004, §3.4, §4).
Sketch repeated_edges(const SketchyInputs& in, const SketchyParams& p, glm::vec2 center) {
  Sketch out;
  out.depth = in.gbuffer.far;
  for (int k = 0; k < p.edge_copies; ++k) {
    EdgeSample e = edge_sample(in, p, center + copy_matrix(p, k) * uncertainty(in, p, center, k));
    if (!e.dark) continue;
    out.drawn = true;
    out.depth = std::min(out.depth, e.depth);
    out.color *= glm::mix(copy_ink(p, k), glm::vec3(1.0f), 1.0f - e.darkness);
  }
  return out;
}

}  // namespace

glm::vec2 uncertainty(const SketchyInputs& in, const SketchyParams& p, glm::vec2 center, int copy) {
  glm::ivec2 x(center);
  switch (p.style) {
    case SketchyStyle::Rough: {  // uncorrelated: one white-noise texel per pixel
      const Image& w = in.noise.white;
      glm::vec4 r = fetch(w, {x.x % w.width, x.y % w.height});
      return glm::vec2(r.x, r.y) - 0.5f;
    }
    case SketchyStyle::Object: {  // 3D noise at the enlarged surface's noise coordinate
      glm::vec4 g = fetch(in.noise_coordinates, x);
      if (g.w == 0.0f) return glm::vec2(0.0f);
      glm::vec3 q = glm::vec3(g) / p.object_noise_scale;
      return glm::vec2(turbulence(in.noise.perlin_3d, q, p.octaves),
                       turbulence(in.noise.perlin_3d, 1.0f - q, p.octaves)) -
             0.5f;
    }
    default: {  // (T(s, t), T(1 - s, 1 - t)), (s, t) = p / noise_scale, shifted per copy
      glm::vec2 st = center / p.noise_scale + copy_noise_shift(copy);
      return glm::vec2(turbulence(in.noise.perlin, st, p.octaves), turbulence(in.noise.perlin, 1.0f - st, p.octaves)) -
             0.5f;
    }
  }
}

SketchyFrame sketchy_composite(const SketchyInputs& in, const SketchyParams& p, const Image& under_color,
                               const Image& under_depth) {
  const GBuffer& g = in.gbuffer;
  int w = g.depth.width, h = g.depth.height;
  SketchyFrame out{under_color.empty() ? Image(w, h, 3, 1.0f) : under_color, Image(w, h, 1, 1.0f)};
  for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      glm::vec2 center(float(x) + 0.5f, float(y) + 0.5f);
      Sketch s = p.style == SketchyStyle::Repeat ? repeated_edges(in, p, center) : edge_and_shade(in, p, center);
      float under = under_depth.empty() ? g.far : under_depth.at(x, y);
      if (!s.drawn || !(s.depth < under)) continue;  // discarded, or behind an ordinary object
      for (int c = 0; c < 3; ++c) out.color.at(x, y, c) = s.color[c];
      out.depth.at(x, y) = (s.depth - g.near) / (g.far - g.near);
    }
  });
  return out;
}

namespace {

constexpr float kUnit = 0x1p-24f;  // unit roundoff of binary32

// The largest row sum of |M|: how far a component of M (u, v) moves per unit of |(u, v)|_inf.
float row_norm(const glm::mat2& m) {
  return std::max(std::abs(m[0][0]) + std::abs(m[1][0]), std::abs(m[0][1]) + std::abs(m[1][1]));
}

// The matrices whose sample positions the composite reads.
std::vector<glm::mat2> sample_matrices(const SketchyParams& p) {
  if (p.style != SketchyStyle::Repeat) return {edge_matrix(p), shade_matrix(p)};
  std::vector<glm::mat2> out;
  for (int k = 0; k < p.edge_copies; ++k) out.push_back(copy_matrix(p, k));
  return out;
}

float matrix_norm(const SketchyParams& p) {
  float n = 0;
  for (const glm::mat2& m : sample_matrices(p)) n = std::max(n, row_norm(m));
  return n;
}

bool power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

// The largest difference of two texels adjacent along an axis (wrapping): the most a
// filtered value moves per texel of coordinate.
float texel_step(const std::vector<const Image*>& layers) {
  float step = 0;
  int depth = int(layers.size());
  for (int z = 0; z < depth; ++z) {
    const Image& a = *layers[size_t(z)];
    const Image& above = *layers[size_t((z + 1) % depth)];
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        float v = a.at(x, y);
        step = std::max({step, std::abs(a.at((x + 1) % a.width, y) - v), std::abs(a.at(x, (y + 1) % a.height) - v)});
        if (depth > 1) step = std::max(step, std::abs(above.at(x, y) - v));
      }
  }
  return step;
}

// dT of sample_position_tolerance: how far apart the two backends' (u, v) can be.
float uncertainty_tolerance(const SketchyInputs& in, const SketchyParams& p) {
  if (p.style == SketchyStyle::Rough) return 0;  // texelFetch, the same texel on both
  bool object = p.style == SketchyStyle::Object;
  float levels = object ? 3 : 2, n = float(p.octaves);
  float per_backend = 8 * kUnit * levels + 2 * kUnit * n + 2 * kUnit;
  std::vector<const Image*> layers;
  float reach = 0;  // S: the largest |coordinate| the turbulence reads, of (s, t) or 1 - (s, t)
  if (object) {
    for (const Image& l : in.noise.perlin_3d) layers.push_back(&l);
    const Image& g = in.noise_coordinates;
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x)
        if (g.at(x, y, 3) != 0.0f)
          for (int c = 0; c < 3; ++c) reach = std::max(reach, std::abs(g.at(x, y, c)) / p.object_noise_scale);
  } else {
    layers.push_back(&in.noise.perlin);
    float shift = 0;
    for (int k = 0; k < (p.style == SketchyStyle::Repeat ? p.edge_copies : 1); ++k)
      shift = std::max({shift, std::abs(copy_noise_shift(k).x), std::abs(copy_noise_shift(k).y)});
    reach = float(std::max(in.gbuffer.depth.width, in.gbuffer.depth.height)) / p.noise_scale + shift;
  }
  reach += 1;
  int size = layers.front()->width;
  float coordinates = 0;  // a power-of-two size scales s exactly; otherwise one rounding each
  if (!power_of_two(size) || (object && !power_of_two(int(layers.size()))))
    coordinates = levels * 2 * kUnit * texel_step(layers) * float(size) * (n * reach + 2);
  return 2 * per_backend + coordinates;
}

}  // namespace

float sample_position_tolerance(const SketchyInputs& in, const SketchyParams& p) {
  float c = float(std::max(in.gbuffer.depth.width, in.gbuffer.depth.height));
  float m = matrix_norm(p), r = m * (p.style == SketchyStyle::Rough ? 0.5f : 1.5f);
  return 4 * kUnit * (c + 2 * r) + m * uncertainty_tolerance(in, p);
}

Image sprite_depth_tie_bound(const SketchyInputs& in, const SketchyParams& p, float eps) {
  const GBuffer& g = in.gbuffer;
  const Image& edge = in.maps.edge;
  int w = g.depth.width, h = g.depth.height;
  float c_max = float(std::max(w, h)), reach = matrix_norm(p) * 1.5f;
  // The darkness is filtered at q / size, which the sampler scales back: one more rounding
  // of |q| each way, per backend; and its lerps round by 4 u each, two levels, per backend.
  float eps_dark = eps + 4 * kUnit * (c_max + reach), delta_dark = 16 * kUnit;
  auto normalized = [&](float d) { return d < g.far ? (d - g.near) / (g.far - g.near) : 1.0f; };
  // The texel indices floor(q +- eps) along one axis, clamped like nearest_texel.
  auto texels = [&](float q, int size) {
    int a = std::clamp(int(std::floor(q - eps)), 0, size - 1), b = std::clamp(int(std::floor(q + eps)), 0, size - 1);
    return std::pair<int, int>(a, b);
  };
  // The filtered darkness's range over the square q +- eps_dark: bilinear between texel
  // centers, so its extremes lie at the square's corners and where the lines through the
  // texel centers cross its sides.
  auto darkness_range = [&](glm::vec2 q) {
    auto stops = [&](float v) {
      std::vector<float> out{v - eps_dark, v + eps_dark};
      for (float k = std::floor(v - eps_dark - 0.5f) + 0.5f; k <= v + eps_dark; k += 1)
        if (k > v - eps_dark) out.push_back(k);
      return out;
    };
    float lo = 2, hi = -1;
    for (float x : stops(q.x))
      for (float y : stops(q.y)) {
        float d = sample(edge, glm::vec2(x, y) / glm::vec2(edge.width, edge.height), kClamp).x;
        lo = std::min(lo, d), hi = std::max(hi, d);
      }
    return std::pair<float, float>(lo, hi);
  };
  struct Range {
    float lo, hi;  // the nearest and farthest depth a sample can give (far = not drawn)
  };
  auto edge_range = [&](glm::vec2 q) {
    auto [lo_d, hi_d] = darkness_range(q);
    bool can_dark = hi_d + delta_dark > p.dark_edge, can_light = lo_d - delta_dark <= p.dark_edge;
    auto [x0, x1] = texels(q.x, edge.width);
    auto [y0, y1] = texels(q.y, edge.height);
    Range r{g.far, can_light ? g.far : 0.0f};
    for (int y : {y0, y1})
      for (int x : {x0, x1}) {
        float d = edge.at(x, y, 1);
        bool dark = can_dark && d < g.far;
        if (dark) r.lo = std::min(r.lo, d), r.hi = std::max(r.hi, d);
        if (!dark || !(d < g.far)) r.hi = g.far;
      }
    return r;
  };
  auto shade_range = [&](glm::vec2 q) {
    const Image& shade = in.maps.shade;
    auto [x0, x1] = texels(q.x, shade.width);
    auto [y0, y1] = texels(q.y, shade.height);
    Range r{g.far, 0.0f};
    for (int y : {y0, y1})
      for (int x : {x0, x1}) {
        float d = shade.at(x, y, 3) > 0.5f ? g.depth.at(x, y) : g.far;
        r.lo = std::min(r.lo, d), r.hi = std::max(r.hi, d);
      }
    return r;
  };
  Image out(w, h, 1);
  for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      glm::vec2 center(float(x) + 0.5f, float(y) + 0.5f);
      Sketch s = p.style == SketchyStyle::Repeat ? repeated_edges(in, p, center) : edge_and_shade(in, p, center);
      float s0 = s.drawn && s.depth < g.far ? normalized(s.depth) : 1.0f;  // what sketchy_composite writes
      Range d{g.far, g.far};
      if (p.style == SketchyStyle::Repeat) {
        for (int k = 0; k < p.edge_copies; ++k) {
          Range e = edge_range(center + copy_matrix(p, k) * uncertainty(in, p, center, k));
          d.lo = std::min(d.lo, e.lo), d.hi = std::min(d.hi, e.hi);
        }
      } else {
        glm::vec2 uv = uncertainty(in, p, center, 0);
        Range e = edge_range(center + edge_matrix(p) * uv), sh = shade_range(center + shade_matrix(p) * uv);
        d = {std::min(e.lo, sh.lo), std::min(e.hi, sh.hi)};
      }
      out.at(x, y) = std::max({0.0f, normalized(d.hi) - s0, s0 - normalized(d.lo)});
    }
  });
  return out;
}

// Over what the pencil pipeline drew, where it ran (else white paper and nothing in front).
namespace {

// The composite's inputs in a frame; `maps` holds the maps they refer to.
SketchyInputs composite_inputs(const ReferenceFrame& f, SketchyMaps& maps) {
  static const Image none;
  maps = {f.get(kSketchyEdge), f.get(kSketchyShade)};
  const Image* coordinates = f.get(maybe(kNoiseCoordinates));
  return {maps, f.get(kSketchyGBuffer), f.get(kSketchyNoise), coordinates ? *coordinates : none};
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(sketchy_composite, [](ReferenceFrame& f) {
  SketchyMaps maps;
  SketchyInputs in = composite_inputs(f, maps);
  const Image* under = f.get(maybe(kComposeColor));
  const GBuffer* ordinary = f.get(maybe(kGBuffer));
  SketchyFrame sketch =
      sketchy_composite(in, f.params<SketchyParams>(), under ? *under : Image(), ordinary ? ordinary->depth : Image());
  f.put(kSketchColor, std::move(sketch.color));
  f.put(kSketchDepth, std::move(sketch.depth));
});

// The sprite's depth is read from nearest texels: at a texel-edge tie the backends' sample
// positions, an ulp apart, can pick neighbors (sprite_depth_tie_bound above).
PLUMBAGO_REFERENCE_BOUND(sketchy_composite_depth, kSketchDepth.name, [](const ReferenceFrame& f) {
  SketchyMaps maps;
  SketchyInputs in = composite_inputs(f, maps);
  auto p = f.params<SketchyParams>();
  return sprite_depth_tie_bound(in, p, sample_position_tolerance(in, p));
});

}  // namespace plumbago::reference

#include "reference/sketchy_composite.hpp"

#include <algorithm>
#include <cmath>

#include "reference/rows.hpp"
#include "reference/sampler.hpp"
#include "reference/stage.hpp"

namespace plumbago::reference {

namespace {

const SamplerState kRepeat{Filter::Linear, Wrap::Repeat, Wrap::Repeat, Wrap::Repeat};
const SamplerState kClamp{Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, Wrap::ClampToEdge};

// T(s, t) = sum_i |N(2^i (s, t))| / 2^i (SPEC 3.2)
float turbulence(const Image& noise, glm::vec2 st, int octaves) {
  float t = 0, f = 1;
  for (int i = 0; i < octaves; ++i, f *= 2) t += std::abs(sample(noise, st * f, kRepeat).x) / f;
  return t;
}

// The same over a 3D noise texture (object style, SPEC 3.5).
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
// (SPEC 3.3); the sprite takes the nearer of the drawn samples' depths (SPEC 3.4).
Sketch edge_and_shade(const SketchyInputs& in, const SketchyParams& p, glm::vec2 center) {
  glm::vec2 uv = uncertainty(in, p, center, 0);
  EdgeSample e = edge_sample(in, p, center + edge_matrix(p) * uv);
  glm::ivec2 s = nearest_texel(in.maps.shade, center + shade_matrix(p) * uv);
  bool interior = in.maps.shade.at(s.x, s.y, 3) > 0.5f;
  Sketch out;
  out.drawn = e.dark || interior;
  out.depth = std::min(e.dark ? e.depth : in.gbuffer.far, interior ? in.gbuffer.depth.at(s.x, s.y) : in.gbuffer.far);
  glm::vec3 c = interior ? glm::vec3(in.maps.shade.at(s.x, s.y, 0), in.maps.shade.at(s.x, s.y, 1), in.maps.shade.at(s.x, s.y, 2))
                         : glm::vec3(1.0f);
  out.color = (1.0f - e.darkness) * c;
  return out;
}

// Repeat style: edge copy k drawn with its own matrix and ink, no shade map (SPEC 3.5).
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
      return glm::vec2(turbulence(in.noise.perlin_3d, q, p.octaves), turbulence(in.noise.perlin_3d, 1.0f - q, p.octaves)) -
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

// Over what the pencil pipeline drew, where it ran (else white paper and nothing in front).
PLUMBAGO_REFERENCE_STAGE(sketchy_composite, [](ReferenceFrame& f) {
  SketchyMaps maps{f.image("sketchy_maps.edge"), f.image("sketchy_maps.shade")};
  const Image* coordinates = f.find("sketchy_enlarged.noise_coordinates");
  Image none;
  SketchyInputs in{maps, f.gbuffer("sketchy_gbuffer"), f.pre.sketchy_noise, coordinates ? *coordinates : none};
  const Image* under = f.find("compose.color");
  auto g = f.gbuffers.find("gbuffer");
  SketchyFrame sketch = sketchy_composite(in, f.params<SketchyParams>(), under ? *under : none,
                                          g == f.gbuffers.end() ? none : g->second.depth);
  f.put("sketchy_composite.color", std::move(sketch.color));
  f.put("sketchy_composite.depth", std::move(sketch.depth));
});

}  // namespace plumbago::reference

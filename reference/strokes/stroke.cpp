// The stroke raster, CPU reference (Kalnins et al. 2002, §4.1; formula in common/strokes/stroke.hpp): the
// ribbons' triangles through the scalar rasterizer, each fragment blended in order.
#include "reference/strokes/stroke.hpp"

#include "reference/core/stage.hpp"
#include "reference/strokes/raster.hpp"
#include "reference/util/sampler.hpp"

namespace plumbago::reference {

namespace {

struct StrokeInputs {
  const std::vector<Image>& textures;
  const Image& height;  // the paper
  StrokePaperParams paper;
};

template <class T>
T interpolated(const StrokeVertex* t, glm::dvec3 w, T StrokeVertex::*field) {
  return T(float(w[0]) * t[0].*field + float(w[1]) * t[1].*field + float(w[2]) * t[2].*field);
}

// One triangle of a ribbon over `out.color`, rows [y0, y1).
void draw(const StrokeVertex* t, const StrokeInputs& in, StrokeRaster& out, int y0, int y1) {
  const SamplerState along{Filter::Linear, Wrap::Repeat, Wrap::ClampToEdge};
  const Image& texture = in.textures[size_t(t[0].layer)];
  const double subpixel = 1.0 / double(1 << kSubpixelBits);
  Image& color = out.color;
  rasterize_triangle(t[0].position, t[1].position, t[2].position, {0, y0, color.width, y1}, subpixel,
                     [&](int x, int y, glm::dvec3 w, bool edge) {
                       if (edge) out.edges.at(x, y) = 1;
                       if (!(w[0] >= 0 && w[1] >= 0 && w[2] >= 0)) return;  // just outside: only the edge's mark
                       float a = interpolated(t, w, &StrokeVertex::alpha) *
                                 sample(texture, interpolated(t, w, &StrokeVertex::uv), along).x;
                       glm::vec3 under(color.at(x, y, 0), color.at(x, y, 1), color.at(x, y, 2));
                       glm::vec3 c = over_paper(glm::vec4(t[0].color, a), under,
                                                in.height.at(x % in.height.width, y % in.height.height), in.paper);
                       for (int ch = 0; ch < 3; ++ch) color.at(x, y, ch) = c[ch];
                       out.fragments.at(x, y) += 1;
                     });
}

}  // namespace

StrokeRaster draw_strokes(const std::vector<StrokeVertex>& triangles, uint32_t seed, const Image& page,
                          const Image& paper_height, const StrokePaperParams& paper) {
  std::vector<Image> textures = stroke_texture_layers(seed);
  StrokeInputs in{textures, paper_height, paper};
  StrokeRaster out{page, Image(page.width, page.height, 1), Image(page.width, page.height, 1)};
  draw_in_bands(
      triangles, page.height, [](const StrokeVertex& x) { return x.position; },
      [&](const StrokeVertex* t, int y0, int y1) { draw(t, in, out, y0, y1); });
  return out;
}

PLUMBAGO_REFERENCE_STAGE(stroke, [](ReferenceFrame& f) {
  const Visibility& visibility = f.get(kVisibleRuns);
  const std::vector<RunBrush>* carried = f.get(maybe(kBrushParameters));
  std::vector<RunBrush> brushes;  // none: the 2002 paper's; coherent without the stage's: new brush paths
  if (strokes_coherent(f.scene.params)) brushes = carried ? *carried : std::vector<RunBrush>(visibility.runs.size());
  std::vector<RunStroke> strokes = run_strokes(f.get(kWindowLines), visibility, f.scene.strokes, f.scene.seed, brushes);
  StrokeRaster r = draw_strokes(stroke_triangles(strokes), f.scene.seed, f.get(kPage), f.get(kPaperHeight),
                                f.params<StrokePaperParams>());
  f.put(kStrokeColor, std::move(r.color));
  f.put(kStrokeFragments, std::move(r.fragments));
  f.put(kRibbonEdges, std::move(r.edges));
});

// What the GPU may add to each fragment (derived, not fitted): its alpha comes from a
// bilinear lookup whose sample position llvmpipe quantizes to 1/256 of a texel (docs/conventions.md: 8-bit
// weights), up to 1/256 of a [0, 1] texture's step in u and in v, doubled by the paper
// transfer's slope: 4/256 of alpha, so of color; and its blend into the 8-bit target
// rounds by up to half a step. 4.5/255 a fragment, less the declared tolerance. At the
// pixels a ribbon's edge passes within a subpixel of (the 1-px band at ribbon edges),
// rounding decides whether the fragment is drawn at all: anything goes there, and the note
// counts them.
PLUMBAGO_REFERENCE_BOUND(stroke_color, kStrokeColor.name, [](const ReferenceFrame& f) {
  Image bound = f.get(kStrokeFragments);
  const Image& edges = f.get(kRibbonEdges);
  for (size_t i = 0; i < bound.data.size(); ++i)
    bound.data[i] = edges.data[i] > 0 ? 1.0f : std::max(0.0f, bound.data[i] * 4.5f / 255.0f - float(tolerance::kByte));
  return bound;
});

}  // namespace plumbago::reference

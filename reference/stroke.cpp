// The stroke raster, CPU reference (SPEC 4.6-4.7; formula in common/stroke.hpp): the
// ribbons' triangles through the scalar rasterizer, each fragment blended in order.
#include "common/stroke.hpp"

#include "common/stroke_paper.hpp"
#include "reference/raster.hpp"
#include "reference/sampler.hpp"
#include "reference/stage.hpp"

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

// One triangle of a ribbon over `out`, rows [y0, y1); counts the fragments per pixel.
void draw(const StrokeVertex* t, const StrokeInputs& in, Image& out, Image& fragments, int y0, int y1) {
  const SamplerState along{Filter::Linear, Wrap::Repeat, Wrap::ClampToEdge};
  const Image& texture = in.textures[size_t(t[0].layer)];
  rasterize_triangle(t[0].position, t[1].position, t[2].position, {0, y0, out.width, y1}, 0.0, [&](int x, int y, glm::dvec3 w, bool) {
    float a = interpolated(t, w, &StrokeVertex::alpha) * sample(texture, interpolated(t, w, &StrokeVertex::uv), along).x;
    glm::vec3 under(out.at(x, y, 0), out.at(x, y, 1), out.at(x, y, 2));
    glm::vec3 c = over_paper(glm::vec4(t[0].color, a), under, in.height.at(x % in.height.width, y % in.height.height), in.paper);
    for (int ch = 0; ch < 3; ++ch) out.at(x, y, ch) = c[ch];
    fragments.at(x, y) += 1;
  });
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(stroke, [](ReferenceFrame& f) {
  std::vector<StrokeVertex> v = stroke_triangles(frame_lines(f.host, f.host, f.scene), *f.host.find<Visibility>("visibility"), f.scene.strokes);
  std::vector<Image> textures = stroke_texture_layers(f.scene.seed);
  StrokeInputs in{textures, f.pre.paper.height, f.params<StrokePaperParams>()};
  Image out = f.image("stroke_paper.color"), fragments(out.width, out.height, 1);
  draw_in_bands(v, out.height, [](const StrokeVertex& x) { return x.position; },
                [&](const StrokeVertex* t, int y0, int y1) { draw(t, in, out, fragments, y0, y1); });
  f.put("stroke.color", std::move(out));
  f.put("stroke.fragments", std::move(fragments));  // not an output: what the bound below reads
});

// The GPU blends each fragment into its 8-bit target: every blend after the first may round
// by half a step more than the one the declared tolerance covers.
PLUMBAGO_REFERENCE_BOUND(stroke_color, "stroke.color", [](const ReferenceFrame& f) {
  Image bound = f.image("stroke.fragments");
  for (float& b : bound.data) b = std::max(0.0f, b - 1.0f) * 0.5f / 255.0f;
  return bound;
});

}  // namespace plumbago::reference

// The stroke raster's triangles (SPEC 4.6-4.7): see common/stroke.hpp.
#include "common/stroke.hpp"

#include "common/stroke_textures.hpp"

namespace plumbago {

namespace {

const StrokeStyle& style_of(LineKind kind, const StrokeStyles& styles) {
  switch (kind) {
    case LineKind::Crease: return styles.crease;
    case LineKind::Border: return styles.border;
    case LineKind::Silhouette: break;
  }
  return styles.silhouette;
}

}  // namespace

std::vector<StrokeVertex> stroke_triangles(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles) {
  std::vector<StrokeVertex> out;
  for (const VisibleRun& run : visibility.runs) {
    const StrokeStyle& style = style_of(lines.paths[run.path].kind, styles);
    Ribbon ribbon = base_stroke({run.window, run.closed, run.occluded_start, run.occluded_end}, style);
    for (const RibbonVertex& v : ribbon.triangles)
      out.push_back({v.position, v.uv, v.alpha, ribbon.color, float(int(style.texture))});
  }
  return out;
}

std::vector<Image> stroke_texture_layers(uint32_t seed) {
  std::vector<Image> layers;
  for (size_t k = 0; k < stroke_texture_names().size(); ++k) layers.push_back(stroke_texture(StrokeTextureKind(k), seed));
  return layers;
}

}  // namespace plumbago

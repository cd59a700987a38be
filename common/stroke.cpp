// The stroke raster's triangles (SPEC 4.6-4.7): see common/stroke.hpp.
#include "common/stroke.hpp"

#include <map>
#include <string>

#include "common/offset_synthesis.hpp"
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

StrokeStyle RunStyles::of(const WindowPath& path, const VisibleRun& run, size_t index) {
  StrokeStyle style = style_of(path.kind, styles_);
  if (style.synthesis != OffsetSynthesis::Markov || !style.offsets) return style;
  auto it = chains_.find(path.kind);
  if (it == chains_.end()) it = chains_.emplace(path.kind, OffsetSynthesizer(*style.offsets)).first;
  std::string name = "stroke run " + std::to_string(path.key) + "/" + std::to_string(index);
  style.offsets = it->second.synthesize_example(run.s1 - run.s0, seed_, name);
  return style;
}

std::vector<StrokeVertex> stroke_triangles(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles,
                                           uint32_t seed) {
  std::vector<StrokeVertex> out;
  RunStyles run_styles(styles, seed);
  for (size_t i = 0; i < visibility.runs.size(); ++i) {
    const VisibleRun& run = visibility.runs[i];
    StrokeStyle style = run_styles.of(lines.paths[run.path], run, i);
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

// The stroke raster (Kalnins et al. 2002 §4.1, §4.4): each visible run of a
// stroke object's feature lines (common/strokes/visibility.hpp) becomes a base stroke in its line
// kind's style (common/strokes/base_stroke.hpp, the scene's "strokes" styles), a ribbon of window
// triangles. Per fragment, with the ribbon's interpolated alpha a_v and texture
// coordinates (u along, v across; affine in window space), and T the style's stroke
// texture (common/strokes/stroke_textures.hpp; u REPEAT, v CLAMP_TO_EDGE, LINEAR):
//   a = a_v T(u, v)
//   out = color a' + out (1 - a'),  a' = the paper's alpha transfer of a (Kalnins et al. 2002, §4.4)
// premultiplied "over", ribbon after ribbon in path order (creases and borders, then
// silhouettes, then decals and hatches, Kalnins et al. 2002, §3, §6), triangle after triangle. Both
// backends make the same samples in double (common/strokes/base_stroke.hpp 1.-5.; the GPU in a
// compute shader, gpu/strokes/stroke_samples.hpp) from the same runs and styles (styled_runs;
// the GPU gives each run its polyline and style itself, by the same rules, from the scene's
// styles put up once: gpu/strokes/run_styles.hpp); the reference makes their triangles in double (6.) and draws them
// with its scalar rasterizer; the GPU expands them in its vertex shader, in float, and draws them in one indirect call.
#pragma once

#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/stage.hpp"
#include "common/strokes/base_stroke.hpp"
#include "common/strokes/brush_parameters.hpp"
#include "common/strokes/offset_synthesis.hpp"
#include "common/strokes/stroke_paper.hpp"
#include "common/strokes/visibility.hpp"

namespace plumbago {

// One vertex as the reference draws it: window position, (u, v), alpha, color, the stroke
// texture's layer (StrokeTextureKind).
struct StrokeVertex {
  glm::vec2 position, uv;
  float alpha;
  glm::vec3 color;
  float layer;
};

// The style a run is drawn with: its line kind's, with the offsets example synthesized over
// the run's length (Kalnins et al. 2002, §4.3, §5, App. A) where the style asks for it; where the scene
// has drawn examples (StrokeStyles), those: rubber-stamped in turn along the path from one
// its key picks, or synthesized from all of them. A decal's (Kalnins et al. 2002, §3, §4.5), with its drawn
// pressure over the run (common/strokes/decal.hpp 3.); a hatch's the same, its alpha and width times its
// level-of-detail factors (Kalnins et al. 2002, §6).
// What is random is drawn from counter-based streams keyed by the scene seed, the path's
// key and the run's ordinal along its path (common/util/random.hpp): a run keeps its
// style when other paths come or go, and each run's numbers can be drawn on their own.
// How the runs of a creases', borders' or silhouettes' line kind get their offsets
// (RunStyles::of): none; the style's own example; the scene's drawn examples for the kind
// (StrokeStyles), rubber-stamped in turn along a path from one its key picks; or an example
// synthesized for each run by the Markov chain of the drawn examples, else of the style's own.
enum class RunOffsets { None, Own, Drawn, Synthesized };
RunOffsets run_offsets(LineKind kind, const StrokeStyles& styles);
const StrokeStyle& line_style(LineKind kind, const StrokeStyles& styles);
const std::vector<OffsetExample>& drawn_examples(LineKind kind, const StrokeStyles& styles);
// The Markov chain of a kind whose runs' offsets are Synthesized.
OffsetSynthesizer offset_chain(LineKind kind, const StrokeStyles& styles);
// The keys of a run's counter-based streams: which drawn example a path starts its stamps
// with, and the Markov walk of its run `ordinal` (common/util/random.hpp stream_key).
enum RunStream : uint32_t { kStampStart = 1, kOffsetWalk = 2 };
// The brush path a run draws (common/strokes/coherent_silhouettes.hpp 5.): `brush`'s, else a
// new one keyed by the run's Markov walk (the scene seed, its path's key, its ordinal).
uint32_t brush_path_key(const RunBrush& brush, uint32_t seed, const WindowPath& path, uint32_t ordinal);

class RunStyles {
 public:
  RunStyles(const StrokeStyles& styles, uint32_t seed, const std::vector<StrokeStyle>& decals)
      : styles_(styles), seed_(seed), decals_(decals) {}
  // `ordinal`: the run's place among its path's runs (run_ordinals); `brush`: the run's
  // where coherent silhouettes are on (a synthesized style draws its brush path's offsets).
  StrokeStyle of(const WindowPath& path, const VisibleRun& run, uint32_t ordinal, const RunBrush* brush = nullptr);

 private:
  const StrokeStyles& styles_;
  uint32_t seed_;
  const std::vector<StrokeStyle>& decals_;
  std::map<LineKind, OffsetSynthesizer> chains_;  // one chain per kind's example, made on first use
};

// Each run's place among its path's runs, in visibility.runs' order.
std::vector<uint32_t> run_ordinals(const std::vector<VisibleRun>& runs);

// Every visible run's style (RunStyles::of), in drawing order (visibility.runs' order); run i
// with brushes[i] where coherent silhouettes are on (brushes one a run), else none.
std::vector<StrokeStyle> run_styles(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles,
                                    uint32_t seed, const std::vector<RunBrush>& brushes = {});

// One visible run as a base stroke takes it (its window polyline and ends) and the style it
// is drawn in (RunStyles::of).
struct StyledRun {
  StrokeRun run;
  StrokeStyle style;
};

// Every visible run with its style and, where coherent silhouettes are on (brushes one a
// run), its brush's knots, in drawing order (visibility.runs' order): what both backends make
// the stroke samples of (the GPU: gpu/strokes/stroke_samples.hpp).
std::vector<StyledRun> styled_runs(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles,
                                   uint32_t seed, const std::vector<RunBrush>& brushes = {});

// One visible run as it is drawn: its style (RunStyles::of) and its base stroke's samples.
struct RunStroke {
  StrokeStyle style;
  BaseStrokeSamples samples;
};

// Every visible run's stroke, in drawing order (visibility.runs' order): what
// stroke_triangles draws, and what experiments/temporal_coherence measures. Run i takes
// brushes[i] as its brush where coherent silhouettes are on (Kalnins et al. 2003,
// common/strokes/coherent_silhouettes.hpp: one a run; its knots, or t = s, and its brush
// path's offsets), else t = s (brushes empty).
std::vector<RunStroke> run_strokes(const WindowLines& lines, const Visibility& visibility, const StrokeStyles& styles,
                                   uint32_t seed, const std::vector<RunBrush>& brushes = {});

// The ribbons of `strokes`, three vertices a triangle, in their order.
std::vector<StrokeVertex> stroke_triangles(const std::vector<RunStroke>& strokes);

// The ribbons of every visible run (run_strokes), three vertices a triangle, in drawing order; `seed`
// (the scene's) seeds the offsets a style synthesizes (Kalnins et al. 2002, §4.3, §5, App. A).
std::vector<StrokeVertex> stroke_triangles(const WindowLines& lines, const Visibility& visibility,
                                           const StrokeStyles& styles, uint32_t seed);

// The strokes a frame draws: its visible runs per line kind, keyed "strokes.<kind>", and
// their sum, "strokes" (what Kalnins et al.'s Table 1 counts); the window's "paths" and the
// visibility "samples" tested (bisection included); per hatching group N,
// "hatching.groupN.sigma" and "hatching.groupN.level" (from + progress (to - from),
// Kalnins et al. 2002, §6); empty without lines or visible runs (a frame without strokes).
std::map<std::string, double> stroke_counts(const WindowLines* lines, const Visibility* v);

// The stroke textures, one per StrokeTextureKind, from the scene seed.
std::vector<Image> stroke_texture_layers(uint32_t seed);

inline constexpr Buffer kStrokeColor{"stroke.color"};
// Reference only: what the parity bound of kStrokeColor reads.
inline constexpr Slot<Image> kStrokeFragments{"stroke.fragments"};
inline constexpr Slot<Image> kRibbonEdges{"stroke.ribbon_edges"};

struct StrokeStage {
  using Params = TypeList<>;
  static StageDesc describe() {
    return {
        .name = "stroke",
        .kind = StageKind::Frame,
        .doc = "stylized strokes of the visible feature lines (Kalnins et al. 2002, §4.1)",
        .params = {"stroke_paper"},
        .inputs = {{.handle = kWindowLines},
                   {.handle = kVisibleRuns},
                   {.handle = kPage},
                   {.handle = kPaperHeight},
                   // Made only in a frame that runs the stage (parity feeds none: both draw t = s).
                   {.handle = kBrushParameters, .used = when::strokes_coherent, .fed_in_parity = false}},
        .outputs = {{.handle = kStrokeColor,
                     .channels = 3,
                     .texel = Texel::Unorm8,
                     .doc = "the strokes over the page",
                     .tolerance = tolerance::kByte,
                     .tolerance_why =
                         "fed the same page, visible runs and paper; the ribbons through the same samples (the GPU's "
                         "made in double, within one float rounding), their corners made in float on the GPU, which "
                         "moves an edge by float rounding, within the band below; the GPU filters "
                         "the stroke texture with 8-bit weights and blends each fragment into an 8-bit "
                         "target: a derived bound allows 4.5/255 per fragment less the tolerance, and "
                         "anything in the 1-px band where a ribbon's edge passes within a subpixel of "
                         "the pixel center (measured max 0.0128 on the teapot where ribbons overlap)",
                     .frame_color = true,
                     .draws_over = {kPage.name}},
                    {.handle = kStrokeFragments, .texel = Texel::Host, .doc = "reference only: fragments per pixel"},
                    {.handle = kRibbonEdges,
                     .texel = Texel::Host,
                     .doc = "reference only: 1 where a ribbon edge passes near the pixel center"}},
        .effects = {"strokes"}};
  }
};

}  // namespace plumbago

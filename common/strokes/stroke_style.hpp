// Stroke styles (Kalnins et al. 2002 §4.2, §5): what a base stroke looks
// like: width, taper, fade, halo, flare, alpha, color, texture, and an optional example
// of offsets to rubber-stamp along it. Styles are JSON files; the presets live in
// styles/strokes/ (pencil, charcoal, ink, toon_silhouette).
//
// Each scalar is declared once, in StrokeStyle::visit (key, default, range, doc), with
// the visitor interface of common/core/params.hpp; the defaults, the JSON reader, the
// validation and stroke_style_specs() all walk it. A style file is one object whose keys
// are those names, plus two that are not scalars:
//   "description": a string, for the reader of the file;
//   "offsets": {"length_px": L_drawn, "points": [[t, displacement_px, pressure, break], ...]}
//     Kalnins et al.'s (2002, §4.3, App. A) offset list: t in [0, 1] along the example, not decreasing; the
//     displacement in px along the screen normal (to the left of the direction of travel,
//     towards v = 1); pressure in [0, 1]; break true lifts the pen from this offset to
//     the next. L_drawn (px) is the example's length when it was drawn: the period of
//     the rubber stamp (base_stroke.hpp).
//
// Readings where Kalnins et al. 2002, §4.1 is silent:
//   - flare: the width is multiplied by (1 + flare (1 - 2 dl / L)), dl the distance to the
//     nearer end of the run, L the run's length: 1 + flare at the ends, 1 in the middle,
//     so flare > 0 widens the ends before the taper narrows them (flare in [-1, 10]; a
//     closed run has no ends and no flare);
//   - pressure (the paper: "width and alpha can be made to vary along the stroke due to
//     pressure"): the example's pressure, interpolated like its displacement, multiplies
//     the width (`pressure_width`, on by default) and/or alpha (`pressure_alpha`, off).
//     Without offsets the pressure is 1.
//
// Every refusal throws StrokeStyleError naming the file and the JSON pointer of the key,
// e.g. "styles/strokes/x.json: /width_px: must be in [0.1, 200], got 500".
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/core/params.hpp"
#include "common/strokes/stroke_textures.hpp"

namespace plumbago {

// One entry of Kalnins et al.'s (2002, §4.3, App. A) offset list.
struct StrokeOffset {
  double t = 0;                // position along the example, [0, 1]
  double displacement_px = 0;  // along the screen normal, px
  double pressure = 1;         // [0, 1]
  bool pen_up = false;         // the break flag: no ink from this offset to the next
};

// An example stroke's offsets and its length when drawn (L_drawn, px).
struct OffsetExample {
  double length_px = 0;
  std::vector<StrokeOffset> offsets;  // t not decreasing, at least one
  // false: made to span one run (a decal's drawn pressure, a synthesized example): past its
  // length it holds its last offset instead of starting over (common/strokes/base_stroke.hpp 4.).
  bool repeats = true;
  // false: drawn at full size on a run of any length, not scaled by min(L / L_drawn, 1) (a
  // brush path's synthesized offsets: common/strokes/coherent_silhouettes.hpp 5.).
  bool scales = true;
};

enum class OffsetSynthesis { Stamp, Markov };

struct StrokeStyle {
  std::string description;
  float width_px, taper_px, fade_px, halo_px, flare, alpha;
  float color_r, color_g, color_b;
  StrokeTextureKind texture;
  float texture_period_px, sample_px;
  bool pressure_width, pressure_alpha;
  OffsetSynthesis synthesis;
  std::optional<OffsetExample> offsets;

  template <class V>
  void visit(V& v) {
    v.real(width_px, "width_px", 4.0, 0.1, 200.0, "width of the stroke, px (Kalnins et al. 2002, §4.1 `width`)");
    v.real(taper_px, "taper_px", 24.0, 0.0, 1000.0,
           "T: within T px of an end the width is x sqrt(1 - ((T - dl)/T)^2); 0 = no taper");
    v.real(fade_px, "fade_px", 0.0, 0.0, 1000.0,
           "F: within F px of an end alpha is x (1 - ((F - dl)/F)^2)^1.5; 0 = off");
    v.real(halo_px, "halo_px", 6.0, 0.0, 1000.0,
           "H: within H px of an end caused by occlusion, h = (H - dl)/H, width x (1 - h^2)^0.25, alpha x (1 - h^2)^5");
    v.real(flare, "flare", 0.0, -1.0, 10.0,
           "width x (1 + flare (1 - 2 dl / L)): > 0 widens the ends, < 0 narrows them");
    v.real(alpha, "alpha", 1.0, 0.0, 1.0, "opacity of the stroke");
    v.real(color_r, "color_r", 0.1, 0.0, 1.0, "stroke color, red");
    v.real(color_g, "color_g", 0.1, 0.0, 1.0, "stroke color, green");
    v.real(color_b, "color_b", 0.1, 0.0, 1.0, "stroke color, blue");
    v.choice(texture, "texture", StrokeTextureKind::Pencil, stroke_texture_names(),
             "stroke texture (Kalnins et al. "
             "2002, §4.1)");
    v.real(texture_period_px, "texture_period_px", 64.0, 1.0, 10000.0,
           "px along the stroke that one tile of the texture spans");
    v.real(sample_px, "sample_px", 3.5, 0.25, 100.0,
           "resampling step along the spline, px (Kalnins et al. 2002, §4.1)");
    v.boolean(pressure_width, "pressure_width", true, "the offsets' pressure multiplies the width");
    v.boolean(pressure_alpha, "pressure_alpha", false, "the offsets' pressure multiplies alpha");
    v.choice(synthesis, "synthesis", OffsetSynthesis::Stamp, {"stamp", "markov"},
             "how the offsets example covers a run: repeated (rubber stamp, Kalnins et al. 2003) or synthesized by the "
             "Markov chain of Kalnins et al. 2002, §4.3, §5, App. A");
  }
};

// A refused style: the message names the file and the JSON pointer of the key.
struct StrokeStyleError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Every default from StrokeStyle::visit, no offsets.
StrokeStyle default_stroke_style();

// The scalars of StrokeStyle::visit, keyed by their JSON names (for documentation).
std::vector<ParamSpec> stroke_style_specs();

// Parses a style document; keys left out take their defaults. `source` names it in messages.
StrokeStyle parse_stroke_style(const std::string& json_text, const std::string& source);

// Whether `name_or_path` names a preset (no '/', not ending in ".json") rather than a file.
bool is_stroke_style_preset(const std::string& name_or_path);

// A name without '/' and not ending in ".json" is a preset: <stroke_style_dir()>/<name>.json;
// anything else is a file path.
StrokeStyle load_stroke_style(const std::string& name_or_path);
// load_stroke_style with a relative file path taken from `base_dir` (the folder of the
// scene or stroke file that names the style).
StrokeStyle load_stroke_style_from(const std::string& name_or_path, const std::string& base_dir);

// $PLUMBAGO_STYLE_DIR when set, else the repository's styles/strokes.
std::string stroke_style_dir();

// The presets in stroke_style_dir(), sorted (file names without ".json").
std::vector<std::string> stroke_style_names();

// Refuses (StrokeStyleError, naming `source`) a style built in code whose values
// parse_stroke_style would refuse: a scalar out of its range or NaN, bad offsets.
void validate_stroke_style(const StrokeStyle& style, const std::string& source);

}  // namespace plumbago

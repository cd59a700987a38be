// Hatching groups (Kalnins et al. 2002 §6.1-6.2): strokes of the stroke files
// (role "hatching", common/strokes/stroke_file.hpp) drawn on the surface like decals
// (common/strokes/decal.hpp), whose number follows the group's size on screen.
//
// 1. Groups, when the scene is read (hatching_groups): the hatching strokes of all stroke
//    files, by group number.
//    - Structured (the default): "roughly parallel and regularly spaced" strokes, from one
//      stroke file. Each is turned to run the way the first does; they are ordered across
//      (by their middle along the normal of their mean direction, in the drawing's window),
//      hatch i at position q = i. The hatches between neighbours, q = i + j / 2^kMaxHatchLevel,
//      "linearly interpolate those of their neighbours": both resampled at the same arc-length
//      fractions in the drawing's window and mixed by q's fraction (points and pressure).
//      Drawn and interpolated hatches alike are projected onto the surface as decals are.
//    - Free ("free": true): the artist's own levels of detail. Level k is the group's
//      strokes of its k-th stroke file (in the scene's order), drawn from a closer view.
// 2. Scale sigma, every frame:
//    - structured, sigma_h: the window length of the backbone (the segments joining the
//      middle surface points of neighbouring drawn hatches) over its length in the drawing's
//      camera and window;
//    - free, sigma_m (§5.4): the object's screen diameter (its bounding sphere's) over that
//      in level 0's camera; level k was drawn at sigma_k, its own camera's sigma_m.
//    A structured group's level k is drawn at sigma_k = 2^k (k < 0: every 2^-k-th hatch).
// 3. Level of detail (hatch_lod_step): at level L the group goes up when sigma >=
//    sigma_{L+1} t+ / 2 and down when sigma < sigma_L t- / 2 (t+ = 1.6: a structured group
//    doubles at 1.6, halves again below 1.4 with t- = 1.4; a t- above t+ counts as t+),
//    one level at a time, each change a transition of `fade_s` seconds of frame time
//    (Animation::time_s; a transition runs to its end before the next may start). Structured
//    levels lie in [-floor(log2(n - 1)), max_level] (at least two hatches), free ones in
//    [0, levels - 1]. Frame 0, or a scene without a camera path, starts settled: the level
//    reached from 0 by those rules, no transition. Frame i replays frames 0..i, so a frame
//    does not depend on which frames were rendered before it.
// 4. Per hatch (hatch_weights): with p the transition's progress in [0, 1] from level A to
//    level B, presence = (1 - p) [in A] + p [in B]; alpha is multiplied by the presence
//    (the fades) and, in a structured group, the width by sigma / ((1 - p) 2^A + p 2^B),
//    clamped to [1/4, 4] ("strokes thicken as their density falls", then narrow as the new
//    ones come in). Hatch q is in structured level L when q 2^L is whole; free hatch of
//    level k is in L when k <= L.
#pragma once

#include <cstdint>
#include <vector>

#include "common/core/params.hpp"
#include "common/scene/scene.hpp"

namespace plumbago {

// Interpolated hatches are made down to this level: 2^3 - 1 between each pair of neighbours.
constexpr int kMaxHatchLevel = 3;

struct HatchingParams {
  static constexpr const char* stage = "hatching";
  float t_plus, t_minus, fade_s, mobile_threshold, mobile_fade;
  int max_level;
  template <class V>
  void visit(V& v) {
    v.real(t_plus, "t_plus", 1.6, 1.0, 2.0,
           "t+: up a level when sigma reaches sigma_next t+ / 2 (a structured group doubles at t+, Kalnins et al. "
           "2002, §6)");
    v.real(t_minus, "t_minus", 1.4, 1.0, 2.0,
           "t-: down a level when sigma falls below sigma_level t- / 2 (hysteresis; above t+ counts as t+)");
    v.real(fade_s, "fade_s", 0.5, 0.0, 10.0,
           "seconds of frame time a level transition takes (Kalnins et al. 2002, §6)");
    v.integer(max_level, "max_level", 2, 0, kMaxHatchLevel,
              "a structured group's highest level (2^level x its hatches); beyond it the strokes only thicken");
    v.real(mobile_threshold, "mobile_threshold", 0.5, 0.0, 0.99,
           "T: a mobile group is placed at a local maximum of l(u) = n_c . n(u) only where l >= T (Kalnins et al. "
           "2002, §6.3: 1/2)");
    v.real(mobile_fade, "mobile_fade", 0.1, 0.0, 1.0,
           "a mobile group's alpha rises from 0 at l = T to 1 at l = T + this (the fade as l approaches T, §6.3); 0: "
           "none");
  }
};

// A float parameter as the decimal it was given (6 significant digits are kept): 1.6, not
// 1.6000000238, so that sigma = 1.6 reaches t+ = 1.6 and 0.2 s at 30 fps is 6 frames.
double given_value(float value);

// What a surface stroke is: a decal (group -1) or a hatch of a group.
struct HatchTag {
  int group = -1;       // index in hatching_groups(scene); -1: a decal
  double position = 0;  // structured: q (drawn hatch i at q = i); free: its level of detail
};

struct HatchGroup {
  int number;  // the files' group number
  bool free;
  bool mobile;                  // moves on the surface (Kalnins et al. 2002, §6.3, common/strokes/mobile_hatching.hpp)
  std::vector<uint32_t> files;  // indices in scene.stroke_files: structured one, free one per level
  size_t hatches = 0;           // structured: the drawn hatches
};

// The scene's hatching groups, ordered by number. Throws SceneError, naming the stroke
// file and the group, for a structured group drawn in several files or a group mixing
// free and structured strokes, or mobile and stationary ones.
std::vector<HatchGroup> hatching_groups(const Scene& scene);

// A hatch before projection: its polyline in its stroke file's window.
struct HatchPolyline {
  uint32_t file;
  const DrawnStroke* stroke;  // whose style it takes: a free hatch's own; in a structured group, the group's first
  HatchTag tag;
  std::vector<DrawnPoint> points;
};
// Every hatch of every group (1. above), group after group, by position.
std::vector<HatchPolyline> hatch_polylines(const Scene& scene);

// A group's level-of-detail state: level `to`, reached from `from` by a transition that
// began at `start_s` (from == to: settled).
struct HatchLod {
  int from = 0, to = 0;
  double start_s = 0;
  double progress(double time_s, double fade_s) const;
};

// The level's scale (2. above) and the levels allowed.
struct HatchLevels {
  std::vector<double> sigma;  // free: sigma_k per level k >= 0; structured: empty (2^k)
  int lowest = 0, highest = 0;
  double at(int level) const;
};

// One frame of 3. above: the state after seeing `sigma` at `time_s`.
HatchLod hatch_lod_step(const HatchLod& state, double sigma, double time_s, const HatchLevels& levels,
                        const HatchingParams& p);
// The settled level for `sigma`, from level 0.
HatchLod hatch_lod_settled(double sigma, const HatchLevels& levels, const HatchingParams& p);

// A group at the frame `scene` shows: its sigma, its state, the transition's progress,
// and the object it lies on: the one most of its drawn points (level 0's) meet. Its
// hatches' points on other objects are dropped (a hatch that strays past its object's
// outline while drawn does not hatch what lies behind).
struct HatchGroupState {
  int number;
  bool free, mobile;
  uint32_t object;
  double sigma;
  HatchLod lod;
  double progress;
};
struct ProjectedDecal;
// Per group of hatching_groups(scene), from the surface strokes (common/strokes/decal.hpp DecalSurface).
std::vector<HatchGroupState> hatch_states(const Scene& scene, const std::vector<ProjectedDecal>& surface,
                                          const HatchingParams& p);

// A hatch's factors this frame (4. above); a decal's are 1.
struct HatchWeight {
  double alpha = 1, width = 1;
};
// One per surface stroke.
std::vector<HatchWeight> hatch_weights(const std::vector<HatchGroupState>& states,
                                       const std::vector<ProjectedDecal>& surface);

}  // namespace plumbago

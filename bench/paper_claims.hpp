// The frame rates the papers claim, in one table (Lee et al. 2006, "Experimental Results";
// Nienhaus & Döllner 2004, §3.5; Kalnins et al. 2002, Table 1).
// `plumbago bench --paper` prints ours for the closest configuration next to them: the
// scene file named in `plumbago_scene` (relative to the repository root), or, where
// Plumbago has no such configuration yet, the reason in `plumbago_note`.
#pragma once

#include <string>
#include <vector>

namespace plumbago {

struct PaperClaim {
  std::string paper;  // short citation
  std::string scene;  // what was drawn
  int faces;          // 0 when the paper gives no count
  std::string resolution;
  double fps_low, fps_high;  // a single figure has low == high
  std::string hardware;
  std::string style;           // the closest Plumbago effects/style
  std::string plumbago_scene;  // our closest configuration ("" when there is none)
  std::string plumbago_note;   // how it differs from theirs, or why there is none
};

inline const std::vector<PaperClaim>& paper_claims() {
  static const std::vector<PaperClaim> claims = {
      {"Lee et al. 2006", "reasonably complicated meshes", 0, "not stated", 15, 60, "GeForce 7800GTX, Pentium IV 630",
       "pencil", "scenes/fandisk_pencil.json", "every effect: contours, interior, cross hatching, paper"},
      {"Lee et al. 2006", "reasonably complicated meshes", 0, "not stated", 15, 60, "GeForce 7800GTX, Pentium IV 630",
       "pencil", "scenes/fandisk_contours.json", "contours only (Fig. 9a)"},
      {"Nienhaus & Doellner 2004", "Ogre", 124008, "800x800", 20, 20, "GeForce FX 5600", "sketchy",
       "scenes/ogre_sketchy.json", "style default: edge and shade maps"},
      {"Kalnins et al. 2002", "cup, 25 strokes", 5000, "not stated", 20, 20, "GeForce3, Pentium IV 1.5 GHz", "strokes",
       "scenes/cup_strokes.json",
       "spot (5,856 faces) decorated like a cup: toon coat, paper, wide silhouettes, 9 "
       "decals (flowers, leaves, a band); 35 visible strokes at the scene's camera"},
      {"Kalnins et al. 2002", "statue, 100 strokes", 120000, "not stated", 10, 10, "GeForce3, Pentium IV 1.5 GHz",
       "strokes", "scenes/statue_strokes.json",
       "the Ogre (124K faces): toon coat, silhouettes synthesized by the "
       "Markov chain, creases over 100 degrees; 146 visible strokes at the scene's camera"},
      {"Kalnins et al. 2002", "building, 7000 strokes", 16000, "not stated", 3, 3, "GeForce3, Pentium IV 1.5 GHz",
       "strokes", "scenes/storefront_strokes.json",
       "a procedural brick storefront: every brick a box of creases, "
       "drawn in a graphite style synthesized from drawn crease examples; 5,359 visible strokes at the scene's camera"},
      {"Kalnins et al. 2002", "breakfast, 400 strokes", 25000, "not stated", 9, 9, "GeForce3, Pentium IV 1.5 GHz",
       "strokes", "scenes/breakfast_strokes.json",
       "a table with the teapot, spot, the cow, an orange and a mug "
       "(24,268 faces): conte silhouettes and creases, translucent toon coat, free hatching in two levels of detail; "
       "279 visible strokes at frame 0; timed along its 40-frame dolly"},
      {"Kalnins et al. 2002", "snowman, 250 strokes", 10000, "not stated", 11, 11, "GeForce3, Pentium IV 1.5 GHz",
       "strokes", "scenes/snowman_strokes.json",
       "procedural spheres and cones (11,136 faces): pale toon coat, "
       "Markov-synthesized crayon silhouettes, decals for the face, structured hatching; 181 visible strokes"},
  };
  return claims;
}

}  // namespace plumbago

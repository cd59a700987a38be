// The shower-door measure of experiments/shower_door/README.md: how much of a per-pixel
// pattern (the sketch's (u, v) perturbation, Nienhaus & Döllner 2004, §3.2, or the
// rendered sketch) moves with the surface between two frames and how much stays fixed to
// the screen.
#pragma once

#include <cstddef>

#include "common/util/image.hpp"

namespace plumbago::shower_door {

// How the previous frame's pattern is read at p', which falls between pixel centers.
enum class Sampling { Bilinear, Nearest };

struct Residuals {
  double attached = 0;  // A: mean |P_next(p) - P_prev(p')|, what is left if the pattern moved with the surface
  double fixed = 0;     // B: mean |P_next(p) - P_prev(p)|, what is left if it stayed on the screen
  size_t pixels = 0;    // the valid pixels of the motion map averaged over
  // B / (A + B): 1 = moves with the surface, 0 = fixed to the screen; NaN if A + B = 0
  // (a pattern that did not change at all says nothing) or no pixel was valid.
  double coherence() const;
};

// `prev`, `next`: the pattern in two consecutive frames, same size and channels; |.| is
// the Euclidean norm over all channels. `motion`: surface_motion's map (p'.x, p'.y, valid).
Residuals residuals(const Image& prev, const Image& next, const Image& motion, Sampling sampling);

// The same per pixel: 2 ch, |P_next(p) - P_prev(p')| and |P_next(p) - P_prev(p)| at valid
// pixels, 0 elsewhere. residuals() is their mean over the valid pixels.
Image residual_map(const Image& prev, const Image& next, const Image& motion, Sampling sampling);

}  // namespace plumbago::shower_door

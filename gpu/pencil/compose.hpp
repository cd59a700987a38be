// Composition on the GPU (Lee et al. 2006, §6, Eq. 6), the twin of reference/pencil/compose.cpp.
#pragma once

#include "common/pencil/compose.hpp"
#include "gpu/gl/framebuffer.hpp"
#include "gpu/pencil/multi_contour.hpp"

namespace plumbago::gpu {

// What is composed besides D_c: D_i and the paper color, each read only when its flag
// says it exists.
struct ComposeInputs {
  const Texture& interior_darkness;
  bool has_interior;
  const Texture& paper_color;
  bool has_paper;
};

class ComposePass {
 public:
  ComposePass();
  // Writes the RGB(A) frame into `out`. The shader runs only inside `inside`, where D_c or
  // D_i can differ from 0; outside it the frame is the blank page (D_c = D_i = 0), which
  // the shader draws once per size and paper and a copy puts in place every frame.
  void run(const Texture& contour_darkness, bool has_contours, const ComposeInputs& in, const ComposeParams& p,
           Texture& out, const PixelRect& inside);
  // The same, drawing the contours (Lee et al. 2006, §4.2-4.3) in this pass rather than reading them: a
  // frame writes and reads no D_c target. `contour_darkness`, if given, receives D_c
  // inside `inside` (a dump).
  void run(const ContourSources& contours, const ComposeInputs& in, const ComposeParams& p, Texture& out,
           const PixelRect& inside, Texture* contour_darkness);

 private:
  // compose.frag with the contours drawn in it or not, and D_c written out or not.
  const Program& program(bool draws_contours, bool writes_contours, bool has_contours, const ComposeInputs& in,
                         const ComposeParams& p);
  // Puts the blank page (drawn once per size and paper) in place in `out`.
  void copy_blank_page(const ComposeInputs& in, const ComposeParams& p, Texture& out);
  ProgramVariants programs_;
  FullscreenPass pass_;
  Texture page_;
  GLuint page_paper_ = 0;  // the paper texture page_ was drawn with, 0 for none
};

}  // namespace plumbago::gpu

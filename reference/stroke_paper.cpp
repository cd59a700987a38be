// The paper effect of stroke-based rendering, CPU reference (SPEC 4.2; formula in
// common/stroke_paper.hpp).
#include "common/stroke_paper.hpp"

#include "common/preprocess.hpp"
#include "reference/rows.hpp"
#include "reference/stage.hpp"

namespace plumbago::reference {

namespace {

// The coat onto the white page, each pixel through the paper texel under it.
Image page_with(const Image& coat, const Image& height, const StrokePaperParams& p) {
  Image out(coat.width, coat.height, 3);
  for_each_row(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      glm::vec4 layer(coat.at(x, y, 0), coat.at(x, y, 1), coat.at(x, y, 2), coat.at(x, y, 3));
      glm::vec3 c = over_paper(layer, glm::vec3(1.0f), height.at(x % height.width, y % height.height), p);
      for (int ch = 0; ch < 3; ++ch) out.at(x, y, ch) = c[ch];
    }
  });
  return out;
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(stroke_paper, [](ReferenceFrame& f) {
  f.put("stroke_paper.color", page_with(f.image("basecoat.coat"), f.pre.paper.height, f.params<StrokePaperParams>()));
});

}  // namespace plumbago::reference

// The paper effect of stroke-based rendering, CPU reference (Kalnins et al. 2002, §4.4; formula in
// common/strokes/stroke_paper.hpp).
#include "common/strokes/stroke_paper.hpp"

#include "common/core/preprocess.hpp"
#include "reference/core/stage.hpp"
#include "reference/util/rows.hpp"

namespace plumbago::reference {

namespace {

struct PageInputs {
  const GBuffer& gbuffer;
  std::vector<uint32_t> strokes;  // per G-buffer object
  const Image* coat;              // null without the base coat
  const Image& height;
  const Image* under;   // what the other pipelines drew; null: white
  const Image* sprite;  // the sketchy sprite's depth (1 where it drew nothing); null: none
};

// Whether the stroke pipeline owns the pixel: a stroke object with no sprite before it.
bool stroke_pixel(const PageInputs& in, int x, int y) {
  uint32_t object = in.gbuffer.ids.at(x, y, 0);
  return object != 0 && in.strokes[object - 1] && (!in.sprite || in.sprite->at(x, y) >= 1.0f);
}

// The stroke objects' pixels: the coat onto the white page through the paper texel under
// it; the others keep what is under.
Image page_with(const PageInputs& in, const StrokePaperParams& p) {
  Image out(in.gbuffer.ids.width, in.gbuffer.ids.height, 3);
  for_each_row(out.height, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      glm::vec3 c(1.0f);
      if (stroke_pixel(in, x, y)) {
        glm::vec4 layer =
            in.coat ? glm::vec4(in.coat->at(x, y, 0), in.coat->at(x, y, 1), in.coat->at(x, y, 2), in.coat->at(x, y, 3))
                    : glm::vec4(0.0f);
        c = over_paper(layer, glm::vec3(1.0f), in.height.at(x % in.height.width, y % in.height.height), p);
      } else if (in.under) {
        c = {in.under->at(x, y, 0), in.under->at(x, y, 1), in.under->at(x, y, 2)};
      }
      for (int ch = 0; ch < 3; ++ch) out.at(x, y, ch) = c[ch];
    }
  });
  return out;
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(stroke_paper, [](ReferenceFrame& f) {
  const Image* under = f.get(maybe(kSketchColor));
  PageInputs in{f.get(kGBuffer),
                stroke_object_flags(f.ordinary),
                f.get(maybe(kCoat)),
                f.get(kPaperHeight),
                under ? under : f.get(maybe(kComposeColor)),
                f.get(maybe(kSketchDepth))};
  f.put(kPage, page_with(in, f.params<StrokePaperParams>()));
});

}  // namespace plumbago::reference

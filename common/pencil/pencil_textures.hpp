// Pencil textures (Lee §5.1, Eq. 3-4): a stack of tileable grayscale layers
// (1 = white paper), layer 0 white, each layer the previous one plus strokes until its
// mean intensity reaches a tone uniformly spaced from 1 down to `darkest`.
// A stroke updates texel c_t with stroke color c_s (1 = no graphite):
//   c_a = c_t (1 - c_s);  if c_t > white_level: c_a = mu_w c_a;  c_t' = c_t - mu_b c_a
// A stroke is a thin, slightly bent line placed uniformly on the wrapping tile, nearly
// horizontal: a flat core with soft edges, tapered ends, pressure varying along it,
// streaks from the lead's fibres, and a few texels of paper tooth it skips.
#pragma once

#include "common/core/stage.hpp"
#include "common/scene/scene.hpp"

#include <cstdint>
#include <vector>

#include "common/util/image.hpp"

namespace plumbago {

struct PencilTexturesParams {
  static constexpr const char* stage = "pencil_textures";
  int layers, size;
  float mu_b, mu_w, white_level, darkest, angle_jitter_deg;
  float stroke_length, stroke_width, stroke_bend, grain, fibre_length, fibre_width, tooth;
  template <class V>
  void visit(V& v) {
    v.integer(layers, "layers", 32, 2, 256, "layers in the tone stack, white included (Lee: 32)");
    v.integer(size, "size", 256, 16, 4096, "width and height of each tileable layer, texels");
    v.real(mu_b, "mu_b", 0.2, 0.0, 1.0, "mu_b of Eq. 3: darkness a stroke adds (paper: 0.1-0.3)");
    v.real(mu_w, "mu_w", 0.4, 0.0, 1.0, "mu_w of Eq. 4: white preservation (paper: 0.3-0.5; 1 = off)");
    v.real(white_level, "white_level", 0.9, 0.0, 1.0, "texels brighter than this count as white for Eq. 4");
    v.real(darkest, "darkest", 0.15, 0.0, 0.95, "mean intensity of the darkest layer");
    v.real(angle_jitter_deg, "angle_jitter_deg", 8, 0, 90, "strokes run horizontally, turned by up to this angle");
    v.real(stroke_length, "stroke_length", 0.45, 0.02, 2.0, "stroke length as a share of the tile size");
    v.real(stroke_width, "stroke_width", 2.0, 0.5, 16.0, "width of a stroke's graphite core, texels");
    v.real(stroke_bend, "stroke_bend", 0.02, 0.0, 0.2, "largest sideways bend of a stroke, share of its length");
    v.real(grain, "grain", 0.6, 0.0, 1.0, "how much the lead's fibres break a stroke into streaks");
    v.real(fibre_length, "fibre_length", 20.0, 0.5, 256.0, "length over which a fibre streak changes, texels");
    v.real(fibre_width, "fibre_width", 0.8, 0.1, 16.0, "width over which the fibre streaks change, texels");
    v.real(tooth, "tooth", 0.25, 0.0, 1.0, "paper tooth: how much graphite the few deepest texels miss");
  }
};

// Layers 0..last (all when last < 0) of the stack: size x size, 1 channel, intensity
// (1 = white). The layers are made in order from one stream of strokes, so a prefix is
// the same as the start of the whole stack.
std::vector<Image> pencil_layers(const PencilTexturesParams& p, uint32_t seed, int last = -1);

// One stroke's effect on texel c_t with stroke color c_s (Eq. 3-4).
float graphite_update(const PencilTexturesParams& p, float c_t, float c_s);

// Mean intensity layer l aims for: 1 - l / (layers - 1) (1 - darkest).
float layer_target(const PencilTexturesParams& p, int layer);

struct Preprocessed;
inline constexpr Slot<std::vector<Image>> kPencilStack{"pencil_textures.stack"};  // white first

struct PencilTexturesStage {
  using Params = TypeList<PencilTexturesParams>;
  static void make(const Scene& scene, Preprocessed& out);
  static StageDesc describe() {
    return {.name = "pencil_textures",
            .kind = StageKind::Preprocessing,
            .doc = "the pencil tone stack (Lee et al. 2006, §5.1, Eq. 3-4)",
            .params = {"pencil_textures"},
            .outputs = {{.handle = kPencilStack, .texel = Texel::Host, .doc = "the layers, white first"}},
            .preprocess = make};
  }
};

}  // namespace plumbago

// The GL-exact sampler (reference/util/sampler.cpp): known answers on hand-made images, and
// the GPU's own texture() on the same texels and coordinates.
#include <gtest/gtest.h>

#include "common/util/image_compare.hpp"
#include "common/util/random.hpp"
#include "gpu/gl/framebuffer.hpp"
#include "reference/util/sampler.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago::reference {
namespace {

Image ramp(int w, int h) {  // texel (x, y) = x + 10 y
  Image img(w, h, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = float(x + 10 * y);
  return img;
}

TEST(Sampler, TexelCentersReturnTexelsExactly) {
  Image img = ramp(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_FLOAT_EQ(sample(img, {(x + 0.5f) / 4, (y + 0.5f) / 3}, {}).x, float(x + 10 * y));
}

TEST(Sampler, BilinearAveragesBetweenCenters) {
  Image img = ramp(4, 3);
  EXPECT_FLOAT_EQ(sample(img, {2.0f / 4, 1.5f / 3}, {}).x, 11.5f);   // halfway between x=1 and 2
  EXPECT_FLOAT_EQ(sample(img, {2.0f / 4, 2.0f / 3}, {}).x, 16.5f);   // and between y=1 and 2
  EXPECT_FLOAT_EQ(sample(img, {1.25f / 4, 0.5f / 3}, {}).x, 0.75f);  // quarter of the way
}

TEST(Sampler, RepeatWrapsAcrossTheEdgeAndClampHoldsTheEdge) {
  Image img = ramp(4, 1);
  SamplerState repeat{Filter::Linear, Wrap::Repeat, Wrap::Repeat};
  EXPECT_FLOAT_EQ(sample(img, {0.0f, 0.5f}, repeat).x, 1.5f);  // between texel 3 and texel 0
  EXPECT_FLOAT_EQ(sample(img, {-0.75f + 0.125f, 0.5f}, repeat).x, 1.0f);
  EXPECT_FLOAT_EQ(sample(img, {0.0f, 0.5f}, {}).x, 0.0f);  // clamp: edge texel only
  EXPECT_FLOAT_EQ(sample(img, {7.0f, 0.5f}, {}).x, 3.0f);
}

TEST(Sampler, NearestPicksTheTexelContainingTheCoordinate) {
  Image img = ramp(4, 1);
  SamplerState nearest{Filter::Nearest, Wrap::Repeat, Wrap::Repeat};
  EXPECT_FLOAT_EQ(sample(img, {0.2499f, 0.5f}, nearest).x, 0.0f);
  EXPECT_FLOAT_EQ(sample(img, {0.25f, 0.5f}, nearest).x, 1.0f);
  EXPECT_FLOAT_EQ(sample(img, {-0.01f, 0.5f}, nearest).x, 3.0f);
}

TEST(Sampler, NearestAtTheUpperEdgeClampsOrWraps) {
  Image img = ramp(4, 1);
  SamplerState clamp{Filter::Nearest};
  SamplerState repeat{Filter::Nearest, Wrap::Repeat, Wrap::Repeat};
  EXPECT_FLOAT_EQ(sample(img, {1.0f, 0.5f}, clamp).x, 3.0f);   // u = 4 is past the last texel
  EXPECT_FLOAT_EQ(sample(img, {1.0f, 0.5f}, repeat).x, 0.0f);  // and wraps to the first
}

TEST(Sampler, NegativeCoordinatesRepeatWholePeriodsAndClampToTheFirstTexel) {
  Image img = ramp(4, 3);
  SamplerState repeat{Filter::Linear, Wrap::Repeat, Wrap::Repeat};
  // s = 1.25 / 4 and s - 3 land on the same point of the tile: u = 0.75 and -11.25.
  EXPECT_FLOAT_EQ(sample(img, {0.3125f - 3.0f, 0.5f / 3 - 2.0f}, repeat).x, 0.75f);
  EXPECT_FLOAT_EQ(sample(img, {0.3125f, 0.5f / 3}, repeat).x, 0.75f);
  EXPECT_FLOAT_EQ(sample(img, {-0.3f, -0.2f}, {}).x, 0.0f);
  EXPECT_FLOAT_EQ(sample(img, {-0.3f, 1.5f / 3}, {}).x, 10.0f);  // s clamped to column 0; t at row 1
}

TEST(Sampler, FetchReadsTexelsAndClampsOutsideTheImage) {
  Image img = ramp(4, 3);
  EXPECT_EQ(fetch(img, {2, 1}).x, 12.0f);
  EXPECT_EQ(fetch(img, {-5, 1}).x, 10.0f);
  EXPECT_EQ(fetch(img, {9, 7}).x, 23.0f);
  EXPECT_EQ(fetch(img, {0, 0}), glm::vec4(0, 0, 0, 1));  // missing channels read 0, alpha 1
}

TEST(Sampler, TrilinearBlendsNeighboringLayersAndClampsInR) {
  std::vector<Image> layers = {Image(2, 2, 1, 0.0f), Image(2, 2, 1, 1.0f), Image(2, 2, 1, 3.0f)};
  SamplerState s{Filter::Linear, Wrap::Repeat, Wrap::Repeat, Wrap::ClampToEdge};
  EXPECT_FLOAT_EQ(sample(layers, {0.3f, 0.7f, 1.5f / 3}, s).x, 1.0f);
  EXPECT_FLOAT_EQ(sample(layers, {0.3f, 0.7f, 2.0f / 3}, s).x, 2.0f);
  EXPECT_FLOAT_EQ(sample(layers, {0.3f, 0.7f, 1.2f}, s).x, 3.0f);
  EXPECT_FLOAT_EQ(sample(layers, {0.3f, 0.7f, -1.0f}, s).x, 0.0f);
}

TEST(Sampler, WeightQuantizationRoundsAlphaDown) {
  Image img = ramp(2, 1);
  SamplerState s{Filter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge, Wrap::ClampToEdge, 2};
  EXPECT_FLOAT_EQ(sample(img, {(0.5f + 0.3f) / 2, 0.5f}, s).x, 0.25f);  // alpha 0.3 -> 0.25
}

// The GPU samples a random texture at off-grid coordinates (outside [0,1] too); the
// reference samples the same texels at the same coordinates.
class SamplerVsGpu : public plumbago::testing::GlTest {
 protected:
  Image random_image(int w, int h, const char* name) {
    Rng rng(7, name);
    Image img(w, h, 4);
    for (float& v : img.data) v = float(rng.uniform());
    return img;
  }

  Image gpu_samples(const gpu::Texture& tex, bool is_3d, glm::vec2 scale, glm::vec2 offset, float r_scale,
                    float r_offset) {
    gpu::Program probe("util/fullscreen.vert", "util/sampler_probe.frag");
    GLuint p = probe.id();
    glProgramUniform1i(p, probe.uniform("use_3d"), is_3d);
    glProgramUniform2f(p, probe.uniform("scale"), scale.x, scale.y);
    glProgramUniform2f(p, probe.uniform("offset"), offset.x, offset.y);
    glProgramUniform1f(p, probe.uniform("r_scale"), r_scale);
    glProgramUniform1f(p, probe.uniform("r_offset"), r_offset);
    gpu::Texture out = gpu::make_texture(kW, kH, GL_RGBA32F);
    gpu::Texture other =
        is_3d ? gpu::make_texture(1, 1, GL_RGBA32F) : gpu::upload_texture_3d({Image(1, 1, 4)}, GL_RGBA32F);
    gpu::FullscreenPass().draw(probe, {{is_3d ? "image3d" : "image2d", &tex}, {is_3d ? "image2d" : "image3d", &other}},
                               out);
    return gpu::download_texture(out, 4);
  }

  // Best of exact and 8-bit weights; prints both so the GPU's filter precision is on record.
  void expect_match(const Image& gpu_img, const std::function<glm::vec4(const SamplerState&, glm::vec2, float)>& ref,
                    const std::string& label) {
    double best = 1e9;
    for (int bits : {0, 8}) {
      Image r(kW, kH, 4);
      SamplerState s;
      s.weight_bits = bits;
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
          glm::vec4 v = ref(s, glm::vec2(x + 0.5f, y + 0.5f), float(x + y + 1));
          for (int c = 0; c < 4; ++c) r.at(x, y, c) = v[c];
        }
      ImageDiff d = compare_images(r, gpu_img, 1e-5);
      std::printf("[sampler %s, weight bits %d] %s\n", label.c_str(), bits, format_diff("texture()", d).c_str());
      best = std::min(best, d.max_abs);
    }
    // llvmpipe filters float textures with float weights: measured max 1.2e-6 with exact
    // weights (0.0035 with 8-bit ones). Hardware quantizes the weight (8 bits on NVIDIA):
    // one step times the largest texel difference (1) is the bound either way.
    EXPECT_LT(best, 1.0 / 256 + 1e-5) << label;
  }

  static constexpr int kW = 64, kH = 48;
};

TEST_F(SamplerVsGpu, Bilinear2DRepeatAndClamp) {
  Image img = random_image(13, 7, "sampler-2d");
  gpu::Texture tex = gpu::upload_texture(img, GL_RGBA32F);
  glm::vec2 scale(0.0371f, 0.0519f), offset(-0.61f, -0.33f);
  for (auto [mode, name] : {std::pair{GL_REPEAT, "repeat"}, std::pair{GL_CLAMP_TO_EDGE, "clamp"}}) {
    gpu::set_sampling(tex, GL_LINEAR, mode, mode);
    Wrap wrap = mode == GL_REPEAT ? Wrap::Repeat : Wrap::ClampToEdge;
    Image g = gpu_samples(tex, false, scale, offset, 0, 0);
    expect_match(
        g,
        [&](SamplerState s, glm::vec2 frag, float) {
          s.wrap_s = s.wrap_t = wrap;
          return sample(img, frag * scale + offset, s);
        },
        name);
  }
}

TEST_F(SamplerVsGpu, Trilinear3DAsThePencilStackIsSampled) {
  std::vector<Image> layers;
  for (int l = 0; l < 5; ++l) layers.push_back(random_image(9, 11, ("sampler-3d-" + std::to_string(l)).c_str()));
  gpu::Texture tex = gpu::upload_texture_3d(layers, GL_RGBA32F);
  glm::vec2 scale(0.0431f, 0.0277f), offset(-0.2f, 0.4f);
  float r_scale = 0.0113f, r_offset = -0.05f;
  Image g = gpu_samples(tex, true, scale, offset, r_scale, r_offset);
  expect_match(
      g,
      [&](SamplerState s, glm::vec2 frag, float) {
        s.wrap_s = s.wrap_t = Wrap::Repeat;
        return sample(layers, glm::vec3(frag * scale + offset, (frag.x + frag.y) * r_scale + r_offset), s);
      },
      "3d");
}

}  // namespace
}  // namespace plumbago::reference

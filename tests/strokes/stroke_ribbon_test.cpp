// The GPU's ribbon corners (shaders/strokes/common_ribbon.glsl, in float) against the
// reference's (common/strokes/base_stroke.hpp 6., in double), corner by corner, on the hard
// cases of a ribbon: taper, halo, closed loops drawn whole and split by pen lifts, offsets
// that zigzag faster than the sample spacing, repeated samples, an exact hairpin, a piece with
// no direction, a one-sample run, coordinates far from the origin. The same samples feed both
// (gpu/strokes/stroke.hpp SampleRecord), so (u, v), alpha and which segments draw must agree
// exactly, and each corner within the float rounding bound derived below. The samples are
// given here (some of them by hand: no base stroke makes repeats or hairpins), not made by
// the GPU (tests/strokes/stroke_samples_test.cpp checks those).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/strokes/stroke.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/strokes/stroke.hpp"
#include "tests/support/stroke_cases.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

constexpr double kUnitRoundoff = 0x1p-24;  // float's
constexpr double kDegenerate = 1e-9;       // px: as common/strokes/base_stroke.cpp

// The samples of every run that draws a ribbon (2 or more) as common_ribbon.glsl reads them, in
// SSBOs 0 (samples) and 1 (runs).
class RibbonBuffers {
 public:
  explicit RibbonBuffers(const std::vector<RunStroke>& strokes) {
    std::vector<gpu::SampleRecord> samples;
    std::vector<gpu::RunRecord> runs;
    for (const RunStroke& stroke : strokes) append(stroke, samples, runs);
    vertices_ = 6 * samples.size();
    runs_count_ = runs.size();
    if (samples.empty()) return;
    samples_ = gpu::make_buffer(samples.data(), samples.size() * sizeof(gpu::SampleRecord));
    runs_ = gpu::make_buffer(runs.data(), runs.size() * sizeof(gpu::RunRecord));
  }
  size_t vertices() const { return vertices_; }  // six a sample
  size_t runs() const { return runs_count_; }
  void bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, samples_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, runs_.id());
  }

 private:
  static void append(const RunStroke& stroke, std::vector<gpu::SampleRecord>& samples,
                     std::vector<gpu::RunRecord>& runs) {
    const std::vector<StrokeSample>& q = stroke.samples.samples;
    if (q.size() < 2) return;
    const StrokeStyle& style = stroke.style;
    bool whole = std::all_of(q.begin(), q.end() - 1, [](const StrokeSample& x) { return x.pen_down_after; });
    auto run = uint32_t(runs.size());
    runs.push_back({glm::vec4(style.color_r, style.color_g, style.color_b, float(int(style.texture))),
                    uint32_t(samples.size()), uint32_t(q.size()), stroke.samples.closed && whole});
    for (const StrokeSample& x : q)
      samples.push_back({glm::vec2(x.position), float(x.s / style.texture_period_px), float(x.width), float(x.alpha),
                         run, x.pen_down_after});
  }
  gpu::Buffer samples_, runs_;
  size_t vertices_ = 0, runs_count_ = 0;
};

// One corner as the GPU made it.
struct GpuCorner {
  glm::vec4 window_uv;    // x, y, u, v
  glm::vec4 alpha_drawn;  // alpha, drawn (0 or 1), run, 0
};

// Every corner of `strokes`' ribbons, six a sample, computed by common_ribbon.glsl's
// ribbon_corner in a compute shader over the buffers the stroke pass draws from, after its
// put_ribbon_normals over each run (which the stroke samples' step runs).
std::vector<GpuCorner> gpu_corners(const std::vector<RunStroke>& strokes) {
  RibbonBuffers buffers(strokes);
  std::string source = "#version 450 core\nlayout(local_size_x = 64) in;\n#define RIBBON_NORMALS\n" +
                       gpu::shader_source("strokes/common_ribbon.glsl") + R"(
struct Captured { vec4 window_uv; vec4 alpha_drawn; };
layout(std430, binding = 2) writeonly buffer Corners { Captured corners[]; };
uniform uint count;
uniform bool normals;  // put_ribbon_normals over the runs, else the corners
void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= count) return;
  if (normals) {
    put_ribbon_normals(k);
    return;
  }
  Corner c = ribbon_corner(int(k));
  corners[k] = Captured(vec4(c.window, c.uv), vec4(c.alpha, c.drawn ? 1.0 : 0.0, float(c.run), 0.0));
})";
  const char* text = source.c_str();
  GLuint program = glCreateShaderProgramv(GL_COMPUTE_SHADER, 1, &text);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  char log[4096] = {};
  glGetProgramInfoLog(program, sizeof log, nullptr, log);
  EXPECT_TRUE(linked && std::string(log).find_first_not_of(" \t\r\n") == std::string::npos) << log;
  auto count = size_t(buffers.vertices());
  std::vector<GpuCorner> out(count);
  if (count == 0) return out;
  gpu::Buffer corners = gpu::make_buffer(nullptr, count * sizeof(GpuCorner));
  buffers.bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, corners.id());
  glUseProgram(program);
  const GLint count_at = glGetUniformLocation(program, "count"), normals_at = glGetUniformLocation(program, "normals");
  glProgramUniform1ui(program, count_at, GLuint(buffers.runs()));
  glProgramUniform1i(program, normals_at, 1);
  glDispatchCompute(GLuint((buffers.runs() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glProgramUniform1ui(program, count_at, GLuint(count));
  glProgramUniform1i(program, normals_at, 0);
  glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gpu::read_buffer(corners, out.data(), count * sizeof(GpuCorner));
  glDeleteProgram(program);
  return out;
}

// The bound on one corner p + n w/2 of sample p (window px), from its inputs rounded to float:
//   p carries at most u C per coordinate (C its largest coordinate magnitude, u = 2^-24);
//   a segment of length l, the difference of two such points, turns by at most 2 sqrt(2) u C / l;
//   the normalized sum of two unit normals at an angle theta to each other (|sum| = 2 c,
//   c = cos(theta / 2)) turns by at most the sum of their turns over 2 c;
//   so the corner moves by at most sqrt(2) u C (1 + w / (l c)), and the float operations add a
//   few u (C + w) more. With l the shorter of the segments whose normals meet at p and c = 1
//   where one normal stands alone, the bound taken is twice the first-order sum:
//     2 u C (4 + w / (l c)).
double corner_bound(double coordinate, double width, double shortest, double c) {
  return 2 * kUnitRoundoff * coordinate * (4 + width / (shortest * c));
}

// For each sample of `q` (one run's reference samples), the shortest segment whose normal
// reaches it and c of the bound above, following base_stroke.cpp's rules: a degenerate segment
// takes the nearest nondegenerate one of its piece, before it if any, else after.
struct Conditioning {
  double shortest, c;
};
std::vector<Conditioning> conditioning(const std::vector<StrokeSample>& q, bool cyclic) {
  size_t m = q.size();
  auto drawn = [&](size_t k) { return k + 1 < m && q[k].pen_down_after; };
  auto length = [&](size_t k) { return glm::distance(q[k + 1].position, q[k].position); };
  auto feeding = [&](size_t k) {  // the segment whose normal segment k takes
    for (size_t i = k + 1; i-- > 0 && drawn(i);)
      if (length(i) > kDegenerate) return i;
    for (size_t i = k + 1; drawn(i); ++i)
      if (length(i) > kDegenerate) return i;
    return k;
  };
  auto normal = [&](size_t k) {
    glm::dvec2 d = q[k + 1].position - q[k].position;
    return glm::dvec2(-d.y, d.x) / glm::length(d);
  };
  std::vector<Conditioning> out(m, {std::numeric_limits<double>::infinity(), 1.0});
  for (size_t i = 0; i < m; ++i) {
    bool has_prev = (i > 0 && drawn(i - 1)) || (cyclic && i == 0), has_next = drawn(i) || (cyclic && i + 1 == m);
    std::vector<size_t> sides;
    if (has_prev) sides.push_back(feeding(i > 0 ? i - 1 : m - 2));
    if (has_next) sides.push_back(feeding(i + 1 < m ? i : 0));
    for (size_t k : sides)
      if (length(k) > kDegenerate) out[i].shortest = std::min(out[i].shortest, length(k));
    if (sides.size() == 2 && length(sides[0]) > kDegenerate && length(sides[1]) > kDegenerate) {
      double sum = glm::length(normal(sides[0]) + normal(sides[1]));
      if (sum > kDegenerate) out[i].c = sum / 2;  // else a hairpin: the previous normal alone
    }
  }
  return out;
}

StrokeStyle style(double width) { return testing::style_of_width(width); }

RunStroke from_run(const StrokeRun& run, const StrokeStyle& s) { return {s, base_stroke_samples(run, s)}; }

// Samples given by hand, every segment drawn unless `lifts` names it.
RunStroke from_samples(const std::vector<glm::dvec2>& p, bool closed, double width, std::vector<size_t> lifts = {}) {
  RunStroke out{style(width), {{}, 0.0, closed}};
  for (size_t j = 0; j < p.size(); ++j) {
    bool down = j + 1 < p.size() && std::find(lifts.begin(), lifts.end(), j) == lifts.end();
    out.samples.samples.push_back({p[j], p[j], 10.0 * double(j), 10.0 * double(j), width, 0.8, down});
  }
  return out;
}

using testing::arc;

std::vector<RunStroke> hard_cases() {
  std::vector<RunStroke> out;
  StrokeStyle tapered = style(9);
  tapered.taper_px = 30;
  tapered.halo_px = 15;
  tapered.fade_px = 10;
  std::vector<glm::dvec2> wave;
  for (int i = 0; i <= 40; ++i) wave.push_back({20.0 + 8 * i, 300 + 40 * std::sin(i * 0.4)});
  out.push_back(from_run({wave, false, true, false}, tapered));           // open, tapered, haloed at its start
  out.push_back(from_run({arc({200, 200}, 60, 36, 1), true}, style(6)));  // closed, drawn whole
  StrokeStyle lifted = style(5);
  lifted.offsets = OffsetExample{70, {{0, 0, 1, false}, {0.4, 2, 0.7, true}, {0.6, -1, 1, false}}};
  out.push_back(from_run({arc({420, 180}, 50, 30, 1), true}, lifted));  // closed, split by pen lifts
  StrokeStyle zigzag = style(1.5);                                      // thin: drawn 2 px wide
  zigzag.sample_px = 2;
  zigzag.offsets = OffsetExample{5, {{0, 1.5, 1, false}, {0.5, -1.5, 1, false}}};
  out.push_back(from_run({{{30, 500}, {300, 520}, {560, 480}}, false}, zigzag));  // faster than the spacing
  out.push_back(from_samples({{100, 100}, {110, 100}, {110, 100}, {110, 100}, {120, 105}}, false, 4));  // repeats
  out.push_back(from_samples({{300, 60}, {350, 60}, {300, 60}}, false, 6));                             // exact hairpin
  out.push_back(from_samples({{50, 50}, {50, 50}, {50, 50}}, false, 3));                                // no direction
  out.push_back(from_samples({{500, 500}, {540, 500}, {540, 540}, {500, 540}, {500, 500}}, true, 5));   // square
  out.push_back(from_samples({{60, 60}}, false, 3));                                                    // one sample
  out.push_back(from_samples({{10, 10}, {20, 12}, {30, 10}, {40, 14}}, false, 4, {1}));  // a lift between
  out.push_back(from_run({arc({3800, 2900}, 25, 20, 0.7), false}, style(7)));            // far from the origin
  return out;
}

// What a corner of the reference carries, beside its position.
bool same_attributes(const RibbonVertex& r, const GpuCorner& g) {
  return r.uv == glm::vec2(g.window_uv.z, g.window_uv.w) && r.alpha == g.alpha_drawn.x;
}

class StrokeRibbonParity : public testing::GlTest {};

TEST_F(StrokeRibbonParity, GpuCornersMatchTheReferenceWithinTheFloatBound) {
  std::vector<RunStroke> strokes = hard_cases();
  std::vector<GpuCorner> gpu = gpu_corners(strokes);
  size_t k = 0, drawn = 0;  // k: the GPU's corner, six a sample of every run with 2 or more
  double max_error = 0, max_ratio = 0;
  for (size_t r = 0; r < strokes.size(); ++r) {
    const std::vector<StrokeSample>& q = strokes[r].samples.samples;
    std::vector<RibbonVertex> ref = ribbon(strokes[r].samples, strokes[r].style).triangles;
    if (q.size() < 2) {
      EXPECT_TRUE(ref.empty()) << "run " << r;
      continue;
    }
    bool cyclic = strokes[r].samples.closed &&
                  std::all_of(q.begin(), q.end() - 1, [](const StrokeSample& x) { return x.pen_down_after; });
    std::vector<Conditioning> cond = conditioning(q, cyclic);
    size_t next = 0;  // the reference's corner
    for (size_t j = 0; j < q.size(); ++j)
      for (size_t corner = 0; corner < 6; ++corner, ++k) {
        const GpuCorner& g = gpu.at(k);
        if (g.alpha_drawn.y == 0) continue;
        ++drawn;
        ASSERT_LT(next, ref.size()) << "run " << r << " sample " << j
                                    << ": the GPU draws a segment the reference does not";
        const RibbonVertex& v = ref[next++];
        size_t i = j + (corner == 2 || corner == 3 || corner == 5 ? 1 : 0);
        double coordinate = std::max(std::abs(q[i].position.x), std::abs(q[i].position.y)) + q[i].width;
        double bound = corner_bound(coordinate, q[i].width, cond[i].shortest, cond[i].c);
        double error = glm::distance(glm::dvec2(v.position), glm::dvec2(g.window_uv));
        EXPECT_LE(error, bound) << "run " << r << " sample " << j << " corner " << corner;
        EXPECT_TRUE(same_attributes(v, g)) << "run " << r << " sample " << j << " corner " << corner;
        max_error = std::max(max_error, error);
        max_ratio = std::max(max_ratio, error / bound);
      }
    EXPECT_EQ(next, ref.size()) << "run " << r << ": the reference draws segments the GPU does not";
  }
  EXPECT_EQ(k, gpu.size());
  EXPECT_GT(drawn, 1000u);
  std::printf("ribbon corners: %zu drawn of %zu, max error %.3g px, max error / bound %.3f\n", drawn, gpu.size(),
              max_error, max_ratio);
}

}  // namespace
}  // namespace plumbago

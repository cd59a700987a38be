// The stage descriptor (docs/design.md, principle 3, in the spirit of Falcor's reflect()): the
// one place that says what a stage is. Everything else follows from the descriptors:
//  - the pass table: what each effect runs, in which order (common/core/passes.hpp);
//  - the G-buffer channels a frame writes (the `gbuffer.*` buffers its stages read);
//  - the buffers `--dump-stages` writes and `compare` compares (the declared outputs);
//  - `render --stats` and `plumbago params` (names, docs, parameter structs).
//
// A stage is a type in common/<stem>.hpp with
//   using Params = TypeList<...>;   // the parameter structs it declares (common/core/params.hpp)
//   static StageDesc describe();    // its descriptor
// listed once in common/core/stage_registry.hpp. Each backend registers its implementation
// next to its own code (reference/<stem>.cpp, gpu/<stem>.cpp); a stage that one backend
// does not implement is an error when that backend starts. Preprocessing is made once on
// the CPU for both backends, so its implementation is in the descriptor itself.
//
//   struct EdgeDetectStage {
//     using Params = TypeList<EdgeDetectParams>;
//     static StageDesc describe() {
//       return {.name = "edge_detect", .kind = StageKind::Frame,
//               .doc = "contour darkness ... (Nienhaus & Döllner 2003)", .params = {"edge"},
//               .inputs = {{.handle = kGBuffer.normal, .used = smooth_normals}, {.handle = kGBuffer.depth}},
//               .outputs = {{.handle = kContourDarkness, .doc = "d", .tolerance = tolerance::kFloat}}};
//     }
//   };
//
// Inputs and outputs are typed handles (common/core/handle.hpp) whose printed names are
// "<stage>.<output>". An input is another stage's handle; reading it makes that stage run
// first (and only when the input's condition holds).
#pragma once

#include <string>
#include <vector>

#include "common/core/handle.hpp"
#include "common/core/params.hpp"

namespace plumbago {

struct Scene;
struct Preprocessed;

template <class... T>
struct TypeList {};

enum class StageKind { Preprocessing, Frame };

// How a buffer is kept on the GPU (the reference keeps floats): 32-bit float, 8-bit
// unsigned normalized, unsigned integer; Host: CPU data under a Slot (common/core/handle.hpp):
// what preprocessing makes (grids, stacks) and what a stage hands later ones (the window
// lines, the visible runs); neither dumped nor compared as an image.
enum class Texel { Float, Unorm8, Uint, Host };

// How parity compares an output. Stages fed identical inputs compare every pixel
// (`All`). A stage that rasterizes geometry (the reference traces rays) compares where
// both backends see the same thing: `Interior`, away from the one-pixel band along depth
// discontinuities (docs/conventions.md); `SameTriangle`, where both also hit the same triangle;
// `Covered`, where both cover the pixel and its 3x3 neighborhood (alpha of the output).
enum class ParityMask { All, Interior, SameTriangle, Covered };
// What is compared: the values, the normalized depth z of a linear depth (docs/conventions.md), or
// angles as (cos, sin) pairs so that -pi and pi agree.
enum class ParityValue { Plain, NormalizedDepth, Angles };

// docs/conventions.md tolerances that the descriptors state for their outputs.
namespace tolerance {
// A float stage fed identical inputs (measured ~1e-7).
constexpr double kFloat = 1e-4;
constexpr double kByte = 2.0 / 255.0;  // an 8-bit target
// A float stage that samples textures bilinearly: llvmpipe filters float textures with
// float weights (tests/util/sampler_test.cpp: 1.2e-6), but the texture coordinates themselves
// come out of slightly different float expressions; measured max 2e-5 on llvmpipe.
// Hardware with 8-bit filter weights would need about 1/256 (docs/conventions.md).
constexpr double kSampled = 1e-3;
// Raster vs ray (docs/conventions.md): normalized depth, unit normals.
constexpr double kDepth = 1e-4;
constexpr double kNormal = 1e-3;
// Barycentrics, raster vs ray: the rasterizer snaps vertices to 1/2^GL_SUBPIXEL_BITS of a
// pixel (8 bits on llvmpipe), which moves a pixel's barycentrics by about
// (1/256 px) / (the triangle's extent in px): 1e-3 for a 4 px triangle. Measured max on the
// Stanford bunny at 800x800 (many 2-5 px triangles): 1.08e-3. Allowed: 4e-3 (1 px triangles).
constexpr double kBary = 4e-3;
// Corner angles of Lee et al. 2006, §5.3: both backends evaluate the same float formula on the same
// world-space floats (GPU in the vertex shader); measured on llvmpipe: see the test.
constexpr double kAngle = 1e-3;
}  // namespace tolerance

// Conditions on what the scene asks for; null means always.
struct StageConfig {
  const ParamSet& params;
  const std::vector<std::string>& effects;
  bool has(const char* effect) const;
};
using Condition = bool (*)(const StageConfig&);

// The name a descriptor takes from a handle (common/core/handle.hpp): descriptors list
// handles, never spelled names.
struct HandleName {
  HandleName(Buffer b) : name(b.name) {}
  template <class T>
  HandleName(Slot<T> s) : name(s.name) {}
  const char* name;
};

// One output of a stage: its handle and how parity compares it.
struct Output {
  HandleName handle;  // "<stage>.<output>": the stage's own handle (the registry checks)
  int channels = 1;   // in a dump (a GPU target may hold more, e.g. depth in the normals' w)
  Texel texel = Texel::Float;
  std::string doc;
  double tolerance = 0;       // parity: the largest difference allowed at a compared pixel
  std::string tolerance_why;  // what was measured, or the bound it comes from
  ParityMask mask = ParityMask::All;
  ParityValue value = ParityValue::Plain;
  // The frame's color: the last stage that ran with such an output made the image.
  bool frame_color = false;
  // Drawn in place over another stage's output (the same GPU target): the first of these
  // whose stage ran (drawn_over below); a dump keeps the one drawn over only where this
  // stage did not run.
  std::vector<std::string> draws_over;
  // Written only when a condition holds (e.g. the corner angles need curvature).
  Condition written = nullptr;
  bool compared = true;  // false: not a parity output (the note in tolerance_why says why)

  std::string buffer() const { return handle.name; }
  std::string name() const { return buffer().substr(buffer().find('.') + 1); }  // after "<stage>."
  std::string producer() const { return buffer().substr(0, buffer().find('.')); }
};

// One input of a stage: another stage's handle, read where a condition holds.
struct Input {
  HandleName handle;
  Condition used = nullptr;  // read only where this holds (null: always)
  // Parity feeds both backends this input from the reference; false where the GPU reads
  // it in a form parity cannot upload (then both compute without it).
  bool fed_in_parity = true;

  std::string buffer() const { return handle.name; }  // "<stage>.<output>"
};

// An effect a scene can ask for ("effects" in a scene file), declared by the stage that
// introduces it.
struct EffectDef {
  std::string name;
  std::string doc;
  // Goes with the objects of a style (sketchy, strokes): a scene has it exactly when it
  // has such an object (common/scene/scene.cpp), so nothing adds it to another scene.
  bool styled = false;
};

// A stage's descriptor, written with designated initializers:
//   return {.name = "edge_detect", .kind = StageKind::Frame, .doc = "... (paper, section)",
//           .params = {"edge"}, .inputs = {{.handle = kGBuffer.depth}},
//           .outputs = {{.handle = kContourDarkness, .tolerance = tolerance::kFloat, ...}}};
struct StageDesc {
  std::string name;  // the stem: common/<subsystem>/<name>.hpp, reference/<subsystem>/<name>.cpp, ...
  StageKind kind = StageKind::Frame;
  std::string doc;                  // what it computes, then its paper, section and equation in parentheses
  std::vector<std::string> params;  // the prefixes of the parameter structs it reads
  std::vector<Input> inputs;
  std::vector<Output> outputs;
  std::vector<std::string> effects;         // effects that ask for it (what it reads runs too)
  std::vector<EffectDef> declared_effects;  // the effects it introduces
  // Preprocessing only (it reads only the scene, made once on the CPU for both backends):
  // the implementation, which puts its outputs' Slots into Preprocessed.
  void (*preprocess)(const Scene&, Preprocessed&) = nullptr;

  std::string output_name(const Output& o) const { return o.buffer(); }
};

// Every stage, in registry order (common/core/stage_registry.hpp), which is also the order they
// run in. Checked when first called: unique names and parameter prefixes, inputs that
// name an output of an earlier stage, known effects; throws std::logic_error otherwise.
const std::vector<StageDesc>& stage_table();
// Throws std::invalid_argument listing the known stages.
const StageDesc& find_stage(const std::string& name);
bool is_stage(const std::string& name);
// The stage and the output a buffer name "<stage>.<output>" refers to.
const StageDesc& stage_of(const std::string& buffer);
const Output& find_output(const std::string& buffer);
// The inputs of `stage` that `config` reads.
std::vector<std::string> inputs_read(const StageDesc& stage, const StageConfig& config);
// The outputs of `stage` that `config` writes.
std::vector<const Output*> outputs_written(const StageDesc& stage, const StageConfig& config);
std::string stage_names();  // "gbuffer, edge_detect, ..." for messages
// Throws std::logic_error unless one of `stages` declares `buffer` as an input or an output
// (a G-buffer's name: one of its channels). Frames check every read of a running stage.
void check_declared(const std::vector<std::string>& stages, const std::string& buffer);

// The buffers a dump of a frame that ran `stages` holds: every output the frame stages
// write, less those another stage that ran drew over in place.
std::vector<std::string> dumped_buffers(const std::vector<std::string>& stages, const StageConfig& config);
// The buffer `output` draws over in a frame that runs `stages`; empty when none.
std::string drawn_over(const Output& output, const std::vector<std::string>& stages);
// The buffer that holds the frame's color: the last frame_color output of `stages`.
std::string frame_color_buffer(const std::vector<std::string>& stages);

// Whether the effects say a buffer is in use; shared conditions of the descriptors.
namespace when {
bool effect_contours(const StageConfig& c);
bool effect_interior(const StageConfig& c);  // interior or crosshatch
bool effect_paper(const StageConfig& c);
bool pencil_effects(const StageConfig& c);  // any effect of the pencil pipeline
bool effect_sketchy(const StageConfig& c);
bool ordinary_drawn(const StageConfig& c);  // the G-buffer's objects are drawn (pencil or strokes)
bool effect_basecoat(const StageConfig& c);
}  // namespace when

}  // namespace plumbago

// libFuzzer target: svg_strokes, the SVG reader of `plumbago strokefile`, on the input as a
// drawing over an 800 x 600 window; style files named by a relative path resolve in an
// empty folder (presets load). An SvgError is a clean refusal; any other exception, a
// crash, a sanitizer report, a hang or runaway memory is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/strokes/svg_strokes.hpp"
#include "fuzz/empty_folder.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  plumbago::SvgStrokeDefaults defaults;
  defaults.style_dir = plumbago::fuzz::empty_folder();
  try {
    plumbago::svg_strokes(std::string(reinterpret_cast<const char*>(data), size), "fuzz.svg", 800, 600, defaults);
  } catch (const plumbago::SvgError&) {
  }
  return 0;
}

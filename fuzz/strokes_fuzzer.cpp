// libFuzzer target: the input read both as a stroke file (parse_stroke_file, its style
// files resolved in an empty folder; presets load) and as a stroke style
// (parse_stroke_style). A SceneError or a StrokeStyleError is a clean refusal; any other
// exception, a crash, a sanitizer report, a hang or runaway memory is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/scene/scene.hpp"
#include "common/strokes/stroke_file.hpp"
#include "fuzz/empty_folder.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    plumbago::parse_stroke_file(text, "fuzz.strokes.json", plumbago::fuzz::empty_folder(), glm::dvec3(0.0));
  } catch (const plumbago::SceneError&) {
  }
  try {
    plumbago::parse_stroke_style(text, "fuzz.style.json");
  } catch (const plumbago::StrokeStyleError&) {
  }
  return 0;
}

// Stroke styles (Kalnins et al. 2002, §4.1, §4.3): defaults, values and offsets read from JSON, every refusal
// naming the file and the key, the presets and where they are found.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "common/strokes/stroke_style.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

// The message of the StrokeStyleError that parsing `json` throws ("" when none).
std::string refusal(const std::string& json, const std::string& source = "x.json") {
  try {
    parse_stroke_style(json, source);
  } catch (const StrokeStyleError& e) {
    return e.what();
  }
  return "";
}

// Sets an environment variable for the life of the object, then restores it.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(StrokeStyle, DefaultsAreTheBriefs) {
  StrokeStyle s = default_stroke_style();
  EXPECT_EQ(s.width_px, 4.0f);
  EXPECT_EQ(s.taper_px, 24.0f);
  EXPECT_EQ(s.fade_px, 0.0f);
  EXPECT_EQ(s.halo_px, 6.0f);
  EXPECT_EQ(s.flare, 0.0f);
  EXPECT_EQ(s.alpha, 1.0f);
  EXPECT_EQ(s.color_r, 0.1f);
  EXPECT_EQ(s.color_g, 0.1f);
  EXPECT_EQ(s.color_b, 0.1f);
  EXPECT_EQ(s.texture, StrokeTextureKind::Pencil);
  EXPECT_EQ(s.texture_period_px, 64.0f);
  EXPECT_EQ(s.sample_px, 3.5f);
  EXPECT_TRUE(s.pressure_width);
  EXPECT_FALSE(s.pressure_alpha);
  EXPECT_EQ(s.synthesis, OffsetSynthesis::Stamp);
  EXPECT_FALSE(s.offsets.has_value());
}

// stroke_style_specs() comes from the same visit(): every default lies in its range, and
// an empty document gives exactly the defaults.
TEST(StrokeStyle, SpecsAndEmptyDocumentAgreeWithTheDefaults) {
  auto specs = stroke_style_specs();
  ASSERT_EQ(specs.size(), 15u);
  EXPECT_EQ(specs[0].key, "width_px");
  EXPECT_EQ(specs[0].min, 0.1);
  EXPECT_EQ(specs[0].max, 200.0);
  for (const ParamSpec& spec : specs) {
    EXPECT_GE(spec.default_value, spec.min) << spec.key;
    EXPECT_LE(spec.default_value, spec.max) << spec.key;
    EXPECT_FALSE(spec.doc.empty()) << spec.key;
  }
  StrokeStyle parsed = parse_stroke_style("{}", "empty.json"), defaults = default_stroke_style();
  EXPECT_EQ(parsed.width_px, defaults.width_px);
  EXPECT_EQ(parsed.halo_px, defaults.halo_px);
  EXPECT_EQ(parsed.texture, defaults.texture);
  EXPECT_NO_THROW(validate_stroke_style(defaults, "defaults"));
}

TEST(StrokeStyle, ReadsEveryKindOfValueAndTheOffsets) {
  StrokeStyle s = parse_stroke_style(R"({
    "description": "test", "width_px": 10, "flare": -0.5, "texture": "charcoal", "pressure_alpha": true,
    "offsets": {"length_px": 80, "points": [[0, 1.5, 0.5, false], [0.5, -2, 1, true], [0.5, 0, 1, false]]}
  })",
                                     "t.json");
  EXPECT_EQ(s.description, "test");
  EXPECT_EQ(s.width_px, 10.0f);
  EXPECT_EQ(s.flare, -0.5f);
  EXPECT_EQ(s.texture, StrokeTextureKind::Charcoal);
  EXPECT_TRUE(s.pressure_alpha);
  EXPECT_EQ(s.taper_px, 24.0f);  // left out: the default
  ASSERT_TRUE(s.offsets.has_value());
  EXPECT_EQ(s.offsets->length_px, 80.0);
  ASSERT_EQ(s.offsets->offsets.size(), 3u);
  EXPECT_EQ(s.offsets->offsets[0].displacement_px, 1.5);
  EXPECT_EQ(s.offsets->offsets[0].pressure, 0.5);
  EXPECT_TRUE(s.offsets->offsets[1].pen_up);
  EXPECT_EQ(s.offsets->offsets[1].t, 0.5);
  EXPECT_NO_THROW(validate_stroke_style(s, "t.json"));
}

TEST(StrokeStyle, RefusalsNameTheFileAndTheKey) {
  EXPECT_EQ(refusal(R"({"width_px": 500})", "styles/strokes/x.json"),
            "styles/strokes/x.json: /width_px: must be in [0.1, 200], got 500");
  EXPECT_EQ(refusal(R"({"width_px": "wide"})"), "x.json: /width_px: expected a number, got string");
  EXPECT_EQ(refusal(R"({"pressure_width": 1})"), "x.json: /pressure_width: expected true or false, got number");
  EXPECT_EQ(refusal(R"({"texture": "crayon"})"),
            "x.json: /texture: expected one of pencil, charcoal, ink, got \"crayon\"");
  EXPECT_EQ(refusal(R"({"description": 3})"), "x.json: /description: expected a string");
  EXPECT_EQ(refusal(R"([1, 2])"), "x.json: /: expected an object");
  std::string unknown = refusal(R"({"widht_px": 3})");
  EXPECT_EQ(unknown.rfind("x.json: /widht_px: unknown key (known: width_px, taper_px", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("offsets"), std::string::npos) << unknown;
}

TEST(StrokeStyle, RefusesBadOffsets) {
  auto offsets = [](const std::string& body) { return refusal(R"({"offsets": )" + body + "}"); };
  EXPECT_EQ(offsets(R"({"length_px": 50, "points": [[0.5, 0, 1, false], [0.25, 0, 1, false]]})"),
            "x.json: /offsets/points/1/0: t must not decrease (0.25 after 0.5)");
  EXPECT_EQ(offsets(R"({"length_px": 50, "points": [[1.5, 0, 1, false]]})"),
            "x.json: /offsets/points/0/0: must be in [0, 1], got 1.5");
  EXPECT_EQ(offsets(R"({"length_px": 50, "points": [[0, 0, 2, false]]})"),
            "x.json: /offsets/points/0/2: must be in [0, 1], got 2");
  EXPECT_EQ(offsets(R"({"length_px": 50, "points": [[0, 0, 1]]})"),
            "x.json: /offsets/points/0: expected [t, displacement_px, pressure, break]");
  EXPECT_EQ(offsets(R"({"length_px": 50, "points": [[0, 0, 1, 0]]})"),
            "x.json: /offsets/points/0/3: expected true or false, got number");
  EXPECT_EQ(offsets(R"({"length_px": 50, "points": []})"), "x.json: /offsets/points: expected at least one offset");
  EXPECT_EQ(offsets(R"({"points": [[0, 0, 1, false]]})"),
            "x.json: /offsets/length_px: missing (the example's length when drawn, px)");
  EXPECT_EQ(offsets(R"({"length_px": 0, "points": [[0, 0, 1, false]]})"),
            "x.json: /offsets/length_px: must be in [1, 100000], got 0");
  EXPECT_EQ(offsets(R"({"length_px": 5, "points": [], "period": 3})"),
            "x.json: /offsets/period: unknown key (known here: length_px, points)");
}

TEST(StrokeStyle, RefusesMalformedJsonWithLineAndColumn) {
  std::string bad = refusal("{\n  \"width_px\": 4,\n}");
  EXPECT_EQ(bad.rfind("x.json: line 3, column 1: not valid JSON", 0), 0u) << bad;
  std::string overflow = refusal(R"({"width_px": 1e999})");
  EXPECT_EQ(overflow.rfind("x.json: line 1, column 18: cannot read the JSON", 0), 0u) << overflow;
}

// NaN cannot be written in JSON; a style built in code can hold one, and the same ranges refuse it.
TEST(StrokeStyle, ValidationRefusesNaNAndOutOfRangeValuesFromCode) {
  StrokeStyle s = default_stroke_style();
  s.halo_px = std::nanf("");
  try {
    validate_stroke_style(s, "code");
    ADD_FAILURE() << "NaN accepted";
  } catch (const StrokeStyleError& e) {
    EXPECT_STREQ(e.what(), "code: /halo_px: must be a finite number, got nan");
  }
  s = default_stroke_style();
  s.sample_px = 0;
  EXPECT_THROW(validate_stroke_style(s, "code"), StrokeStyleError);
  s = default_stroke_style();
  s.offsets = OffsetExample{20, {{0.5, 0, 1, false}, {0.2, 0, 1, false}}};
  EXPECT_THROW(validate_stroke_style(s, "code"), StrokeStyleError);
  s.offsets = OffsetExample{20, {}};
  EXPECT_THROW(validate_stroke_style(s, "code"), StrokeStyleError);
}

TEST(StrokeStyle, PresetsLoadByName) {
  EXPECT_EQ(stroke_style_names(),
            (std::vector<std::string>{"charcoal", "ink", "pencil", "sketchy_pencil", "toon_silhouette"}));
  for (const std::string& name : stroke_style_names()) EXPECT_NO_THROW(load_stroke_style(name)) << name;
  EXPECT_EQ(load_stroke_style("charcoal").texture, StrokeTextureKind::Charcoal);
  EXPECT_EQ(load_stroke_style("ink").texture, StrokeTextureKind::Ink);
  StrokeStyle pencil = load_stroke_style("pencil");
  EXPECT_EQ(pencil.texture, StrokeTextureKind::Pencil);
  EXPECT_TRUE(pencil.offsets.has_value());
  StrokeStyle sketchy = load_stroke_style("sketchy_pencil");  // offsets synthesized (Kalnins et al. 2002,
                                                              // App. A)
  EXPECT_EQ(sketchy.synthesis, OffsetSynthesis::Markov);
  EXPECT_TRUE(sketchy.offsets.has_value());
  StrokeStyle toon = load_stroke_style("toon_silhouette");  // Kalnins Fig. 1/3: wide, dark, small halo
  EXPECT_GE(toon.width_px, 8.0f);
  EXPECT_LE(toon.halo_px, toon.width_px);
  EXPECT_LT(toon.color_r + toon.color_g + toon.color_b, 0.3f);
}

TEST(StrokeStyle, UnknownPresetListsTheKnownOnes) {
  try {
    load_stroke_style("crayon");
    ADD_FAILURE() << "no refusal";
  } catch (const StrokeStyleError& e) {
    std::string what = e.what();
    EXPECT_EQ(what.rfind("stroke style 'crayon': no such preset in " + stroke_style_dir(), 0), 0u) << what;
    EXPECT_NE(what.find("(known: charcoal, ink, pencil, sketchy_pencil, toon_silhouette)"), std::string::npos) << what;
  }
  // A name too long for a file name (fuzz_svg): std::filesystem threw its own error past the reader.
  EXPECT_THROW(load_stroke_style(std::string(300, 'a')), StrokeStyleError);
}

TEST(StrokeStyle, FilesByPathAndTheStyleDirFromTheEnvironment) {
  testing::TempDir dir;
  std::string path = dir.write("mine.json", R"({"width_px": 9})");
  EXPECT_EQ(load_stroke_style(path).width_px, 9.0f);
  EXPECT_THROW(load_stroke_style(dir.path("absent.json")), StrokeStyleError);
  try {
    load_stroke_style(dir.path("absent.json"));
  } catch (const StrokeStyleError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.path("absent.json") + ": cannot read the stroke style file: there is no such file");
  }
  dir.write("broad.json", R"({"width_px": 12})");
  ScopedEnv env("PLUMBAGO_STYLE_DIR", dir.dir());
  EXPECT_EQ(stroke_style_dir(), dir.dir());
  EXPECT_EQ(stroke_style_names(), (std::vector<std::string>{"broad", "mine"}));
  EXPECT_EQ(load_stroke_style("broad").width_px, 12.0f);
  std::string bad = dir.write("bad.json", R"({"alpha": 2})");
  try {
    load_stroke_style("bad");
    ADD_FAILURE() << "no refusal";
  } catch (const StrokeStyleError& e) {
    EXPECT_EQ(std::string(e.what()), bad + ": /alpha: must be in [0, 1], got 2");
  }
}

}  // namespace
}  // namespace plumbago

// The SVG reader of `plumbago strokefile` (common/strokes/svg_strokes.hpp) and its number
// scanner (common/strokes/svg_numbers.hpp): SVG's number grammar, long and huge attributes in
// linear time, every refusal naming the file, the element and the attribute, and the
// drawings of scenes/drawn read as their committed stroke files say.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "common/strokes/svg_numbers.hpp"
#include "common/strokes/svg_strokes.hpp"
#include "common/util/input_file.hpp"

namespace plumbago {
namespace {

namespace fs = std::filesystem;

// The refusal of reading `svg` as d.svg in an 800 x 600 window ("" when none).
std::string refusal(const std::string& svg, const SvgStrokeDefaults& defaults = {}) {
  try {
    svg_strokes(svg, "d.svg", 800, 600, defaults);
  } catch (const SvgError& e) {
    return e.what();
  }
  return "";
}

std::string drawing(const std::string& elements) {
  return R"(<svg xmlns="http://www.w3.org/2000/svg" width="800" height="600">)" + elements + "</svg>";
}

using Command = std::pair<char, std::vector<double>>;

// The commands of path data `d`.
std::vector<Command> commands(std::string_view d) {
  std::vector<Command> out;
  svg_path_commands(d, [&](char c, const std::vector<double>& v) { out.push_back({c, v}); });
  return out;
}

// The SvgNumberError of reading `text` ("" when none).
template <class Read>
std::string number_refusal(Read read, const std::string& text) {
  try {
    read(text);
  } catch (const SvgNumberError& e) {
    return e.what();
  }
  return "";
}

TEST(SvgNumbers, ReadSvgsGrammar) {
  EXPECT_EQ(svg_numbers(" 1,2\t-3.5e1 +4 .5.5 1-2 7E-1 "), (std::vector<double>{1, 2, -35, 4, 0.5, 0.5, 1, -2, 0.7}));
  EXPECT_TRUE(svg_numbers("").empty());
  EXPECT_EQ(svg_numbers("1e-400"), std::vector<double>{0});  // an underflow is 0, not an error
  EXPECT_EQ(svg_length("12px"), 12);
  EXPECT_EQ(svg_length(" 3 "), 3);
  EXPECT_EQ(commands("M1,2L3-4zm.5.5h1e1"),
            (std::vector<Command>{{'M', {1, 2}}, {'L', {3, -4}}, {'z', {}}, {'m', {0.5, 0.5}}, {'h', {10}}}));
}

TEST(SvgNumbers, RefuseWhatIsNotAFiniteNumber) {
  for (const char* text : {"nan", "NaN", "inf", "-Infinity", "x1", "1e", "1x", ".", "-", "1,,e5", "0x10", "1#"})
    EXPECT_NE(number_refusal(svg_numbers, std::string("0 ") + text).find("is not a number"), std::string::npos) << text;
  EXPECT_EQ(number_refusal(svg_numbers, "1 x1,2"), "'x1' is not a number");
  EXPECT_EQ(number_refusal(svg_numbers, "1e999"), "'1e999' is beyond double range");
  EXPECT_EQ(number_refusal(svg_numbers, std::string(100, 'a')), "'" + std::string(24, 'a') + "...' is not a number");
  EXPECT_EQ(number_refusal(svg_length, "10cm"), "'10cm' is not a number");
  EXPECT_EQ(number_refusal(svg_length, "1 2"), "'1 2' is not one length (a number, in px or without a unit)");
  EXPECT_EQ(number_refusal(commands, "M 0 0 L nan 1"), "'nan' is not a number");
  EXPECT_EQ(number_refusal(commands, "M 0 0 L 1e 1"), "'1e' is not a number");
  EXPECT_EQ(number_refusal(commands, "3 M 0 0"), "path data must start with a command (M), not a number");
}

// std::regex recursed per character and overflowed the stack on a few thousand points.
TEST(SvgStrokes, LongPolylinesAndHugeAttributesReadInLinearTime) {
  std::string points, pressure, subpaths;
  for (int k = 0; k < 100000; ++k) {
    points += std::to_string(k % 800) + "," + std::to_string(k % 600) + " ";
    pressure += "0.5 ";
  }
  for (int k = 0; k < 50000; ++k) subpaths += "M 0 0 L 10 10 ";
  const std::string note(8 << 20, 'n');  // an 8 MB attribute the reader does not read
  // One data-pressure for 50,000 subpaths, padded to 1 MB: read once, not once a subpath.
  const std::string padded_pressure = std::string("1").append(1 << 20, ' ');
  auto start = std::chrono::steady_clock::now();
  std::vector<DrawnStroke> s =
      svg_strokes(drawing(R"(<polyline data-note=")" + note + R"(" data-pressure=")" + pressure + R"(" points=")" +
                          points + R"("/><path data-pressure=")" + padded_pressure + R"(" d=")" + subpaths + R"("/>)"),
                  "long.svg", 800, 600, {});
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(s.size(), 50001u);
  EXPECT_EQ(s[0].points.size(), 100000u);
  EXPECT_NEAR(s[0].points[1].window.x, 1, 1e-9);
  EXPECT_NEAR(s[0].points[1].window.y, 599, 1e-9);
  EXPECT_EQ(s[0].points[1].pressure, 0.5);
  EXPECT_LT(seconds, 10.0);
  std::printf("[svg] 100000 points, 50000 subpaths, an 11 MB drawing read in %.2f s\n", seconds);
}

// Each Z adds a point: one byte of the drawing, some 370 of `plumbago strokefile`'s memory.
// A drawing holds no more points than a stroke file may.
TEST(SvgStrokes, PointsBeyondTheBoundAreRefused) {
  auto closed = [](size_t points) {  // M and L, then Z to the start and back
    std::string path = R"(<path d="M 0 0 L 1 1 )";
    return path.append(points - 2, 'z').append(R"("/>)");
  };
  EXPECT_EQ(refusal(drawing(closed(kMaxDrawnPoints))), "");
  EXPECT_EQ(refusal(drawing(closed(kMaxDrawnPoints + 1))),
            "d.svg: <path> #1: d: the drawing has over 250000 points, the most a stroke file may hold");
  EXPECT_EQ(refusal(drawing(closed(kMaxDrawnPoints - 1) + R"(<polyline points="0,0 1,1"/>)")),
            "d.svg: <polyline> #2: points: the drawing has over 250000 points, the most a stroke file may hold");
}

TEST(SvgStrokes, RefusalsNameTheFileTheElementAndTheAttribute) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"(<polyline id="a" points="0,0 x1,2"/>)", R"(d.svg: <polyline id="a"> #1: points: 'x1' is not a number)"},
      {R"(<polyline points="0,0 nan,2"/>)", "d.svg: <polyline> #1: points: 'nan' is not a number"},
      {R"(<polyline points="0,0 1e999,2"/>)", "d.svg: <polyline> #1: points: '1e999' is beyond double range"},
      {R"(<polyline points="0,0 &bogus; 1,1"/>)", "d.svg: <polyline> #1: points: '&bogus;' is not a number"},
      {R"(<polyline points="0,0 1"/>)", "d.svg: <polyline> #1: points: an odd count of numbers (3)"},
      {R"(<polyline points="0,0"/>)", "d.svg: <polyline> #1: points: a stroke needs 2 points or more"},
      {R"(<polyline/>)", "d.svg: <polyline> #1: points: missing"},
      {R"(<g><path id="p" d="M 0 0 L inf 2"/></g>)", R"(d.svg: <path id="p"> #2: d: 'inf' is not a number)"},
      {R"(<path d="M 0 0 Q 1 1 2 2"/>)", "d.svg: <path> #1: d: path command 'Q' is not a straight segment"},
      {R"(<path d="M 0 0 L 1"/>)", "d.svg: <path> #1: d: path command 'L': wrong count of numbers (1)"},
      {R"(<path d=""/>)", ""},  // no subpath: no stroke
      {R"(<path/>)", "d.svg: <path> #1: d: missing"},
      {R"(<path d="L 1 1"/>)", "d.svg: <path> #1: d: a path must start with M"},
      {R"svg(<polyline transform="scale(2)" points="0,0 1,1"/>)svg", "d.svg: <polyline> #1: transform: is not read"},
      {R"svg(<g transform="scale(2)"/>)svg", "d.svg: <g> #1: transform: is not read"},
      {R"(<polyline data-pressure="0.5 nan" points="0,0 1,1"/>)", "d.svg: <polyline> #1: data-pressure: 'nan'"},
      {R"(<polyline data-pressure="2" points="0,0 1,1"/>)", "data-pressure: each must be in [0, 1], found 2"},
      {R"(<polyline data-pressure="1 1 1" points="0,0 1,1"/>)", "data-pressure: expected one number or one per point"},
      {R"(<polyline stroke-width="wide" points="0,0 1,1"/>)", "<polyline> #1: stroke-width: 'wide' is not a number"},
      {R"(<polyline style="fill:none;stroke-width:e" points="0,0 1,1"/>)",
       "<polyline> #1: style: stroke-width: 'e' is not a number"},
      {R"(<polyline data-role="ink" points="0,0 1,1"/>)", "<polyline> #1: data-role: expected one of"},
      {R"(<polyline data-role="hatching" data-group="1e300" points="0,0 1,1"/>)",
       "<polyline> #1: data-group: expected a whole number in 0..1000000"},
      {R"(<polyline data-role="hatching" data-group="0" data-free="yes" points="0,0 1,1"/>)",
       "<polyline> #1: data-free: expected true or false"},
      {R"(<polyline data-style="crayon" points="0,0 1,1"/>)", "<polyline> #1: data-style: stroke style 'crayon'"},
      {R"(<polyline id="z" data-role="crease" points="5,5 9,9 5,5"/>)",
       R"(<polyline id="z"> #1: points: a crease or silhouette stroke is an offsets example: its ends must be 1 px )"},
      {R"(<polyline data-role="silhouette" points="5,5 5,5"/>)", "points: a crease or silhouette stroke"},
      {R"(<polyline points="0,0 2e6,0"/>)",
       "d.svg: <polyline> #1: points: point 1 lies at 2e+06, 600 px in the window"},
  };
  for (const auto& [elements, needle] : cases) {
    std::string what = refusal(drawing(elements));
    EXPECT_EQ(needle.empty(), what.empty()) << elements << ": " << what;
    EXPECT_NE(what.find(needle), std::string::npos) << elements << ": " << what;
    for (const char* library : {"stod", "_M_range_check", "bad_alloc", "-nan", "regex"})
      EXPECT_EQ(what.find(library), std::string::npos) << what;
  }
  SvgStrokeDefaults hatching{StrokeRole::Hatching, "", -1, false};
  EXPECT_NE(refusal(drawing(R"(<polyline points="0,0 1,1"/>)"), hatching).find("<polyline> #1: --group: must be in"),
            std::string::npos);
  SvgStrokeDefaults crayon{StrokeRole::Decal, "crayon"};
  EXPECT_NE(refusal(drawing(R"(<polyline points="0,0 1,1"/>)"), crayon).find("<polyline> #1: --style: stroke style"),
            std::string::npos);
}

TEST(SvgStrokes, TheRootsUserSpaceIsCheckedToo) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"(<svg viewBox="0 0 nan 600">)", "d.svg: <svg> #0: viewBox: 'nan' is not a number"},
      {R"(<svg viewBox="0 0 800">)",
       "d.svg: <svg> #0: viewBox: expected 4 numbers (min-x, min-y, width, height), found 3"},
      {R"(<svg viewBox="0 0 0 600">)", "d.svg: <svg> #0: viewBox: the drawing's width and height must be positive"},
      {R"(<svg viewBox="0 0 1e-300 1e-300">)", "d.svg: <polyline> #1: points: point 0 lies at"},
      {R"(<svg width="800" height="">)", "d.svg: <svg> #0: height: '' is not one length"},
      {R"(<svg width="100%" height="600">)", "d.svg: <svg> #0: width: '100%' is not a number"},
      {R"(<svg width="-1" height="600">)", "d.svg: <svg> #0: width: the drawing's width and height must be positive"},
  };
  for (const auto& [root, needle] : cases) {
    std::string what = refusal(root + R"(<polyline points="1,1 2,2"/></svg>)");
    EXPECT_NE(what.find(needle), std::string::npos) << root << ": " << what;
  }
  std::vector<DrawnStroke> px =
      svg_strokes(R"(<svg width="400px" height="300px"><polyline points="100,75 0,0"/></svg>)", "d.svg", 800, 600, {});
  EXPECT_EQ(px[0].points[0].window, glm::dvec2(200, 450));
}

TEST(SvgStrokes, MalformedXmlIsRefusedWithItsLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"<svg>\n<polyline points=\"0,0 1,1\">\n</svg>", "line 3"},  // the polyline is not closed
      {"<svg>\n<polyline points=\"0,0 1,1\"/>", "line 2"},         // nor the svg
      {"<svg>\n<polyline points='0,0 1,1/></svg>", "line 2"},     {"\n<svg><<</svg>", "line 2"}, {"", "line 1"},
  };
  for (const auto& [svg, line] : cases) {
    std::string what = refusal(svg);
    EXPECT_EQ(what.rfind("d.svg: " + line + ", column ", 0), 0u) << svg << ": " << what;
    EXPECT_NE(what.find("not valid XML"), std::string::npos) << what;
  }
  EXPECT_EQ(refusal(drawing(R"(<polyline points="0,0 &amp; 1,1"/>)")),
            "d.svg: <polyline> #1: points: '&' is not a number");
  EXPECT_EQ(refusal(drawing(R"(<polyline points="0,0 &#49;,1"/>)")), "");  // a character reference: "1"
}

// Elements nested far deeper than a recursive walk could go, and elements the reader
// does not read (rect, circle, text, image) beside the strokes.
TEST(SvgStrokes, DeepNestingAndOtherElements) {
  std::string deep;
  for (int k = 0; k < 100000; ++k) deep += "<g>";
  deep += R"(<polyline points="0,0 1,1"/>)";
  for (int k = 0; k < 100000; ++k) deep += "</g>";
  EXPECT_EQ(svg_strokes(drawing(deep), "d.svg", 800, 600, {}).size(), 1u);
  std::vector<DrawnStroke> s = svg_strokes(
      drawing(
          R"(<rect width="10" height="x"/><circle r="nan"/><text>hi</text><image href="r.png"/><!-- <polyline points="x"/> -->)"
          R"(<![CDATA[<polyline points="x"/>]]><path d="M 0 0 l 5 0 M 1 1 v 3"/>)"),
      "d.svg", 800, 600, {});
  ASSERT_EQ(s.size(), 2u);  // the path's subpaths; nothing from the comment or the CDATA
  EXPECT_NEAR(s[1].points[1].window.x, 1, 1e-9);
  EXPECT_NEAR(s[1].points[1].window.y, 596, 1e-9);
}

// The drawings of scenes/drawn read into the strokes of their committed stroke files, byte
// for byte (made by `plumbago strokefile` with the file's style: experiments/figures/draw_stand_ins.py).
TEST(SvgStrokes, TheCommittedDrawingsGiveTheirStrokeFiles) {
  const fs::path drawn = fs::path(PLUMBAGO_SOURCE_DIR) / "scenes" / "drawn";
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(drawn)) {
    if (entry.path().extension() != ".svg") continue;
    const std::string svg = entry.path().string();
    const std::string strokes = (drawn / entry.path().stem()).string() + ".strokes.json";
    SCOPED_TRACE(svg);
    StrokeFile file = load_stroke_file(strokes, glm::dvec3(0.0));
    SvgStrokeDefaults defaults{StrokeRole::Decal, file.style, 0, false, false, drawn.string()};
    file.strokes = svg_strokes(read_input_file(svg, "SVG drawing"), svg, file.width, file.height, defaults);
    const std::string made = stroke_file_json(file, glm::dvec3(0.0)),
                      committed = read_input_file(strokes, "stroke file");
    EXPECT_EQ(made.substr(made.find("\"strokes\"")), committed.substr(committed.find("\"strokes\"")));
    ++files;
  }
  EXPECT_GE(files, 7u);
}

}  // namespace
}  // namespace plumbago

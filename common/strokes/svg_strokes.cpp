// Strokes drawn in SVG (Kalnins et al. 2002, §3, §4.5): see common/strokes/svg_strokes.hpp.
#include "common/strokes/svg_strokes.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <stdexcept>

#include "common/scene/json_position.hpp"
#include "common/strokes/svg_numbers.hpp"

namespace plumbago {

namespace {

// An element the reader looks at (svg, g, polyline, path) and its index among them, for messages.
struct Element {
  pugi::xml_node node;
  size_t index = 0;

  std::string name() const { return node.name(); }
  bool has(const char* attribute) const { return bool(node.attribute(attribute)); }
  const char* value(const char* attribute) const { return node.attribute(attribute).value(); }
  bool drawn() const { return name() == "polyline" || name() == "path"; }
};

// The node after `n` in document order; none after the last. A loop, not a recursion: a
// drawing may nest deeper than the stack would allow.
pugi::xml_node next_in_document(pugi::xml_node n) {
  if (n.first_child()) return n.first_child();
  while (n && !n.next_sibling()) n = n.parent();
  return n ? n.next_sibling() : n;
}

std::vector<Element> elements(const pugi::xml_document& doc) {
  std::vector<Element> out;
  for (pugi::xml_node n = doc.first_child(); n; n = next_in_document(n)) {
    const std::string name = n.name();
    if (n.type() == pugi::node_element && (name == "svg" || name == "g" || name == "polyline" || name == "path"))
      out.push_back({n, out.size()});
  }
  return out;
}

// An id, as a message shows it: at most 40 characters.
std::string shown_id(const std::string& id) { return id.size() > 40 ? id.substr(0, 40) + "..." : id; }

class SvgReader {
 public:
  SvgReader(std::string source, int width, int height, const SvgStrokeDefaults& defaults)
      : source_(std::move(source)), width_(width), height_(height), defaults_(defaults), size_(width, height) {}

  // "drawing.svg: <polyline id="a"> #3: points: WHAT" (the attribute left out when empty).
  [[noreturn]] void fail(const Element& e, const std::string& attribute, const std::string& what) const {
    std::string id = e.has("id") ? " id=\"" + shown_id(e.value("id")) + "\"" : "";
    throw SvgError(source_ + ": <" + e.name() + id + "> #" + std::to_string(e.index) + ": " +
                   (attribute.empty() ? "" : attribute + ": ") + what);
  }

  // `read` applied to `text`, its SvgNumberError a refusal naming the attribute.
  template <class Read>
  auto parsed_text(const Element& e, const std::string& attribute, std::string_view text, Read read) const {
    try {
      return read(text);
    } catch (const SvgNumberError& x) {
      fail(e, attribute, x.what());
    }
  }
  template <class Read>
  auto parsed(const Element& e, const char* attribute, Read read) const {
    return parsed_text(e, attribute, e.value(attribute), read);
  }

  // The root's user space onto the window: viewBox, else width and height, else the window.
  void root(const Element& svg) {
    if (svg.has("viewBox")) {
      std::vector<double> box = parsed(svg, "viewBox", svg_numbers);
      if (box.size() != 4)
        fail(svg, "viewBox", "expected 4 numbers (min-x, min-y, width, height), found " + std::to_string(box.size()));
      origin_ = {box[0], box[1]}, size_ = {box[2], box[3]};
    } else if (svg.has("width") && svg.has("height")) {
      size_ = {parsed(svg, "width", svg_length), parsed(svg, "height", svg_length)};
    }
    if (!(size_.x > 0 && size_.y > 0))
      fail(svg, svg.has("viewBox") ? "viewBox" : "width", "the drawing's width and height must be positive");
  }

  void no_transform(const Element& e) const {
    if (e.has("transform")) fail(e, "transform", "is not read: flatten it first");
  }

  // The stroke width of a drawn element: its style's stroke-width, else its attribute, else 0.
  double stroke_width(const Element& e) const {
    std::string style = e.value("style");
    for (size_t start = 0; start < style.size();) {
      size_t end = std::min(style.find(';', start), style.size()), colon = style.find(':', start);
      if (colon < end && trimmed(style.substr(start, colon - start)) == "stroke-width")
        return parsed_text(e, "style: stroke-width", trimmed(style.substr(colon + 1, end - colon - 1)), svg_length);
      start = end + 1;
    }
    return e.has("stroke-width") ? parsed(e, "stroke-width", svg_length) : 0;
  }

  // The strokes of one drawn element (a path's subpaths each); `widest` the drawing's widest stroke width.
  std::vector<DrawnStroke> strokes(const Element& e, double widest) {
    no_transform(e);
    const char* attribute = e.name() == "polyline" ? "points" : "d";
    if (!e.has(attribute)) fail(e, attribute, "missing");
    std::vector<DrawnStroke> out;
    const DrawnStroke blank = attributes(e);
    const std::vector<double> given = pressures(e, widest);
    for (const std::vector<glm::dvec2>& line : e.name() == "polyline" ? polyline(e) : path(e)) {
      if (line.size() < 2) fail(e, attribute, "a stroke needs 2 points or more");
      if (given.size() != 1 && given.size() != line.size())
        fail(e, "data-pressure",
             "expected one number or one per point (" + std::to_string(line.size()) + "), found " +
                 std::to_string(given.size()));
      DrawnStroke s = blank;
      for (size_t k = 0; k < line.size(); ++k)
        s.points.push_back({window(e, attribute, line[k], k), given[given.size() == 1 ? 0 : k]});
      if (s.role == StrokeRole::Crease || s.role == StrokeRole::Silhouette)
        if (std::string fault = offsets_example_fault(s); !fault.empty()) fail(e, attribute, fault);
      out.push_back(std::move(s));
    }
    return out;
  }

 private:
  static std::string trimmed(const std::string& s) {
    size_t a = s.find_first_not_of(" \t\n\r"), b = s.find_last_not_of(" \t\n\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
  }

  // Point k (user units) in the window, within the bound of a stroke file's points.
  glm::dvec2 window(const Element& e, const char* attribute, glm::dvec2 user, size_t k) const {
    glm::dvec2 unit = (user - origin_) / size_;
    glm::dvec2 w(unit.x * width_, (1.0 - unit.y) * height_);
    if (!(std::abs(w.x) <= kMaxDrawnPixel && std::abs(w.y) <= kMaxDrawnPixel))
      fail(e, attribute,
           "point " + std::to_string(k) + " lies at " + format_number(w.x) + ", " + format_number(w.y) +
               " px in the window, beyond ±" + format_number(kMaxDrawnPixel));
    return w;
  }

  // Counts `more` points of the drawing against the most a stroke file may hold.
  void count_points(const Element& e, const char* attribute, size_t more) {
    if ((points_ += more) > kMaxDrawnPoints)
      fail(e, attribute,
           "the drawing has over " + std::to_string(kMaxDrawnPoints) + " points, the most a stroke file may hold");
  }

  std::vector<std::vector<glm::dvec2>> polyline(const Element& e) {
    std::vector<double> v = parsed(e, "points", svg_numbers);
    if (v.size() % 2) fail(e, "points", "an odd count of numbers (" + std::to_string(v.size()) + "): x y pairs");
    count_points(e, "points", v.size() / 2);
    std::vector<glm::dvec2> line;
    for (size_t k = 0; k + 1 < v.size(); k += 2) line.push_back({v[k], v[k + 1]});
    return {line};
  }

  // A path's subpaths as its commands are read, and where the pen is.
  struct Subpaths {
    std::vector<std::vector<glm::dvec2>> lines;
    glm::dvec2 at{0.0}, start{0.0};
  };

  // Each subpath's points: M, L, H, V, Z, absolute or relative (SVG 1.1, §8.3).
  std::vector<std::vector<glm::dvec2>> path(const Element& e) {
    Subpaths s;
    parsed(e, "d", [&](std::string_view d) {
      svg_path_commands(d, [&](char c, const std::vector<double>& v) { add_command(e, c, v, s); });
      return true;
    });
    return s.lines;
  }

  void add_command(const Element& e, char c, const std::vector<double>& v, Subpaths& s) {
    const char kind = char(std::toupper(c));
    const bool relative = std::islower(c);
    const size_t arity = kind == 'M' || kind == 'L' ? 2 : kind == 'Z' ? 0 : 1;
    if (kind != 'M' && kind != 'L' && kind != 'H' && kind != 'V' && kind != 'Z')
      fail(e, "d", std::string("path command '") + c + "' is not a straight segment: flatten curves first");
    if (arity ? v.empty() || v.size() % arity : !v.empty())
      fail(e, "d", std::string("path command '") + c + "': wrong count of numbers (" + std::to_string(v.size()) + ")");
    if (kind == 'Z') {
      if (!s.lines.empty()) s.lines.back().push_back(s.start), count_points(e, "d", 1);
      s.at = s.start;
    }
    for (size_t k = 0; k < v.size(); k += arity) {
      glm::dvec2 to = kind == 'H'   ? glm::dvec2(v[k] + (relative ? s.at.x : 0), s.at.y)
                      : kind == 'V' ? glm::dvec2(s.at.x, v[k] + (relative ? s.at.y : 0))
                                    : glm::dvec2(v[k], v[k + 1]) + (relative ? s.at : glm::dvec2(0));
      if (kind == 'M' && k == 0) s.lines.push_back({}), s.start = to;
      if (s.lines.empty()) fail(e, "d", "a path must start with M");
      s.lines.back().push_back(to), count_points(e, "d", 1);
      s.at = to;
    }
  }

  // A stroke of element e without its points: role, style, group, free, mobile.
  DrawnStroke attributes(const Element& e) {
    DrawnStroke s;
    s.role = e.has("data-role") ? role(e) : defaults_.role;
    if (s.role == StrokeRole::Decal || s.role == StrokeRole::Hatching) {
      s.style_name = e.has("data-style") ? e.value("data-style") : defaults_.style;
      s.style = style(e, s.style_name.empty() ? kDefaultDecalStyle : s.style_name);
    }
    if (s.role == StrokeRole::Hatching) {
      s.group = e.has("data-group") ? group(e) : defaults_.group;
      if (!e.has("data-group") && (s.group < 0 || s.group > kMaxHatchingGroup))
        fail(e, "--group", "must be in 0.." + std::to_string(kMaxHatchingGroup));
      s.free = e.has("data-free") ? flag(e, "data-free") : defaults_.free;
      s.mobile = e.has("data-mobile") ? flag(e, "data-mobile") : defaults_.mobile;
    }
    return s;
  }

  StrokeRole role(const Element& e) const {
    const std::vector<std::string>& names = stroke_role_names();
    auto it = std::find(names.begin(), names.end(), e.value("data-role"));
    if (it == names.end()) fail(e, "data-role", "expected one of decal, crease, silhouette, hatching");
    return StrokeRole(it - names.begin());
  }

  int group(const Element& e) const {
    std::vector<double> g = parsed(e, "data-group", svg_numbers);
    if (g.size() != 1 || g[0] != std::floor(g[0]) || g[0] < 0 || g[0] > kMaxHatchingGroup)
      fail(e, "data-group", "expected a whole number in 0.." + std::to_string(kMaxHatchingGroup));
    return int(g[0]);
  }

  bool flag(const Element& e, const char* attribute) const {
    const std::string v = e.value(attribute);
    if (v != "true" && v != "false") fail(e, attribute, "expected true or false");
    return v == "true";
  }

  // The style named by the element (data-style) or the command (--style), loaded once.
  const StrokeStyle& style(const Element& e, const std::string& name) {
    auto it = styles_.find(name);
    if (it != styles_.end()) return it->second;
    try {
      return styles_.emplace(name, load_stroke_style_from(name, defaults_.style_dir)).first->second;
    } catch (const StrokeStyleError& x) {
      fail(e, e.has("data-style") ? "data-style" : "--style", x.what());
    }
  }

  // The pressures of element e: one for every point, or one a point (data-pressure).
  std::vector<double> pressures(const Element& e, double widest) const {
    if (e.has("data-pressure")) {
      std::vector<double> v = parsed(e, "data-pressure", svg_numbers);
      for (double p : v)
        if (!(p >= 0 && p <= 1)) fail(e, "data-pressure", "each must be in [0, 1], found " + format_number(p));
      return v;
    }
    double w = stroke_width(e);
    return {w > 0 && widest > 0 ? std::min(1.0, w / widest) : 1.0};
  }

  std::string source_;
  int width_, height_;
  SvgStrokeDefaults defaults_;
  glm::dvec2 origin_{0.0}, size_;
  std::map<std::string, StrokeStyle> styles_;
  size_t points_ = 0;  // read so far
};

}  // namespace

std::vector<DrawnStroke> svg_strokes(const std::string& svg, const std::string& source, int width, int height,
                                     const SvgStrokeDefaults& defaults) {
  pugi::xml_document doc;
  pugi::xml_parse_result parsed = doc.load_buffer(svg.data(), svg.size());
  if (!parsed)
    throw SvgError(source + ": " + line_and_column(svg, size_t(parsed.offset) + 1) + ": not valid XML (" +
                   parsed.description() + ")");
  SvgReader reader(source, width, height, defaults);
  std::vector<Element> all = elements(doc);
  double widest = 0;
  for (const Element& e : all) {
    if (e.name() == "svg") reader.root(e);
    if (e.name() == "g") reader.no_transform(e);
    if (e.drawn()) widest = std::max(widest, reader.stroke_width(e));
  }
  std::vector<DrawnStroke> out;
  for (const Element& e : all)
    if (e.drawn())
      for (DrawnStroke& s : reader.strokes(e, widest)) out.push_back(std::move(s));
  return out;
}

}  // namespace plumbago
